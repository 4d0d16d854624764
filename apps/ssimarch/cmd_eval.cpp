// ssimarch eval SCENE.json --surface NAME --at U,V | X,Y,Z --order K: a surface's point and
// every partial derivative up to order K, as JSON, for checking surfaces by hand.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/core/jet.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch::cli {

namespace {

constexpr int kMaxEvalOrder = 8;

struct EvalArgs {
  std::string scene, surface, at;
  int order = 2;
};

std::vector<double> parse_point(const std::string& text, const Constants& constants) {
  std::vector<double> v;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    v.push_back(evaluate_constant(part, constants, "--at component " + std::to_string(v.size() + 1)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return v;
}

template <int NV>
nlohmann::json derivative_list(const std::function<std::array<double, 3>(const std::array<int, NV>&)>& d, int order, int components) {
  nlohmann::json list = nlohmann::json::array();
  const auto& layout = Jet<NV, kMaxEvalOrder>::Layout::get();
  for (int i = 0; i < Jet<NV, kMaxEvalOrder>::kSize; ++i) {
    const auto& e = layout.exponents[static_cast<std::size_t>(i)];
    if (layout.degree[static_cast<std::size_t>(i)] > order) break;
    auto value = d(e);
    nlohmann::json entry{{"order", e}};
    if (components == 3) entry["value"] = {value[0], value[1], value[2]};
    else entry["value"] = value[0];
    list.push_back(entry);
  }
  return list;
}

void run_eval(const EvalArgs& a) {
  if (a.order < 0 || a.order > kMaxEvalOrder)
    throw CliError("--order must be between 0 and " + std::to_string(kMaxEvalOrder) + ", got " + std::to_string(a.order));
  Scene scene = load_scene(a.scene, input_limits());
  const Surface& s = scene.surface(a.surface);
  std::vector<double> at = parse_point(a.at, scene.constants);
  nlohmann::json out{{"surface", a.surface}, {"type", std::string(s.type_name())}, {"at", at}, {"order", a.order}};
  if (at.size() == 2) {
    if (!s.is_parametric())
      throw CliError("--at " + a.at + ": two components are parameters (u,v), but surface \"" + a.surface + "\" (" +
                     std::string(s.type_name()) + ") has no parametric form; give a point X,Y,Z");
    using J = Jet<2, kMaxEvalOrder>;
    Vec3T<J> f = s.point(J::variable(0, at[0]), J::variable(1, at[1]));
    out["form"] = "parametric";
    out["point"] = {f.x.value(), f.y.value(), f.z.value()};
    out["derivatives"] = derivative_list<2>(
        [&](const std::array<int, 2>& e) { return std::array<double, 3>{f.x.derivative(e), f.y.derivative(e), f.z.derivative(e)}; },
        a.order, 3);
    const ParamDomain& d = s.domain();
    if (!(d.u.contains(at[0]) || d.periodic_u) || !(d.v.contains(at[1]) || d.periodic_v)) out["warning"] = "(u,v) lies outside the domain";
    if (a.order >= 1) {
      auto n = unit_normal(s, at[0], at[1]);
      out["unit_normal"] = n ? nlohmann::json{n->x(), n->y(), n->z()} : nlohmann::json(nullptr);
      if (!n) out["warning"] = "degenerate point: Fu x Fv = 0, no normal";
    }
    if (a.order >= 2) {
      if (auto ff = fundamental_forms(s, at[0], at[1]))
        out["fundamental_forms"] = {{"E", ff->E}, {"F", ff->F}, {"G", ff->G}, {"L", ff->L}, {"M", ff->M}, {"N", ff->N}};
    }
  } else if (at.size() == 3) {
    if (!s.is_implicit())
      throw CliError("--at " + a.at + ": three components are a point X,Y,Z, but surface \"" + a.surface + "\" (" +
                     std::string(s.type_name()) + ") has no implicit form; give parameters U,V");
    using J = Jet<3, kMaxEvalOrder>;
    J f = s.value(Vec3T<J>(J::variable(0, at[0]), J::variable(1, at[1]), J::variable(2, at[2])));
    out["form"] = "implicit";
    out["value"] = f.value();
    out["derivatives"] = derivative_list<3>(
        [&](const std::array<int, 3>& e) { return std::array<double, 3>{f.derivative(e), 0, 0}; }, a.order, 1);
    if (a.order >= 1) {
      Vec3 g(f.d(0), f.d(1), f.d(2));
      out["gradient"] = {g.x(), g.y(), g.z()};
      if (g.norm() > 0) out["unit_normal"] = {g.x() / g.norm(), g.y() / g.norm(), g.z() / g.norm()};
    }
  } else {
    throw CliError("--at needs 2 components (u,v of a parametric form) or 3 (x,y,z for an implicit form), got " +
                   std::to_string(at.size()));
  }
  std::cout << out.dump(2) << "\n";
}

}  // namespace

void add_eval_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* cmd = app.add_subcommand("eval", "Print a surface's point and all partial derivatives up to an order, as JSON");
  cmd->footer("Derivatives are exact (Taylor jets). Each entry's \"order\" is the multi-index: [i,j] for d^(i+j)F/du^i dv^j, "
              "[i,j,k] for d^(i+j+k)f/dx^i dy^j dz^k. Components of --at may be expressions using the scene's constants.");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("--surface", args->surface, "Name of the surface in the scene")->required();
  cmd->add_option("--at", args->at, "U,V for the parametric form or X,Y,Z for the implicit form")->required();
  cmd->add_option("--order", args->order, "Highest derivative order, 0.." + std::to_string(kMaxEvalOrder) + " (default 2)");
  add_budget_options(cmd);
  commands.add(cmd, [args] {
    run_eval(*args);
    return 0;
  });
}

}  // namespace ssimarch::cli
