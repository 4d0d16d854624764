// ssimarch singular SCENE.json [--intersection NAME] [--grid N] [--json]: every singular point
// of each intersection, located, classified, with its half-branches (issue 10; docs/singular.md).
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/singular_json.hpp"
#include "ssimarch/pipeline/singular_job.hpp"

namespace ssimarch::cli {

namespace {

struct SingularArgs {
  std::string scene, intersection;
  int grid = 32;
  bool json = false;
};

void print_table(const std::string& name, const nlohmann::json& points, int contact_points) {
  std::cout << fmt::format("intersection {}: {} singular point(s)\n", name, points.size());
  if (contact_points > 0)
    std::cout << fmt::format(
        "  and {} point(s) of curves of tangential contact, not listed (`ssimarch trace` gives the "
        "curves; their crossings with other branches are listed)\n",
        contact_points);
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
  const Scene scene = load_scene(a.scene, input_limits());
  const std::vector<SingularJobResult> found = run_singular_job(scene, {a.intersection, a.grid});
  nlohmann::json out = nlohmann::json::object();
  for (const SingularJobResult& r : found) {
    nlohmann::json points = nlohmann::json::array();
    for (const SingularAnalysis& p : r.points) points.push_back(singular_analysis_to_json(p));
    if (a.json)
      out[r.intersection] = {{"singular_points", points}, {"tangential_contact_points", r.contact_points}};
    else
      print_table(r.intersection, points, r.contact_points);
  }
  if (a.json) std::cout << out.dump(2) << "\n";
}

}  // namespace

void add_singular_command(CLI::App& app, Commands& commands) {
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
  commands.add(cmd, [args] {
    run_singular(*args);
    return 0;
  });
}

}  // namespace ssimarch::cli
