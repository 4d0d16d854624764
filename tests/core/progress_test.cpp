// The progress meter (core/progress.hpp): rate limit, rate and time left, stage changes, thread
// safety; the writers (core/progress_writers.hpp); the interrupt flag (core/interrupt.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/core/progress.hpp"
#include "ssimarch/core/progress_writers.hpp"

namespace ssimarch {
namespace {

struct RecordingSink : ProgressSink {
  std::vector<ProgressState> shown;
  int closed = 0;
  void show(const ProgressState& s) override { shown.push_back(s); }
  void close() override { ++closed; }
};

// A clock the test moves by hand (seconds).
struct FakeClock {
  double now = 100.0;
  std::function<double()> fn() {
    return [this] { return now; };
  }
};

TEST(ProgressMeter, DropsUpdatesWithinTheIntervalButNeverTheFirstOrTheLast) {
  RecordingSink sink;
  FakeClock clock;
  ProgressMeter meter(&sink, 0.1, clock.fn());
  for (int i = 0; i <= 1000; ++i) {  // 1000 units at 1 ms each: 1 s
    meter.report("radial", i, 1000);
    clock.now += 0.001;
  }
  // The first, one per full 0.1 s after it (10), and the finished one: at most 12 of 1001.
  ASSERT_GE(sink.shown.size(), 10u);
  ASSERT_LE(sink.shown.size(), 12u);
  EXPECT_EQ(sink.shown.front().done, 0);
  EXPECT_EQ(sink.shown.back().done, 1000);
  EXPECT_TRUE(sink.shown.back().finished());
  for (std::size_t k = 1; k + 1 < sink.shown.size(); ++k)
    EXPECT_GE(sink.shown[k].elapsed_s - sink.shown[k - 1].elapsed_s, 0.1 - 1e-9);
  // A finished stage is shown once.
  meter.report("radial", 1000, 1000);
  EXPECT_EQ(static_cast<long>(sink.shown.size()), meter.shown());
}

TEST(ProgressMeter, RateAndTimeLeftAreTheStagesMeanPace) {
  RecordingSink sink;
  FakeClock clock;
  ProgressMeter meter(&sink, 0.1, clock.fn());
  meter.report("map", 0, 400);
  EXPECT_TRUE(std::isnan(sink.shown.back().rate));  // nothing measured yet
  EXPECT_TRUE(std::isnan(sink.shown.back().eta_s));
  clock.now += 2.0;
  meter.report("map", 100, 400);  // 100 units in 2 s: 50/s, 300 left: 6 s
  EXPECT_DOUBLE_EQ(sink.shown.back().rate, 50.0);
  EXPECT_DOUBLE_EQ(sink.shown.back().eta_s, 6.0);
  EXPECT_DOUBLE_EQ(sink.shown.back().elapsed_s, 2.0);
  EXPECT_DOUBLE_EQ(sink.shown.back().fraction(), 0.25);
}

TEST(ProgressMeter, ANewStageIsShownAtOnceAndRestartsTheClock) {
  RecordingSink sink;
  FakeClock clock;
  ProgressMeter meter(&sink, 0.1, clock.fn());
  meter.report("bulk", 0.5, 1);
  clock.now += 0.01;
  meter.report("radial", 0, 1);  // within the interval, but a new stage
  ASSERT_EQ(sink.shown.size(), 2u);
  EXPECT_EQ(sink.shown[1].stage, "radial");
  EXPECT_DOUBLE_EQ(sink.shown[1].elapsed_s, 0.0);
  meter.close();
  meter.close();
  EXPECT_EQ(sink.closed, 1);
  meter.report("axial", 0, 1);  // after close: dropped
  EXPECT_EQ(sink.shown.size(), 2u);
}

TEST(ProgressMeter, ManyThreadsReportingAreSerialisedAndRateLimited) {
  RecordingSink sink;
  ProgressMeter meter(&sink, 3600.0);  // an interval no run of this test reaches: only the first and the last
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&meter] {
      for (int i = 0; i < 10000; ++i) meter.report("porosity", i, 10000);
    });
  for (auto& th : threads) th.join();
  meter.report("porosity", 10000, 10000);
  ASSERT_EQ(sink.shown.size(), 2u);
  EXPECT_TRUE(sink.shown.back().finished());
}

