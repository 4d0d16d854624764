#include "ssimarch/io/singular_json.hpp"

#include "ssimarch/io/json_vectors.hpp"

namespace ssimarch {

nlohmann::json singular_points_to_json(const std::vector<SingularPointReport>& points) {
  using nlohmann::json;
  json out = json::array();
  for (const SingularPointReport& s : points) {
    json branches = json::array();
    for (const auto& b : s.half_branches) {
      json terms = json::array();
      for (const auto& t : b.expansion) terms.push_back(json{{"exponent", t.exponent}, {"coefficient", t.coefficient}});
      branches.push_back(json{{"tangent", json::array({b.tangent.x(), b.tangent.y(), b.tangent.z()})},
                              {"param_tangent", vector_json(b.param_tangent)},
                              {"expansion",
                               {{"coefficient", b.coefficient},
                                {"exponent", b.exponent},
                                {"normal", json::array({b.normal.x(), b.normal.y(), b.normal.z()})},
                                {"terms", std::move(terms)}}},
                              {"continuation", b.continuation}});
    }
    out.push_back(json{{"xyz", json::array({s.p.x(), s.p.y(), s.p.z()})},
                       {"params", vector_json(s.x)},
                       {"type", to_string(s.type)},
                       {"ak", s.ak},
                       {"multiplicity", s.multiplicity},
                       {"milnor", s.milnor},
                       {"half_branches", std::move(branches)},
                       {"curves", s.curves}});
  }
  return out;
}

nlohmann::json singular_analysis_to_json(const SingularAnalysis& point) {
  using nlohmann::json;
  const Classification& kind = point.kind;
  json branches = json::array();
  for (const HalfBranch& b : point.branches) {
    json terms = json::array();
    for (const PuiseuxTerm& t : b.expansion.terms)
      terms.push_back({{"exponent", t.exponent}, {"coefficient", t.coefficient}});
    branches.push_back({{"tangent", vector_json(b.tangent_3d)},
                        {"param_tangent", vector_json(b.param_tangent)},
                        {"expansion",
                         {{"coefficient", b.leading_coefficient},
                          {"exponent", b.leading_exponent},
                          {"normal", vector_json(b.normal_3d)},
                          {"terms", terms}}},
                        {"branch", b.branch},
                        {"continuation", b.continuation},
                        {"exit", b.exit_ok ? vector_json(b.exit_point) : json(nullptr)}});
  }
  json cone = json::array();
  for (const auto& l : kind.tangent_cone)
    cone.push_back(
        {{"direction", vector_json(point.curve.direction_3d(l.direction))}, {"multiplicity", l.multiplicity}});
  return {{"xyz", vector_json(point.location.point)},
          {"params", vector_json(point.location.x)},
          {"type", std::string(to_string(kind.type))},
          {"ak", kind.ak},
          {"multiplicity", kind.multiplicity},
          {"milnor", kind.milnor >= 0 ? json(kind.milnor) : json(nullptr)},
          {"tangent_cone", cone},
          {"gap", point.location.gap},
          {"sine", point.location.sine},
          {"half_branches", branches}};
}

}  // namespace ssimarch
