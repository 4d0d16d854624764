#include "ssimarch/network/curve_network.hpp"

#include <algorithm>
#include <numeric>

#include "ssimarch/march/arc_length.hpp"

namespace ssimarch {

std::string_view to_string(VertexKind kind) {
  switch (kind) {
    case VertexKind::kSingularPoint: return "singular_point";
    case VertexKind::kIsolatedPoint: return "isolated_point";
    case VertexKind::kBoundaryEnd: return "boundary_end";
    case VertexKind::kInteriorEnd: return "interior_end";
  }
  return "?";
}

namespace {

// A point of a curve that is a vertex: its index in curve.points and the vertex id.
struct Cut {
  std::size_t index;
  int vertex;
};

// The singular vertices (ids < count) that points of c lie on, by point index; a closed
// curve's closing point is its first one and is not listed twice.
std::vector<Cut> singular_cuts(const TracedCurve& c, const std::vector<NetworkVertex>& vertices, int count,
                               double tol) {
  std::vector<Cut> cuts;
  const std::size_t n = c.closed ? c.points.size() - 1 : c.points.size();
  for (std::size_t i = 0; i < n; ++i)
    for (int v = 0; v < count; ++v)
      if ((c.points[i].p - vertices[static_cast<std::size_t>(v)].p).norm() <= tol) {
        cuts.push_back({i, v});
        break;
      }
  return cuts;
}

// The edge's length as the curve's: the sum of its segments' recorded lengths
// (march/arc_length.hpp, recorded_segment_lengths), so that a branch's edges add up to its curve's length.
double arc_length(const TracedCurve& c, const std::vector<double>& segments, std::size_t first, std::size_t last) {
  double length = 0;
  const std::size_t n = c.points.size();
  auto add = [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) length += segments[i];
  };
  if (last > first) {
    add(first, last);
  } else {  // through the closing point (point n - 1 is point 0)
    add(first, n - 1);
    add(0, last);
  }
  return length;
}

// An open curve's end that is not a singular point: a vertex of its own, on the boundary or,
// anywhere else, a failure.
int end_vertex(const CurvePoint& p, Termination why, const std::string& message, int curve, const char* which,
               CurveNetwork* net) {
  const bool boundary = why == Termination::kLeftDomain;
  net->vertices.push_back({boundary ? VertexKind::kBoundaryEnd : VertexKind::kInteriorEnd, p.p, p.x, ""});
  if (!boundary) net->failures.push_back({curve, which, std::string(to_string(why)), message});
  return static_cast<int>(net->vertices.size()) - 1;
}

// The edges of curve ci between its vertices (cuts, in point order), appended to the network;
// returns the branch.
NetworkBranch branch_of(const Problem& P, const TracedCurve& c, int ci, std::vector<Cut> cuts, CurveNetwork* net) {
  NetworkBranch b;
  b.curve = ci;
  b.closed = c.closed;
  b.length = c.length;
  const std::size_t n = c.points.size();
  std::vector<bool> corner(n, false);
  for (const Cut& k : cuts) corner[k.index] = true;
  const std::vector<double> segments = recorded_segment_lengths(c);
  auto add_edge = [&](const Cut& a, const Cut& z) {
    net->edges.push_back({a.vertex, z.vertex, ci, a.index, z.index, arc_length(c, segments, a.index, z.index)});
    b.edges.push_back(static_cast<int>(net->edges.size()) - 1);
  };
  if (c.closed) {
    if (cuts.empty()) {
      add_edge({0, -1}, {n - 1, -1});
    } else {
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) add_edge(cuts[k], cuts[k + 1]);
      const Cut last = cuts.front().index == 0 ? Cut{n - 1, cuts.front().vertex} : cuts.front();
      add_edge(cuts.back(), last);
    }
    b.rotation = rotation_index(P, c, corner);
    return b;
  }
  // Open: the ends are vertices too (singular ones when the curve starts or stops on one).
  const bool starts_singular = !cuts.empty() && cuts.front().index == 0;
  const bool ends_singular = !cuts.empty() && cuts.back().index == n - 1 && n > 1;
  if (starts_singular && c.start_end != Termination::kLeftDomain)
    net->failures.push_back({ci, "start", std::string(to_string(c.start_end)), c.start_message});
  if (ends_singular && c.end_end != Termination::kLeftDomain)
    net->failures.push_back({ci, "end", std::string(to_string(c.end_end)), c.end_message});
  if (!starts_singular)
    cuts.insert(cuts.begin(), {0, end_vertex(c.points.front(), c.start_end, c.start_message, ci, "start", net)});
  if (!ends_singular) cuts.push_back({n - 1, end_vertex(c.points.back(), c.end_end, c.end_message, ci, "end", net)});
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) add_edge(cuts[k], cuts[k + 1]);
  b.rotation.plane = P.kind() == PairKind::kImplicitImplicit ? "principal axes" : "u,v";
  b.rotation.note = "open curve";
  return b;
}

// Branches sharing a vertex are one component (union-find); a vertex on no branch (an isolated
// point) is a component of its own.
void find_components(CurveNetwork* net) {
  const std::size_t nb = net->branches.size(), nv = net->vertices.size();
  std::vector<std::size_t> parent(nb + nv);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t b = 0; b < nb; ++b)
    for (int e : net->branches[b].edges)
      for (int v : {net->edges[static_cast<std::size_t>(e)].from, net->edges[static_cast<std::size_t>(e)].to})
        if (v >= 0) parent[find(nb + static_cast<std::size_t>(v))] = find(b);
  std::vector<int> root_component(nb + nv, -1);
  auto component_of = [&](std::size_t i) -> NetworkComponent& {
    int& k = root_component[find(i)];
    if (k < 0) {
      k = static_cast<int>(net->components.size());
      net->components.emplace_back();
    }
    return net->components[static_cast<std::size_t>(k)];
  };
  for (std::size_t b = 0; b < nb; ++b) component_of(b).branches.push_back(static_cast<int>(b));
  for (std::size_t v = 0; v < nv; ++v) component_of(nb + v).vertices.push_back(static_cast<int>(v));
}

}  // namespace

CurveNetwork build_curve_network(const Problem& P, const TraceResult& result) {
  CurveNetwork net;
  for (const SingularPointReport& s : result.singular_points)
    net.vertices.push_back({VertexKind::kSingularPoint, s.p, s.x, std::string(to_string(s.type))});
  const int singular = static_cast<int>(net.vertices.size());
  for (const SingularPointReport& s : result.isolated_points)
    net.vertices.push_back({VertexKind::kIsolatedPoint, s.p, s.x, std::string(to_string(s.type))});
  const double tol = 1e-9 * P.scale();
  for (std::size_t ci = 0; ci < result.curves.size(); ++ci) {
    const TracedCurve& c = result.curves[ci];
    if (c.points.empty()) continue;
    net.branches.push_back(branch_of(P, c, static_cast<int>(ci), singular_cuts(c, net.vertices, singular, tol), &net));
  }
  find_components(&net);
  return net;
}

}  // namespace ssimarch
