// ssimarch curve-geometry SCENE.json --intersection NAME --at X,Y,Z [--method M] [--step H]:
// the differential geometry of one intersection curve at the curve point nearest to X,Y,Z, as
// JSON (issue 4; docs/geometry.md).
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/geometry/intersection_geometry.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/point_geometry.hpp"

namespace ssimarch::cli {

namespace {

struct CurveGeometryArgs {
  std::string scene, intersection, at, method, toward;
  double step = 0.01;
};

Vec3 parse_xyz(const std::string& text, const Constants& constants, const std::string& option) {
  std::vector<double> v;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    v.push_back(evaluate_constant(part, constants, option + " component " + std::to_string(v.size() + 1)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (v.size() != 3) throw CliError(option + " " + text + ": expected three components X,Y,Z, got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

nlohmann::json vec_json(const Vec3& a) {
  return a.allFinite() ? nlohmann::json::array({a.x(), a.y(), a.z()}) : nlohmann::json(nullptr);
}
nlohmann::json num_json(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

int run_curve_geometry(const CurveGeometryArgs& a) {
  if (!(a.step > 0) || !std::isfinite(a.step)) throw CliError("--step must be a positive length, got " + std::to_string(a.step));
  Scene scene = load_scene(a.scene, input_limits());
  const IntersectionSpec* spec = scene.intersection(a.intersection);
  if (!spec) {
    const std::string known = scene.intersection_names();
    throw CliError("--intersection: the scene has no intersection \"" + a.intersection + "\" (it has: " +
                   (known.empty() ? std::string("none") : known) + ")");
  }
  GeometryMethod method = spec->options.geometry.value_or(GeometryMethod::kExact);
  if (!a.method.empty() && !parse(a.method, &method))
    throw CliError("--method: unknown method \"" + a.method + "\" (known: " + method_names() + ")");
  const std::string method_name(to_string(method));
  const Vec3 at = parse_xyz(a.at, scene.constants, "--at");
  std::optional<Vec3> toward;
  if (!a.toward.empty()) toward = parse_xyz(a.toward, scene.constants, "--toward");

  const Problem problem = scene.problem(*spec);
  nlohmann::json out{{"intersection", spec->name}, {"method", method_name}, {"at", vec_json(at)}};
  const PointGeometry r = geometry_at_point(problem, {at, method, a.step, toward});
  if (!r.x) {
    out["status"] = "not-on-curve";
    out["message"] = "Newton from the nearest surface points did not converge onto the curve";
    std::cout << out.dump(2) << "\n";
    return 1;
  }
  const CurveGeometry& g = r.geometry;
  out["point"] = vec_json(r.point);
  out["distance"] = num_json(r.distance);
  out["unknowns"] = std::vector<double>(r.x->data(), r.x->data() + r.x->size());
  out["t"] = vec_json(g.t);
  out["n"] = vec_json(g.n);
  out["b"] = vec_json(g.b);
  out["kappa"] = num_json(g.kappa);
  out["tau"] = num_json(g.tau);
  out["kappa_prime"] = num_json(g.kappa_prime);
  out["theta"] = num_json(g.theta);
  out["status"] = std::string(to_string(g.status));
  out["tau_convention"] = "standard: (c' x c'').c''' / |c' x c''|^2 (the thesis prints -tau)";
  if (r.sampled) {
    out["step"] = a.step;
    out["samples"] = r.samples;
  }
  std::cout << out.dump(2) << "\n";
  return 0;
}

}  // namespace

void add_curve_geometry_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<CurveGeometryArgs>();
  CLI::App* cmd = app.add_subcommand(
      "curve-geometry",
      "Tangent t, principal normal n, binormal b, curvature kappa, torsion tau, dkappa/ds and the angle theta between the "
      "surface normals of one intersection curve at the point nearest to --at, as JSON. Quantities a method cannot "
      "determine there are null and \"status\" says why. Exit status 1 if no curve point is found near --at.");
  cmd->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md)")->required();
  cmd->add_option("--intersection", args->intersection, "Name of the intersection in the scene")->required();
  cmd->add_option("--at", args->at, "A point near the curve, X,Y,Z (numbers or expressions); it is projected onto the curve")
      ->required();
  cmd->add_option("--method", args->method,
                  "exact, ye-maekawa, willmore, stoyanov, estimate, barnhill-kersey or mixed (default: the "
                  "intersection's \"geometry\" option, else exact; docs/geometry.md)");
  cmd->add_option("--step", args->step,
                  "Chord between the samples the estimate methods take along the curve (model units, default 0.01)");
  cmd->add_option("--toward", args->toward,
                  "Orient t so that t . (X,Y,Z) >= 0 (default: the method's natural orientation, N1 x N2)");
  add_budget_options(cmd);
  commands.add(cmd, [args] { return run_curve_geometry(*args); });
}

}  // namespace ssimarch::cli
