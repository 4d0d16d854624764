#include "ssimarch/pipeline/shared_boundary.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "ssimarch/core/gauss_legendre.hpp"
#include "ssimarch/problem/closest_point.hpp"

namespace ssimarch {

namespace {

// Arc length over [a, b]: 8-point Gauss-Legendre on the speed, exact to rounding on a piece no
// longer than the chord bound that crosses no break of the edge (pieces end at the breaks).
double edge_length(const FaceRegion& r, int i, double a, double b) {
  const auto& kNodes = kGaussLegendre8Nodes;
  const auto& kWeights = kGaussLegendre8Weights;
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double sum = 0;
  for (std::size_t k = 0; k < kNodes.size(); ++k)
    sum += kWeights[k] *
           (r.boundary_derivative(i, m - h * kNodes[k]).norm() + r.boundary_derivative(i, m + h * kNodes[k]).norm());
  return sum * h;
}

struct Sampling {
  double deviation, chord;  // the closed forms' rule (ResolvedTraceOptions)
  double floor;             // pieces shorter than this (model units) are not split
};

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Parameters after `a` up to `b`: the piece is split at its middle while its chord is longer than
// the chord bound or its middle farther than the deviation from the chord, down to the floor (a
// length of the model) or to 1e-12 of the edge's range, which bounds the depth.
void refine(const FaceRegion& r, int i, double a, double b, const Sampling& s, double width, std::vector<double>* out) {
  const Vec3 pa = r.boundary_point(i, a), pb = r.boundary_point(i, b);
  const double m = 0.5 * (a + b);
  const Vec3 pm = r.boundary_point(i, m);
  const double chord = (pb - pa).norm();
  const bool fine = chord <= s.chord && distance_to_segment(pm, pa, pb) <= s.deviation;
  if (fine || (pm - pa).norm() + (pb - pm).norm() <= s.floor || b - a <= 1e-12 * width) {
    out->push_back(b);
    return;
  }
  refine(r, i, a, m, s, width, out);
  refine(r, i, m, b, s, width, out);
}

std::vector<double> edge_parameters(const FaceRegion& r, int i, const Sampling& s) {
  const auto [lo, hi] = r.boundary_range(i);
  // Eight pieces first (a closed edge's ends coincide, and a piece's middle alone does not see a
  // turn of more than half a circle), cut at the edge's breaks (a B-spline's knots).
  constexpr int kFirstPieces = 8;
  std::vector<double> cuts = r.boundary_breaks(i);
  for (int k = 1; k < kFirstPieces; ++k) cuts.push_back(lo + (hi - lo) * k / kFirstPieces);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> out{lo};
  for (double c : cuts)
    if (c > out.back() && c <= hi) refine(r, i, out.back(), c, s, hi - lo, &out);
  return out;
}

// The unknowns of the point of the curve at X: from the nearest points on the parametric
// surfaces, found from the previous point's (neighbours along an edge) or by a grid at the first.
std::optional<UnknownVec> unknowns_at(const Problem& problem, const Vec3& X, const UnknownVec* previous) {
  if (!previous) {
    const auto near = unknowns_near(problem, X);
    if (!near) return std::nullopt;
    return UnknownVec(*near);
  }
  UnknownVec x = *previous;
  switch (problem.kind()) {
    case PairKind::kImplicitImplicit: x = X; break;
    case PairKind::kParametricParametric:
      x.tail<2>() = refine_closest_parameters(problem.second(), X, Vec2(x[2], x[3]));
      [[fallthrough]];
    case PairKind::kParametricImplicit:
      x.head<2>() = refine_closest_parameters(problem.first(), X, Vec2(x[0], x[1]));
      break;
  }
  return x;
}

double normals_sine(const Problem& problem, const UnknownVec& x) {
  const Linearization L = problem.linearize(x);
  return L.normal_first.cross(L.normal_second).norm();
}

// The curve along boundary curve i of `face`, or nothing where a point has no unknowns.
std::optional<TracedCurve> edge_curve(const Problem& problem, const FaceRegion& face, int i, const Sampling& s) {
  TracedCurve c;
  const std::vector<double> params = edge_parameters(face, i, s);
  bool tangent = true;
  for (std::size_t k = 0; k < params.size(); ++k) {
    const Vec3 X = face.boundary_point(i, params[k]);
    const auto x = unknowns_at(problem, X, c.points.empty() ? nullptr : &c.points.back().x);
    if (!x) return std::nullopt;
    c.points.push_back({*x, X, face.boundary_derivative(i, params[k]).normalized()});
    if (k > 0) c.segment_lengths.push_back(edge_length(face, i, params[k - 1], params[k]));
    tangent = tangent && normals_sine(problem, *x) <= kSharedEdgeTangentSine;
  }
  for (double l : c.segment_lengths) c.length += l;
  const std::string where = "at a vertex of the edge #" + std::to_string(face.boundary_edge(i)) + " both faces share";
  const auto ends = face.boundary_edge_vertices(i);
  c.closed = ends[0] != 0 && ends[0] == ends[1];
  if (c.closed) {
    c.points.back() = c.points.front();  // a closed curve's last point repeats its first
  } else {
    c.start_end = c.end_end = Termination::kLeftDomain;
    c.start_message = c.end_message = where;
  }
  c.tangential_contact = tangent;
  return c;
}

}  // namespace

std::optional<TraceResult> shared_boundary(const Problem& problem, const FaceRegion* first, const FaceRegion* second,
                                           const ResolvedTraceOptions& options) {
  if (!first || !second || first->solid().empty() || first->solid() != second->solid()) return std::nullopt;
  const auto started = std::chrono::steady_clock::now();
  std::set<std::int64_t> edges_of_second;
  for (int j = 0; j < second->boundary_curves(); ++j) edges_of_second.insert(second->boundary_edge(j));
  TraceResult out;
  const Sampling sampling{options.options.deviation, options.chord, options.options.min_step};
  std::set<std::int64_t> on_shared_edges;
  for (int i = 0; i < first->boundary_curves(); ++i) {
    const std::int64_t edge = first->boundary_edge(i);
    if (edge == 0 || !edges_of_second.count(edge)) continue;
    auto curve = edge_curve(problem, *first, i, sampling);
    if (!curve) return std::nullopt;  // a point no surface reaches: trace the pair instead
    out.stats.points += static_cast<long>(curve->points.size());
    out.curves.push_back(std::move(*curve));
    for (std::int64_t v : first->boundary_edge_vertices(i)) on_shared_edges.insert(v);
  }
  // Vertices the faces share off their shared edges: the faces touch there only.
  std::map<std::int64_t, Vec3> vertices_of_second;
  for (const auto& [id, p] : second->boundary_vertices()) vertices_of_second.emplace(id, p);
  for (const auto& [id, p] : first->boundary_vertices()) {
    if (id == 0 || on_shared_edges.count(id) || !vertices_of_second.count(id)) continue;
    const auto x = unknowns_at(problem, p, nullptr);
    if (!x) return std::nullopt;
    SingularPointReport point;
    point.x = VecX(*x);
    point.p = p;
    point.type = SingularType::kIsolated;
    out.isolated_points.push_back(std::move(point));
  }
  out.start_search.method = StartSearchMethod::kSharedBoundary;
  out.start_search.certified = true;
  out.start_search.note = "faces of one solid meet only along their shared edges and at their shared vertices: " +
                          std::to_string(out.curves.size()) + " shared edge(s), " +
                          std::to_string(out.isolated_points.size()) +
                          " vertex(es) shared off them, read from the model's topology (not traced)";
  out.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return out;
}

}  // namespace ssimarch
