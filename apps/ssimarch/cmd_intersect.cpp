// ssimarch intersect A.step [B.step]: the curves where the faces of one part (or model, or face
// set) meet those of another, each face trimmed to its loops (io/step_intersect.hpp; docs/cad.md,
// "Part against part").
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/io/step_intersect.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "trace_flags.hpp"
#include "trace_output.hpp"

namespace ssimarch::cli {

namespace {

struct IntersectArgs {
  std::string a, b;
  std::string a_faces = "all", b_faces = "all";
  std::string unit;
  GeneratedSceneFlags out;
};

void print_intersect_summary(const std::vector<IntersectionRun>& runs, const IntersectScene& s) {
  int met = 0, curves = 0, coincident = 0, warnings = 0;
  double length = 0;
  for (const IntersectionRun& r : runs) {
    met += r.result.curves.empty() ? 0 : 1;
    curves += static_cast<int>(r.result.curves.size());
    coincident += r.coincidence ? 1 : 0;
    warnings += static_cast<int>(r.result.warnings.size());
    for (const TracedCurve& c : r.result.curves) length += c.length;
  }
  std::cerr << met << " face pair(s) meet: " << curves << " curve(s), total length " << std::setprecision(12) << length
            << std::setprecision(6);
  if (coincident > 0) std::cerr << "; " << coincident << " pair(s) share a region (coincident, no curve)";
  if (warnings > 0) std::cerr << "; " << warnings << " warning(s) in the output";
  std::cerr << "\n"
            << s.pairs << " face pair(s) traced, " << s.culled - s.culled_by_solid
            << " left out: their boxes are apart";
  if (s.culled_by_solid > 0)
    std::cerr << "; " << s.culled_by_solid << " more: faces of one solid that share no edge or vertex";
  std::cerr << "\n";
}

// Two models whose coordinates mean different lengths are intersected number for number
// unless converted: said, not refused (a file may declare a unit it was not written in).
void warn_if_units_differ(const StepModel& a, const StepModel& b) {
  const StepLengthUnit &ua = a.length_unit(), &ub = b.length_unit();
  if (ua.metres > 0 && ub.metres > 0 && std::fabs(ua.metres - ub.metres) <= 1e-12 * ua.metres) return;
  if (ua.metres == 0 && ub.metres == 0) return;
  std::cerr << "intersect: warning: " << a.file().source << " is in " << ua.name << " and " << b.file().source << " in "
            << ub.name << "; their numbers are compared as they are (--unit mm reads both in millimetres)\n";
}

int run_intersect(const IntersectArgs& args) {
  std::error_code unreadable;  // a missing file is reported by its reader below
  const bool same = args.b.empty() || std::filesystem::equivalent(args.a, args.b, unreadable);
  // Two files in different units meet only when both are read in one (--unit).
  const std::optional<StepLengthUnit> unit = unit_flag(args.unit);
  const StepModel ma = StepModel::read(args.a, input_limits(), unit);
  const std::unique_ptr<StepModel> mb =
      same ? nullptr : std::make_unique<StepModel>(StepModel::read(args.b, input_limits(), unit));
  if (mb) warn_if_units_differ(ma, *mb);
  const StepModel& b_model = same ? ma : *mb;
  const StepFaceSet a{std::filesystem::absolute(args.a), &ma, step_face_list(args.a_faces, ma, "--a-faces", 1)};
  const StepFaceSet b{std::filesystem::absolute(same ? args.a : args.b), &b_model,
                      step_face_list(args.b_faces, b_model, "--b-faces", 1)};
  const IntersectScene s =
      step_intersect_scene(a, b, same, requested_options(trace_overrides(args.out.options)).solid_topology);
  for (const std::string& w : s.not_read) std::cerr << "intersect: not read, left out: " << w << "\n";
  const TraceJobResult job = trace_generated_scene(s.scene, args.a, args.out);
  if (!args.out.quiet) print_intersect_summary(job.runs, s);
  return job.complete() && s.not_read.empty() ? 0 : 1;
}

}  // namespace

void add_intersect_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<IntersectArgs>();
  CLI::App* cmd = app.add_subcommand(
      "intersect", "Intersect the faces of one STEP part or model with another's, each trimmed to its loops");
  cmd->footer(
      "Every face of set A is intersected with every face of set B whose box its box meets (sweep and prune: "
      "pairs whose boxes are apart are never traced); each face is trimmed to its loops (docs/cad.md, \"Part "
      "against part\"). Two faces of one solid meet along the edges and at the vertices they share: answered "
      "from the model's topology, and left out when they share none (--solid-topology false traces them). A and B are "
      "two STEP files, or one file (B left out, or the same file) with two face sets: "
      "then a pair of faces in both sets is traced once, a face never with itself. One intersection per pair, named "
      "faceI-faceJ (one model) or aI-bJ (two), faces numbered as `ssimarch faces` lists them, placed in their "
      "assemblies. Output as for `ssimarch trace` (JSON by default, docs/output-format.md; --format csv, obj, svg, "
      "step, vtp, html). A summary (pairs met, curves, total length, pairs left out) goes to stderr.\n"
      "Exit status: 0 every pair traced (also when none meets); 1 a face could not be read or a pair's trace is "
      "incomplete (e.g. faces lying in each other: coincident, reported without curves); 2 invalid input; 130 "
      "interrupted (Ctrl-C), nothing written.");
  cmd->add_option("a", args->a, "STEP model of set A (.step, .stp; AP203/AP214/AP242)")->required();
  cmd->add_option("b", args->b, "STEP model of set B (default: A's file)");
  cmd->add_option("--a-faces", args->a_faces,
                  "Faces of A: numbers as `ssimarch faces` lists them (I[,J,...]), part:NAME (the faces placed as a "
                  "part whose instance path contains NAME) or all (default)");
  cmd->add_option("--b-faces", args->b_faces, "Faces of B, as --a-faces (default: all)");
  add_unit_option(cmd, &args->unit);
  add_generated_scene_flags(cmd, &args->out, "face pairs");
  commands.add(cmd, [args] { return run_intersect(*args); });
}

}  // namespace ssimarch::cli
