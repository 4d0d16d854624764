// ssimarch trace SCENE.json: traces the scene's intersections and writes the curves.
#include <iostream>
#include <algorithm>
#include <memory>

#include "commands.hpp"
#include "ssimarch/io/run.hpp"
#include "ssimarch/io/scene.hpp"
#include "trace_output.hpp"

namespace ssimarch::cli {

namespace {

struct TraceArgs {
  std::string scene;
  std::string output = "-";
  std::string format;
  std::vector<std::string> only;
  std::string predictor, corrector, step, geometry;
  double step_length = -1, deviation = -1, tolerance = -1;
  bool quiet = false;
};

// The CLI's option flags as a scene "options" object, so they are validated by the same code.
nlohmann::json overrides(const TraceArgs& a) {
  nlohmann::json o = nlohmann::json::object();
  if (!a.predictor.empty()) o["predictor"] = a.predictor;
  if (!a.corrector.empty()) o["corrector"] = a.corrector;
  if (!a.step.empty()) o["step"] = a.step;
  if (a.step_length >= 0) o["step_length"] = a.step_length;
  if (a.deviation >= 0) o["deviation"] = a.deviation;
  if (a.tolerance >= 0) o["tolerance"] = a.tolerance;
  if (!a.geometry.empty()) o["geometry"] = a.geometry;
  return o;
}

void run_trace(const TraceArgs& a) {
  Scene scene = load_scene(a.scene);
  nlohmann::json o = overrides(a);
  std::vector<IntersectionRun> runs;
  for (const std::string& name : a.only) {
    bool found = false;
    for (const auto& s : scene.intersections) found = found || s.name == name;
    if (!found) {
      std::string known;
      for (const auto& s : scene.intersections) known += (known.empty() ? "" : ", ") + s.name;
      throw CliError("--intersection: the scene has no intersection \"" + name + "\" (it has: " + known + ")");
    }
  }
  for (auto spec : scene.intersections) {
    if (!a.only.empty() && std::find(a.only.begin(), a.only.end(), spec.name) == a.only.end()) continue;
    apply_trace_options(o, scene.constants, "command-line options", &spec.options, &spec.extra_options);
    runs.push_back(run_intersection(scene, spec));
  }
  if (runs.empty()) throw CliError(a.scene + ": the scene has no intersections to trace");
  OutputFormat f = a.format.empty() ? (a.output == "-" ? OutputFormat::kJson : format_from_path(a.output)) : parse_format(a.format);
  PointDecorator decorate = make_geometry_decorator(runs);
  write_runs(runs, f, a.output, decorate);
  if (!a.quiet) print_summary(runs);
  for (const auto& r : runs)
    // No curve is a result when the start-point search proved there is none (issue 11 item 6).
    if ((r.result.curves.empty() && !r.result.start_search.certified) || r.result.failed_starts > 0) g_exit_status = 1;
}

}  // namespace

void add_trace_command(CLI::App& app) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand("trace", "Trace the intersection curves of a scene file");
  cmd->footer(
      "Output: JSON {\"intersections\": [...]} (default; schema in docs/output-format.md), CSV (one row per point), "
      "OBJ (polylines) or SVG (pictures). A summary goes to stderr.\n"
      "Exit status: 0 traced; 1 an intersection found no curve or a start point could not be put on the curve; "
      "2 invalid input.");
  cmd->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md)")->required();
  cmd->add_option("-o,--output", args->output, "Output file; '-' for standard output (default)");
  cmd->add_option("--format", args->format, "json | csv | obj | svg (default: from the output file's extension, else json)");
  cmd->add_option("--intersection", args->only, "Trace only the intersection(s) with this name (repeatable)");
  cmd->add_option("--predictor", args->predictor, "Predictor for every intersection (overrides the scene; docs/marching.md)");
  cmd->add_option("--corrector", args->corrector, "Corrector for every intersection (overrides the scene)");
  cmd->add_option("--step", args->step, "Step rule for every intersection (overrides the scene)");
  cmd->add_option("--step-length", args->step_length, "Nominal step length, model units (overrides the scene)");
  cmd->add_option("--deviation", args->deviation, "Chordal deviation tolerance delta, model units (overrides the scene)");
  cmd->add_option("--tolerance", args->tolerance, "Corrector tolerance, model units (default 1e-12)");
  cmd->add_option("--geometry", args->geometry,
                  "Add the curve's differential geometry (t, n, b, kappa, tau, kappa_prime, theta) to every point, "
                  "computed by this method (docs/geometry.md)");
  cmd->add_flag("-q,--quiet", args->quiet, "No summary on stderr");
  cmd->callback([args] { run_trace(*args); });
}

}  // namespace ssimarch::cli