TEST(ProgressMeter, ReportProgressReachesTheMeterOfTheThreadsScopeOnly) {
  RecordingSink sink;
  ProgressMeter meter(&sink);
  report_progress("packing", 1, 2);  // no scope: nowhere
  {
    ProgressScope scope(&meter);
    report_progress("packing", 1, 2);
    std::thread([] { report_progress("other thread", 1, 2); }).join();  // another thread has no scope
  }
  report_progress("packing", 2, 2);
  ASSERT_EQ(sink.shown.size(), 1u);
  EXPECT_EQ(sink.shown[0].stage, "packing");
}

std::string written_by(const std::function<void(std::FILE*)>& write) {
  std::FILE* f = std::tmpfile();
  write(f);
  std::rewind(f);
  std::string s;
  for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
  std::fclose(f);
  return s;
}

TEST(ProgressWriters, JsonLinesHoldEveryFieldWithNullForUnknowns) {
  const std::string s = written_by([](std::FILE* f) {
    JsonProgressLines sink(f);
    ProgressState st;
    st.stage = "map \"x\"";
    st.done = 25;
    st.total = 100;
    st.elapsed_s = 5;
    sink.show(st);
    st.rate = 5;
    st.eta_s = 15;
    sink.show(st);
  });
  EXPECT_EQ(s,
            "{\"progress\": {\"stage\": \"map \\\"x\\\"\", \"done\": 25, \"total\": 100, \"fraction\": 0.25, "
            "\"elapsed_s\": 5, \"rate\": null, \"eta_s\": null}}\n"
            "{\"progress\": {\"stage\": \"map \\\"x\\\"\", \"done\": 25, \"total\": 100, \"fraction\": 0.25, "
            "\"elapsed_s\": 5, \"rate\": 5, \"eta_s\": 15}}\n");
}

TEST(ProgressWriters, TheBarShowsPercentCountsRateAndTimeLeft) {
  const std::string s = written_by([](std::FILE* f) {
    TerminalProgressBar bar(f, 10);
    ProgressState st;
    st.stage = "packing";
    st.done = 500;
    st.total = 1000;
    st.elapsed_s = 10;
    st.rate = 50;
    st.eta_s = 10;
    bar.show(st);
    bar.close();
  });
  EXPECT_EQ(s, "\rpacking    [#####     ]  50%  500/1000  50/s  0:10 left\033[K\n");
  EXPECT_EQ(TerminalProgressBar::clock(3725), "1:02:05");
  EXPECT_EQ(TerminalProgressBar::clock(65.4), "1:05");
}

TEST(ProgressWriters, AutoModeShowsNothingOffATerminal) {
  std::FILE* f = std::tmpfile();  // a regular file: not a terminal
  EXPECT_EQ(make_progress_sink(ProgressMode::kAuto, f), nullptr);
  EXPECT_EQ(make_progress_sink(ProgressMode::kNone, f), nullptr);
  EXPECT_NE(make_progress_sink(ProgressMode::kJson, f), nullptr);
  std::fclose(f);
}

TEST(Interrupt, TheFlagMakesCheckingLoopsThrowUntilCleared) {
  clear_interrupt();
  EXPECT_NO_THROW(throw_if_interrupted());
  request_interrupt();
  EXPECT_TRUE(interrupt_requested());
  EXPECT_THROW(throw_if_interrupted(), Interrupted);
  clear_interrupt();
  EXPECT_NO_THROW(throw_if_interrupted());
}

TEST(Interrupt, SigintSetsTheFlagInsteadOfEndingTheProcess) {
  clear_interrupt();
  ASSERT_TRUE(install_interrupt_handler());
  std::raise(SIGINT);
  EXPECT_TRUE(interrupt_requested());
  clear_interrupt();
  std::signal(SIGINT, SIG_DFL);
}

}  // namespace
}  // namespace ssimarch
