#include "trace_flags.hpp"

#include <algorithm>

#include "commands.hpp"
#include "run_budget.hpp"
#include "run_progress.hpp"
#include "ssimarch/core/thread_pool.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/scene.hpp"

namespace ssimarch::cli {

void add_trace_option_flags(CLI::App* cmd, TraceOptionFlags* flags) {
  const auto& table = trace_option_table();
  flags->values.resize(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const TraceOptionSpec& o = table[i];
    std::string help =
        std::string(o.help) + " (overrides the scene; " + o.rule + "; default " + std::string(o.default_text) + ")";
    CLI::Option* flag = cmd->add_option(o.flag(), flags->values[i], help);
    flag->type_name(o.type == TraceOptionSpec::Type::kChoice ? "NAME" : "VALUE");
    flags->flags.emplace_back(&o, flag);
  }
}

std::vector<OptionOverride> trace_overrides(const TraceOptionFlags& flags) {
  std::vector<OptionOverride> out;
  for (std::size_t i = 0; i < flags.flags.size(); ++i) {
    const auto& [spec, flag] = flags.flags[i];
    if (flag->count() > 0) out.push_back({spec, flags.values[i], spec->flag()});
  }
  return out;
}

void add_unit_option(CLI::App* cmd, std::string* unit) {
  cmd->add_option("--unit", *unit,
                  "Convert the STEP model's lengths to this unit: mm, cm, m, um, nm, km, in, ft (default: keep the "
                  "file's unit; planes and output are in the chosen unit)")
      ->type_name("UNIT");
}

std::optional<StepLengthUnit> unit_flag(const std::string& text) {
  if (text.empty()) return std::nullopt;
  return named_length_unit(text, "--unit");
}

void add_format_overrides(OutputFormat format, TraceRequest* request) {
  auto set = [&](const char* key) {
    const TraceOptionSpec* spec = find_trace_option(key);
    return std::any_of(request->overrides.begin(), request->overrides.end(),
                       [&](const OptionOverride& o) { return o.option == spec; });
  };
  if (format == OutputFormat::kStep && !set("bspline"))
    request->overrides.push_back({find_trace_option("bspline"), std::string("true"), "--format step"});
  if ((format == OutputFormat::kVtp || format == OutputFormat::kVtpAscii) && !set("geometry"))
    request->overrides.push_back({find_trace_option("geometry"), std::string("mixed"), "--format vtp"});
}

void add_generated_scene_flags(CLI::App* cmd, GeneratedSceneFlags* flags, const std::string& parallel) {
  cmd->add_option("-o,--output", flags->output, "Output file; '-' for standard output (default)");
  cmd->add_option(
      "--format", flags->format,
      "json | csv | obj | svg | step | vtp | vtp-ascii | html (default: from the output file's extension; else json)");
  add_trace_option_flags(cmd, &flags->options);
  cmd->add_option("--threads", flags->threads,
                  "Threads for the " + parallel + " (default: every core; the result does not depend on it)");
  cmd->add_flag("-q,--quiet", flags->quiet, "No summary and no progress on stderr");
  add_progress_option(cmd);
  add_budget_options(cmd);
}

TraceJobResult trace_generated_scene(const nlohmann::json& scene_json, const std::string& source,
                                     const GeneratedSceneFlags& flags) {
  if (flags.threads > 0) set_thread_count(flags.threads);
  if (flags.output != "-") refuse_input_as_output(flags.output);
  const OutputFormat f = flags.format.empty()
                             ? (flags.output == "-" ? OutputFormat::kJson : format_from_path(flags.output))
                             : parse_format(flags.format);
  TraceRequest request{{}, "--intersection", trace_overrides(flags.options)};
  add_format_overrides(f, &request);
  TraceJobResult job;
  if (scene_json["intersections"].empty()) {
    write_runs(job.runs, f, flags.output, nullptr);
    return job;
  }
  const Scene scene = parse_scene(scene_json.dump(), source, {}, input_limits());
  RunProgress progress(flags.quiet);
  job = trace_scene(scene, request);
  progress.meter().close();
  write_runs(job.runs, f, flags.output, &scene);
  return job;
}

}  // namespace ssimarch::cli
