// ssimarch trace SCENE.json: traces the scene's intersections and writes the curves.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "run_budget.hpp"
#include "run_progress.hpp"
#include "ssimarch/core/thread_pool.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "trace_flags.hpp"
#include "trace_output.hpp"

namespace ssimarch::cli {

namespace {

struct TraceArgs {
  std::string scene;
  std::string faces;  // with a STEP model instead of a scene
  std::string unit;   // and its length unit
  std::string output = "-";
  std::string format;
  std::vector<std::string> only;
  bool quiet = false;
  bool list_options = false;
  unsigned threads = 0;
  TraceOptionFlags options;
};

bool is_step_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".step" || ext == ".stp";
}

// The scene file, or for a STEP model (`trace MODEL.step --faces 3,7`) a scene of its listed
// faces, one intersection per pair (io/step_surface_json.hpp).
Scene load_trace_input(const TraceArgs& a) {
  if (!is_step_path(a.scene)) {
    if (!a.faces.empty()) throw CliError("trace: --faces selects faces of a STEP model (MODEL.step or .stp), not of a scene");
    if (!a.unit.empty())
      throw CliError(
          "trace: --unit converts a STEP model (MODEL.step or .stp); in a scene, give a STEP surface "
          "its \"unit\" key");
    return load_scene(a.scene, input_limits());
  }
  if (a.faces.empty())
    throw CliError("trace: a STEP model needs --faces I,J[,...] or --faces all (the numbers of `ssimarch faces " + a.scene + "`)");
  const StepModel model = StepModel::read(a.scene, input_limits(), unit_flag(a.unit));
  const std::vector<int> faces = step_face_list(a.faces, model, "--faces");
  const std::filesystem::path step = std::filesystem::absolute(a.scene);
  return parse_scene(step_faces_scene_json(step, model, faces).dump(), a.scene, {}, input_limits());
}

int run_trace(const TraceArgs& a) {
  if (a.list_options) {
    std::cout << trace_options_markdown();
    return 0;
  }
  if (a.scene.empty()) throw CliError("trace: a scene file is required (ssimarch trace SCENE.json; --help)");
  if (a.threads > 0) set_thread_count(a.threads);
  const Scene scene = load_trace_input(a);
  if (a.output != "-") refuse_input_as_output(a.output);  // before the work (OutputFiles checks it again)
  OutputFormat f = a.format.empty() ? (a.output == "-" ? OutputFormat::kJson : format_from_path(a.output)) : parse_format(a.format);
  TraceRequest request{a.only, "--intersection", trace_overrides(a.options)};
  add_format_overrides(f, &request);
  RunProgress progress(a.quiet);  // the trace's loops report to the thread's meter
  const TraceJobResult job = trace_scene(scene, request);
  progress.meter().close();
  write_runs(job.runs, f, a.output, &scene);
  if (!a.quiet) print_summary(job.runs);
  return job.complete() ? 0 : 1;
}

}  // namespace

void add_trace_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand("trace", "Trace the intersection curves of a scene file");
  cmd->footer(
      "Output: JSON {\"intersections\": [...]} (default; schema in docs/output-format.md), CSV (one row per point), "
      "OBJ (polylines), SVG (pictures), STEP AP242 (the certified B-splines and p-curves of the option bspline, "
      "which --format step turns on), VTK XML for ParaView (--format vtp, base64 binary, or vtp-ascii: FILE.vtp "
      "the curves with params, t, kappa, tau, arc length and branch per point, FILE_points.vtp the singular points "
      "and curve ends, FILE.vtm both; the format turns the option geometry on, method mixed) or HTML (the "
      "interactive 3D viewer page with the surfaces, docs/viewer.md). A summary and, on a terminal, a progress "
      "bar go to stderr.\n"
      "Option values may be numbers or expressions of the scene's constants; each option is a key of a scene's "
      "\"options\" (docs/scene-format.md; --list-options prints the table).\n"
      "Exit status: 0 traced; 1 an intersection found no curve or a start point could not be put on the curve; "
      "2 invalid input; 130 interrupted (Ctrl-C), nothing written.");
  cmd->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md), or a STEP model (.step, .stp) with --faces");
  cmd->add_option("--faces", args->faces,
                  "With a STEP model: the faces to intersect, as `ssimarch faces MODEL.step` numbers them (I,J[,...]: "
                  "every pair of them, one intersection each named faceI-faceJ; all: every pair of the model's faces). "
                  "Each face is trimmed to its loops (docs/cad.md)");
  add_unit_option(cmd, &args->unit);
  cmd->add_option("-o,--output", args->output, "Output file; '-' for standard output (default)");
  cmd->add_option("--format", args->format, "json | csv | obj | svg | step | vtp | vtp-ascii | html (default: from the output file's extension, .vtp/.vtm: vtp, .html: html; else json)");
  cmd->add_option("--intersection", args->only, "Trace only the intersection(s) with this name (repeatable)");
  add_trace_option_flags(cmd, &args->options);
  cmd->add_option("--threads", args->threads,
                  "Threads for the intersections and the start-point search (default: every core; the result does "
                  "not depend on it)");
  cmd->add_flag("-q,--quiet", args->quiet, "No summary and no progress on stderr");
  add_progress_option(cmd);
  cmd->add_flag("--list-options", args->list_options,
                "Print the trace options (scene keys; the flags are --key-with-dashes) as the Markdown table of "
                "docs/scene-format.md, and exit");
  add_budget_options(cmd);
  commands.add(cmd, [args] { return run_trace(*args); });
}

}  // namespace ssimarch::cli
