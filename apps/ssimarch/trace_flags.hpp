// The flags `trace` and `section` share: one per row of the trace option table
// (--step-length, --tolerance, ...), and the options an output format turns on.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "ssimarch/pipeline/trace_job.hpp"
#include "trace_output.hpp"

namespace ssimarch::cli {

/// The option table's flags on one subcommand; values stay text until the scene's constants are known.
struct TraceOptionFlags {
  std::vector<std::pair<const TraceOptionSpec*, CLI::Option*>> flags;
  std::vector<std::string> values;
};

/// Adds --key-with-dashes for every row of the option table, with the table's help.
void add_trace_option_flags(CLI::App* cmd, TraceOptionFlags* flags);

/// The overrides of the flags the user gave.
std::vector<OptionOverride> trace_overrides(const TraceOptionFlags& flags);

/// What the output format needs unless a flag sets it: STEP holds the certified B-splines
/// (bspline on), VTP carries kappa and tau (geometry mixed).
void add_format_overrides(OutputFormat format, TraceRequest* request);

}  // namespace ssimarch::cli
