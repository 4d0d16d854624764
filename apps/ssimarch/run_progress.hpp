// Progress of a run on stderr (core/progress.hpp): the flag --progress MODE every long-running
// subcommand has, and the meter a run reports to while it lives.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>

#include "ssimarch/core/progress.hpp"
#include "ssimarch/core/progress_writers.hpp"

namespace ssimarch::cli {

/// Adds --progress auto|bar|json|none (default auto: a bar when stderr is a terminal).
void add_progress_option(CLI::App* cmd);

/// The progress display of one run: the sink --progress chose (none when `quiet`), its meter, and
/// the meter as the thread's ProgressScope so that library loops reach it. Ends the bar's line
/// when it goes.
class RunProgress {
 public:
  explicit RunProgress(bool quiet);
  ~RunProgress();
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;
  ProgressMeter& meter() { return meter_; }

 private:
  std::unique_ptr<ProgressSink> sink_;
  ProgressMeter meter_;
  ProgressScope scope_;
};

}  // namespace ssimarch::cli
