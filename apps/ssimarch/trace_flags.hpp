// The flags `trace`, `section` and `intersect` share: one per row of the trace option table
// (--step-length, --tolerance, ...), the options an output format turns on, and the tracing and
// writing of a generated scene of STEP faces.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/step/units.hpp"
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

/// Adds `--unit NAME` (faces, trace, section, intersect): read STEP models converted to a length
/// unit (docs/cad.md, "Length unit").
void add_unit_option(CLI::App* cmd, std::string* unit);

/// The unit `--unit` named; empty when it was not given. Throws InputError naming --unit.
std::optional<StepLengthUnit> unit_flag(const std::string& text);

/// What `section` and `intersect` share besides their inputs: the output, its format, the trace
/// options, threads and quiet.
struct GeneratedSceneFlags {
  std::string output = "-";
  std::string format;
  bool quiet = false;
  unsigned threads = 0;
  TraceOptionFlags options;
};

/// Adds -o, --format, the option table's flags, --threads (its help says what runs on them:
/// `parallel`), -q, --progress and the budget options.
void add_generated_scene_flags(CLI::App* cmd, GeneratedSceneFlags* flags, const std::string& parallel);

/// Traces the generated scene (pairs of STEP faces, or faces and planes; `source` names it in
/// messages) with the flags' options and writes its runs to the output in its format (empty: from
/// the file's extension, json on standard output), an empty list when it has no intersection;
/// progress on stderr unless quiet. Refuses an output that names an input first.
TraceJobResult trace_generated_scene(const nlohmann::json& scene, const std::string& source,
                                     const GeneratedSceneFlags& flags);

}  // namespace ssimarch::cli
