#include "ssimarch/io/topology_json.hpp"

#include "ssimarch/io/json_vectors.hpp"

namespace ssimarch {

namespace {
using nlohmann::json;
json id_or_null(int id) { return id >= 0 ? json(id) : json(nullptr); }
}  // namespace

nlohmann::json curve_network_to_json(const CurveNetwork& net) {
  json vertices = json::array(), edges = json::array(), branches = json::array(), components = json::array(),
       failures = json::array();
  for (std::size_t i = 0; i < net.vertices.size(); ++i) {
    const NetworkVertex& v = net.vertices[i];
    vertices.push_back(json{{"id", i},
                            {"kind", std::string(to_string(v.kind))},
                            {"type", v.type},
                            {"xyz", vector_json(v.p)},
                            {"params", vector_json(v.x)}});
  }
  for (std::size_t i = 0; i < net.edges.size(); ++i) {
    const NetworkEdge& e = net.edges[i];
    edges.push_back(json{{"id", i}, {"vertices", json::array({id_or_null(e.from), id_or_null(e.to)})}, {"curve", e.curve},
                         {"point_range", json::array({e.first, e.last})}, {"length", e.length}});
  }
  for (const NetworkBranch& b : net.branches) {
    const json index = b.rotation.index ? json(*b.rotation.index) : json(nullptr);
    branches.push_back(json{{"curve", b.curve}, {"edges", b.edges}, {"closed", b.closed}, {"length", b.length},
                            {"rotation_index", index}, {"rotation_plane", b.rotation.plane},
                            {"rotation_note", b.rotation.note}});
  }
  for (const NetworkComponent& c : net.components)
    components.push_back(json{{"branches", c.branches}, {"vertices", c.vertices}});
  for (const NetworkFailure& f : net.failures)
    failures.push_back(json{{"curve", f.curve}, {"end", f.end}, {"reason", f.reason}, {"message", f.message}});
  return json{{"complete", net.complete()}, {"vertices", std::move(vertices)}, {"edges", std::move(edges)},
              {"branches", std::move(branches)}, {"components", std::move(components)}, {"failures", std::move(failures)}};
}

}  // namespace ssimarch
