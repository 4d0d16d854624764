// The two ways progress is shown (core/progress.hpp): a bar with rate and time left, redrawn in
// place on a terminal, and JSON lines for programs that watch a run. Both write to a C stream
// (stderr in the CLI: standard output carries results).
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "ssimarch/core/progress.hpp"

namespace ssimarch {

/// "radial   [##########          ]  50%  1.2e+03/s  0:04 left", redrawn with '\r'; a stage that
/// finishes leaves its line (with the stage's time) and the next stage starts a new one.
class TerminalProgressBar : public ProgressSink {
 public:
  explicit TerminalProgressBar(std::FILE* out, int width = 30) : out_(out), width_(width) {}

  void show(const ProgressState& s) override {
    if (open_line_ && s.stage != line_stage_) std::fputc('\n', out_);
    const int filled = static_cast<int>(s.fraction() * width_ + 0.5);
    std::string line = "\r" + pad(s.stage, 10) + " [" + std::string(filled, '#') + std::string(width_ - filled, ' ') + "] ";
    char buf[96];
    std::snprintf(buf, sizeof buf, "%3d%%", static_cast<int>(s.fraction() * 100 + 1e-9));
    line += buf;
    if (s.total > 1) line += "  " + count(s.done) + "/" + count(s.total);
    if (s.finished()) {
      line += "  " + clock(s.elapsed_s);
    } else if (std::isfinite(s.rate)) {
      if (s.total > 1) line += "  " + count(s.rate) + "/s";
      line += "  " + clock(s.eta_s) + " left";
    }
    line += "\033[K";  // erase what a longer earlier line left
    std::fputs(line.c_str(), out_);
    std::fflush(out_);
    open_line_ = true;
    line_stage_ = s.stage;
  }

  void close() override {
    if (open_line_) std::fputc('\n', out_);
    std::fflush(out_);
    open_line_ = false;
  }

  /// Seconds as m:ss, or h:mm:ss from an hour on.
  static std::string clock(double seconds) {
    if (!std::isfinite(seconds)) return "?";
    const long t = std::lround(std::max(0.0, seconds));
    char buf[48];
    if (t >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
    else std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
    return buf;
  }

 private:
  static std::string pad(std::string_view s, std::size_t n) {
    std::string r(s);
    if (r.size() < n) r.append(n - r.size(), ' ');
    return r;
  }
  static std::string count(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, v < 1e5 ? "%.0f" : "%.3g", v);
    return buf;
  }

  std::FILE* out_;
  int width_;
  bool open_line_ = false;
  std::string line_stage_;
};

/// One JSON object a line: {"progress": {"stage", "done", "total", "fraction", "elapsed_s",
/// "rate", "eta_s"}} (rate and eta_s null while unknown). docs/output-format.md "Progress".
class JsonProgressLines : public ProgressSink {
 public:
  explicit JsonProgressLines(std::FILE* out) : out_(out) {}

  void show(const ProgressState& s) override {
    std::string line = "{\"progress\": {\"stage\": \"" + escaped(s.stage) + "\", \"done\": " + number(s.done) +
                       ", \"total\": " + number(s.total) + ", \"fraction\": " + number(s.fraction()) +
                       ", \"elapsed_s\": " + number(s.elapsed_s) + ", \"rate\": " + number(s.rate) +
                       ", \"eta_s\": " + number(s.eta_s) + "}}\n";
    std::fputs(line.c_str(), out_);
    std::fflush(out_);
  }

 private:
  static std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
  }
  static std::string escaped(std::string_view s) {
    std::string r;
    for (char c : s) {
      if (c == '"' || c == '\\') r += '\\';
      if (static_cast<unsigned char>(c) >= 0x20) r += c;
    }
    return r;
  }

  std::FILE* out_;
};

enum class ProgressMode {
  kAuto,  ///< the bar when the stream is a terminal, nothing otherwise
  kBar,
  kJson,
  kNone,
};

/// The sink of a mode on `out`; null for kNone, and for kAuto when `out` is not a terminal.
inline std::unique_ptr<ProgressSink> make_progress_sink(ProgressMode mode, std::FILE* out) {
  if (mode == ProgressMode::kAuto) mode = ::isatty(::fileno(out)) ? ProgressMode::kBar : ProgressMode::kNone;
  if (mode == ProgressMode::kBar) return std::make_unique<TerminalProgressBar>(out);
  if (mode == ProgressMode::kJson) return std::make_unique<JsonProgressLines>(out);
  return nullptr;
}

}  // namespace ssimarch
