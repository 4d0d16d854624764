// ssimarch singular SCENE.json [--intersection NAME] [--grid N] [--json]: every singular point
// of each intersection, located, classified, with its half-branches (issue 10; docs/singular.md).
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/singular/half_branches.hpp"

namespace ssimarch::cli {

namespace {

struct SingularArgs {
  std::string scene, intersection;
  int grid = 32;
  bool json = false;
};

nlohmann::json vec_json(const Eigen::VectorXd& a) { return std::vector<double>(a.data(), a.data() + a.size()); }

nlohmann::json point_json(const Problem& problem, const SingularLocation& s) {
  const LocalCurve curve = local_curve(problem, s.x);
  const Classification kind = classify(curve.h);
  const std::vector<HalfBranch> hb = half_branches(problem, curve, kind);
  nlohmann::json branches = nlohmann::json::array();
  for (const HalfBranch& b : hb) {
    nlohmann::json terms = nlohmann::json::array();
    for (const PuiseuxTerm& t : b.expansion.terms) terms.push_back({{"exponent", t.exponent}, {"coefficient", t.coefficient}});
    branches.push_back({{"tangent", vec_json(b.tangent_3d)},
                        {"param_tangent", vec_json(b.param_tangent)},
                        {"expansion", {{"coefficient", b.leading_coefficient}, {"exponent", b.leading_exponent},
                                       {"normal", vec_json(b.normal_3d)}, {"terms", terms}}},
                        {"branch", b.branch},
                        {"continuation", b.continuation},
                        {"exit", b.exit_ok ? vec_json(b.exit_point) : nlohmann::json(nullptr)}});
  }
  nlohmann::json cone = nlohmann::json::array();
  for (const auto& l : kind.tangent_cone) cone.push_back({{"direction", vec_json(curve.direction_3d(l.direction))}, {"multiplicity", l.multiplicity}});
  return {{"xyz", vec_json(s.point)},
          {"params", vec_json(s.x)},
          {"type", std::string(to_string(kind.type))},
          {"ak", kind.ak},
          {"multiplicity", kind.multiplicity},
          {"milnor", kind.milnor >= 0 ? nlohmann::json(kind.milnor) : nlohmann::json(nullptr)},
          {"tangent_cone", cone},
          {"gap", s.gap},
          {"sine", s.sine},
          {"half_branches", branches}};
}

void print_table(const std::string& name, const nlohmann::json& points) {
  std::cout << fmt::format("intersection {}: {} singular point(s)\n", name, points.size());
  if (points.empty()) return;
  std::cout << fmt::format("  {:<36} {:<22} {:<5} {:>3} {:>3} {:>8}  {}\n", "point", "type", "A_k", "mu", "m", "branches",
                           "half-branch tangents");
  for (const auto& p : points) {
    const auto& x = p["xyz"];
    std::string tangents;
    for (const auto& b : p["half_branches"])
      tangents += fmt::format("({:.4f},{:.4f},{:.4f}) ", b["tangent"][0].get<double>(), b["tangent"][1].get<double>(),
                              b["tangent"][2].get<double>());
    std::cout << fmt::format("  ({:>10.6f},{:>10.6f},{:>10.6f}) {:<22} {:<5} {:>3} {:>3} {:>8}  {}\n", x[0].get<double>(),
                             x[1].get<double>(), x[2].get<double>(), p["type"].get<std::string>(), p["ak"].get<std::string>(),
                             p["milnor"].is_null() ? std::string("-") : std::to_string(p["milnor"].get<int>()),
                             p["multiplicity"].get<int>(), p["half_branches"].size() / 2, tangents);
  }
}

void run_singular(const SingularArgs& a) {
  if (a.grid < 3) throw CliError("--grid must be at least 3, got " + std::to_string(a.grid));
  Scene scene = load_scene(a.scene, input_limits());
  nlohmann::json out = nlohmann::json::object();
  bool any = false;
  for (const auto& spec : scene.intersections) {
    if (!a.intersection.empty() && spec.name != a.intersection) continue;
    any = true;
    const Problem problem = scene.problem(spec);
    HuntOptions options;
    options.grid = a.grid;
    nlohmann::json points = nlohmann::json::array();
    for (const SingularLocation& s : hunt_singular_points(problem, options)) points.push_back(point_json(problem, s));
    if (a.json)
      out[spec.name] = {{"singular_points", points}};
    else
      print_table(spec.name, points);
  }
  if (!any) throw CliError("--intersection: the scene has no intersection \"" + a.intersection + "\"");
  if (a.json) std::cout << out.dump(2) << "\n";
}

}  // namespace

void add_singular_command(CLI::App& app) {
  auto args = std::make_shared<SingularArgs>();
  CLI::App* cmd = app.add_subcommand(
      "singular",
      "Every singular point of each intersection of a scene (surfaces meeting with parallel normals): location, type "
      "(node, isolated, cusp, tacnode, ramphoid_cusp, oscnode, triple_point, quadruple_point, ...), A_k/D_k name, "
      "Milnor number, multiplicity and the tangents of its half-branches, as a table or JSON (docs/singular.md).");
  cmd->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md)")->required();
  cmd->add_option("--intersection", args->intersection, "Only this intersection (default: all)");
  cmd->add_option("--grid", args->grid, "Samples per parameter direction of the hunt (default 32)");
  cmd->add_flag("--json", args->json, "JSON instead of the table");
  add_budget_options(cmd);
  cmd->callback([args] { run_singular(*args); });
}

}  // namespace ssimarch::cli
