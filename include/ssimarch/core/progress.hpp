// Progress of long runs: loops report (stage, done, total) to a ProgressMeter, which measures the
// stage's rate and time left, drops updates that come faster than its interval (0.1 s: at most 10
// a second reach the screen, however many threads or iterations report) and hands the rest to a
// ProgressSink (a terminal bar or JSON lines: core/progress_writers.hpp). Thread-safe.
//
// Deep loops that have no options of their own to carry a callback (the packing generators, the
// certified start-point search, the loop over a scene's intersections) report to the meter of
// the current thread's ProgressScope through report_progress(); without a scope it costs one
// thread-local load.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <string_view>

namespace ssimarch {

/// What a sink shows: the stage, the work done of its total, and the measured pace.
struct ProgressState {
  std::string stage;
  double done = 0, total = 1;  ///< units of work of the stage (total > 0)
  double elapsed_s = 0;        ///< since the stage's first report
  /// Units per second, mean over the stage; NaN until time has passed and work was done.
  double rate = std::numeric_limits<double>::quiet_NaN();
  /// Seconds left at that rate; NaN while the rate is unknown.
  double eta_s = std::numeric_limits<double>::quiet_NaN();
  bool finished() const { return done >= total; }
  double fraction() const { return total > 0 ? std::clamp(done / total, 0.0, 1.0) : 0.0; }
};

/// Where progress is shown. show() is called with the meter's lock held: never concurrently.
class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  virtual void show(const ProgressState& state) = 0;
  /// The run is over (or was interrupted): leave the output tidy (e.g. end the bar's line).
  virtual void close() {}
};

/// Seconds on the steady clock (the meter's default clock).
inline double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class ProgressMeter {
 public:
  /// `sink` may be null (a meter that shows nothing); `clock` returns seconds (tests inject one).
  explicit ProgressMeter(ProgressSink* sink, double min_interval_s = 0.1, std::function<double()> clock = steady_seconds)
      : sink_(sink), min_interval_s_(min_interval_s), clock_(std::move(clock)) {}

  /// `done` of `total` units of `stage` are done. Shown when the stage is new, finished, or the
  /// last update shown is at least the interval old; dropped otherwise.
  void report(std::string_view stage, double done, double total) {
    if (!sink_ || !(total > 0)) return;
    std::lock_guard lock(mutex_);
    if (closed_) return;
    const double now = clock_();
    const bool new_stage = !started_ || stage != state_.stage;
    if (new_stage) {
      state_.stage.assign(stage);
      stage_start_ = now;
      started_ = true;
      finished_shown_ = false;
    } else if (finished_shown_ || (done < total && now - last_shown_ < min_interval_s_)) {
      return;
    }
    state_.done = done;
    state_.total = total;
    state_.elapsed_s = now - stage_start_;
    const bool measurable = state_.elapsed_s > 0 && done > 0;
    state_.rate = measurable ? done / state_.elapsed_s : std::numeric_limits<double>::quiet_NaN();
    state_.eta_s = measurable ? std::max(0.0, total - done) / state_.rate : std::numeric_limits<double>::quiet_NaN();
    finished_shown_ = done >= total;
    last_shown_ = now;
    ++shown_;
    sink_->show(state_);
  }

  /// Ends the display (idempotent); later reports are dropped.
  void close() {
    std::lock_guard lock(mutex_);
    if (sink_ && started_ && !closed_) sink_->close();
    closed_ = true;
  }

  /// Updates handed to the sink so far.
  long shown() const {
    std::lock_guard lock(mutex_);
    return shown_;
  }

  /// A callback for options that take one per stage fraction (PorosityJob::progress).
  std::function<void(std::string_view, double)> fraction_callback() {
    return [this](std::string_view stage, double f) { report(stage, f, 1.0); };
  }

 private:
  ProgressSink* sink_;
  double min_interval_s_;
  std::function<double()> clock_;
  mutable std::mutex mutex_;
  ProgressState state_;
  double stage_start_ = 0, last_shown_ = 0;
  bool started_ = false, finished_shown_ = false, closed_ = false;
  long shown_ = 0;
};

namespace internal {
inline thread_local ProgressMeter* t_progress_meter = nullptr;
}

/// Routes report_progress() on this thread to `meter` while it lives (scopes nest).
class ProgressScope {
 public:
  explicit ProgressScope(ProgressMeter* meter) : previous_(internal::t_progress_meter) {
    internal::t_progress_meter = meter;
  }
  ~ProgressScope() { internal::t_progress_meter = previous_; }
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

 private:
  ProgressMeter* previous_;
};

/// Reports to the current thread's scope's meter; nothing without one.
inline void report_progress(std::string_view stage, double done, double total) {
  if (ProgressMeter* m = internal::t_progress_meter) m->report(stage, done, total);
}

}  // namespace ssimarch
