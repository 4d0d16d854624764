#include "ssimarch/io/singular_json.hpp"

namespace ssimarch {

namespace {
nlohmann::json array_of(const VecX& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}
}  // namespace

nlohmann::json singular_points_to_json(const std::vector<SingularPointReport>& points) {
  using nlohmann::json;
  json out = json::array();
  for (const SingularPointReport& s : points) {
    json branches = json::array();
    for (const auto& b : s.half_branches) {
      json terms = json::array();
      for (const auto& t : b.expansion) terms.push_back(json{{"exponent", t.exponent}, {"coefficient", t.coefficient}});
      branches.push_back(json{{"tangent", json::array({b.tangent.x(), b.tangent.y(), b.tangent.z()})},
                              {"param_tangent", array_of(b.param_tangent)},
                              {"expansion", {{"coefficient", b.coefficient}, {"exponent", b.exponent},
                                             {"normal", json::array({b.normal.x(), b.normal.y(), b.normal.z()})},
                                             {"terms", std::move(terms)}}},
                              {"continuation", b.continuation}});
    }
    out.push_back(json{{"xyz", json::array({s.p.x(), s.p.y(), s.p.z()})},
                       {"params", array_of(s.x)},
                       {"type", s.type},
                       {"ak", s.ak},
                       {"multiplicity", s.multiplicity},
                       {"milnor", s.milnor},
                       {"half_branches", std::move(branches)},
                       {"curves", s.curves}});
  }
  return out;
}

}  // namespace ssimarch
