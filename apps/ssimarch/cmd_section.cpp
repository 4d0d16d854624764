// ssimarch section MODEL.step --plane X,Y,Z,NX,NY,NZ: the curves where planes cut a STEP model,
// each face trimmed to its loops (io/step_section.hpp; docs/cad.md, "Sections").
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/io/step_section.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "trace_flags.hpp"
#include "trace_output.hpp"

namespace ssimarch::cli {

namespace {

struct SectionArgs {
  std::string model;
  std::vector<std::string> planes;
  std::string faces = "all";
  std::string unit;
  GeneratedSceneFlags out;
};

// Per plane: the faces it cuts, their curves and total length; then what was left out.
void print_section_summary(const std::vector<IntersectionRun>& runs, std::size_t planes, const SectionScene& s) {
  for (std::size_t k = 1; k <= planes; ++k) {
    const std::string suffix = "-plane" + std::to_string(k);
    int faces = 0, curves = 0, coincident = 0, warnings = 0;
    double length = 0;
    for (const IntersectionRun& r : runs) {
      const std::string& n = r.spec.name;
      if (n.size() < suffix.size() || n.compare(n.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
      faces += r.result.curves.empty() ? 0 : 1;
      curves += static_cast<int>(r.result.curves.size());
      coincident += r.coincidence ? 1 : 0;
      warnings += static_cast<int>(r.result.warnings.size());
      for (const TracedCurve& c : r.result.curves) length += c.length;
    }
    std::cerr << "plane" << k << ": " << faces << " face(s) cut, " << curves << " curve(s), total length "
              << std::setprecision(12) << length << std::setprecision(6);
    if (coincident > 0) std::cerr << "; " << coincident << " face(s) lie in the plane (coincident, no curve)";
    if (warnings > 0) std::cerr << "; " << warnings << " warning(s) in the output";
    std::cerr << "\n";
  }
  std::cerr << s.pairs << " face-plane pair(s) traced, " << s.culled
            << " left out: the face's box does not reach the plane\n";
}

int run_section(const SectionArgs& a) {
  if (a.planes.empty()) throw CliError("section: at least one --plane X,Y,Z,NX,NY,NZ is required (--help)");
  std::vector<SectionPlane> planes;
  for (const std::string& p : a.planes) planes.push_back(parse_section_plane(p, "--plane"));
  const StepModel model = StepModel::read(a.model, input_limits(), unit_flag(a.unit));
  const std::vector<int> faces = step_face_list(a.faces, model, "--faces", 1);
  const SectionScene s = step_section_scene(std::filesystem::absolute(a.model), model, faces, planes);
  for (const std::string& w : s.not_read) std::cerr << "section: not read, left out: " << w << "\n";
  const TraceJobResult job = trace_generated_scene(s.scene, a.model, a.out);
  if (!a.out.quiet) print_section_summary(job.runs, planes.size(), s);
  return job.complete() && s.not_read.empty() && s.pairs > 0 ? 0 : 1;
}

}  // namespace

void add_section_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<SectionArgs>();
  CLI::App* cmd =
      app.add_subcommand("section", "Cut a STEP model by planes: the curves on every face, trimmed to its loops");
  cmd->footer(
      "Each face whose box the plane reaches is intersected with the whole (unbounded) plane and its curves are cut "
      "to the face's loops (docs/cad.md, \"Sections\"); one intersection per face and plane, named faceI-planeK "
      "(faces numbered as `ssimarch faces MODEL.step` lists them, placed in their assemblies). Output as for "
      "`ssimarch trace` (JSON by default, docs/output-format.md; --format csv, obj, svg, step, vtp, html). A summary "
      "per plane (faces cut, curves, total length) goes to stderr.\n"
      "Exit status: 0 every face traced; 1 a face could not be read, no face reaches a plane, or a face's trace is "
      "incomplete (e.g. a face lying in the plane: coincident, reported without curves); 2 invalid input; 130 "
      "interrupted (Ctrl-C), nothing written.");
  cmd->add_option("model", args->model, "STEP model (.step, .stp; AP203/AP214/AP242)")->required();
  cmd->add_option(
         "--plane", args->planes,
         "A cutting plane X,Y,Z,NX,NY,NZ: a point and the normal, in the model's length unit (--unit's when given; "
         "repeatable)")
      ->required();
  cmd->add_option("--faces", args->faces,
                  "The faces to cut: numbers as `ssimarch faces MODEL.step` lists them (I[,J,...]) or all (default)");
  add_unit_option(cmd, &args->unit);
  add_generated_scene_flags(cmd, &args->out, "faces");
  commands.add(cmd, [args] { return run_section(*args); });
}

}  // namespace ssimarch::cli
