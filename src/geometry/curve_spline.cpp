#include "ssimarch/geometry/curve_spline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A point of the branch with what the interpolant needs there. y = [3D point; unknowns of H]
// (the unknowns unwrapped along the branch, so that periodic parameters do not jump).
struct Node {
  HermiteEnd end;     // order 2 at a regular point: y, dy/ds, d2y/ds2 from the exact curve jet
  bool regular = true;
  VecX x;             // the unknowns, wrapped (for evaluating the problem)
  // At a singular point: the half-branch tangents (unit, pointing away) with their dx/ds.
  std::vector<std::pair<Vec3, VecX>> branches;
};

// A one-sided tangent is used only when the chord to the piece's other end lies within this
// angle of it (cosine): a chord of length h turns from the tangent by about kappa h / 2, while a
// tangent of another half-branch (a node, a rose's petals) makes a finite angle with it. Beyond,
// the piece keeps only the position at the singular point (docs/math/curve_spline.md §1).
constexpr double kOneSidedTangentCosine = 0.9;

// dx/ds for the 3D unit direction d at x: least squares of [J_H; D] x' = [0; d], where D is the
// point's Jacobian; at a singular point of the curve J_H drops rank but [J_H; D] does not while
// both surfaces are regular.
VecX parameter_direction(const Problem& problem, const VecX& x, const Vec3& d) {
  const Linearization L = problem.linearize(x);
  const int m = static_cast<int>(L.jacobian.rows());
  MatX A(m + 3, problem.dim());
  A.topRows(m) = L.jacobian;
  A.bottomRows(3) = L.point_jacobian;
  VecX rhs = VecX::Zero(m + 3);
  rhs.tail<3>() = d;
  return A.colPivHouseholderQr().solve(rhs);
}

Node make_node(const Problem& problem, const VecX& x, const Vec3& hint) {
  Node node;
  node.x = x;
  const int n = problem.dim();
  const CurveJet<2> jet = curve_jet<2>(problem, x, &hint);
  node.end.value = VecX(3 + n);
  node.end.value << jet.alpha[0], x;
  node.regular = jet.status == CurveJetStatus::kOk;
  node.end.first = VecX(3 + n);
  node.end.second = VecX(3 + n);
  if (node.regular) {
    node.end.first << jet.alpha[1], jet.x[1];
    node.end.second << 2.0 * jet.alpha[2], 2.0 * jet.x[2];
    node.end.order = 2;
    return node;
  }
  // Singular point: only the half-branch tangent `hint` is known (its sign is set per side).
  const Vec3 d = hint.normalized();
  const VecX dx = parameter_direction(problem, x, d);
  node.end.order = d.allFinite() && dx.allFinite() ? 1 : 0;
  node.end.first << d, dx;
  return node;
}

// The end data of `node` for a piece leaving it towards `other` (leaving = true) or arriving
// from it. At a singular point: the half-branch (or, without them, the tangent line) closest to
// the chord, oriented along the piece (a cusp reverses it); none when the chord is far from all.
HermiteEnd side(const Node& node, const Vec3& other, bool leaving) {
  HermiteEnd e = node.end;
  if (node.regular || e.order == 0) return e;
  const Vec3 chord = (other - Vec3(e.value.head<3>())).normalized();
  std::vector<std::pair<Vec3, VecX>> candidates = node.branches;
  if (candidates.empty()) {
    candidates.emplace_back(e.first.head<3>(), e.first.tail(e.first.size() - 3));
    candidates.emplace_back(-e.first.head<3>(), -e.first.tail(e.first.size() - 3));
  }
  const auto best = std::max_element(candidates.begin(), candidates.end(),
                                     [&](const auto& a, const auto& b) { return a.first.dot(chord) < b.first.dot(chord); });
  if (best->first.dot(chord) < kOneSidedTangentCosine) {
    e.order = 0;
    return e;
  }
  // The half-branch points away from the node: a piece arriving along it moves against it.
  const double sign = leaving ? 1.0 : -1.0;
  e.first << sign * best->first, sign * best->second;
  return e;
}

// The point of the true curve in the normal plane of the interpolant at P (unit tangent T):
// Newton on [H(x); T.(point(x) - P)] = 0 from the interpolated unknowns (docs/math/curve_spline.md §3).
std::optional<VecX> project_in_normal_plane(const Problem& problem, VecX x, const Vec3& P, const Vec3& T) {
  const double scale = problem.scale();
  const int n = problem.dim();
  for (int it = 0; it < 16; ++it) {
    const Linearization L = problem.linearize(x);
    VecX F(n);
    F << L.h, T.dot(problem.point(x) - P);
    MatX J(n, n);
    J.topRows(n - 1) = L.jacobian;
    J.row(n - 1) = T.transpose() * L.point_jacobian;
    const VecX dx = J.partialPivLu().solve(-F);
    if (!dx.allFinite()) return std::nullopt;
    x = problem.wrap(x + dx);
    // Converged when the update moves the 3D point by rounding only (the unknowns themselves may
    // move more where the parameterisation is slow, e.g. a rational one near its range's end).
    if ((L.point_jacobian * dx).norm() <= 1e-14 * scale) break;
  }
  const Linearization L = problem.linearize(x);
  if (!(L.distance <= 1e-11 * scale)) return std::nullopt;
  return x;
}

struct Fit {
  const Problem& problem;
  CurveSplineOptions options;
  double tolerance;
  int n;
  std::vector<QuinticPiece> pieces;
  std::vector<bool> smooth;  // per join
  double max_deviation = 0;
  int inserted = 0;

  // Distance of the interpolant's point (and of each p-curve's image) from the true curve point
  // in the normal plane; the curve point itself (wrapped unknowns) in *on_curve.
  double deviation(const QuinticPiece& q, double u, VecX* on_curve) const {
    const VecX y = q.at(u);
    const Vec3 P = y.head<3>();
    const VecX X = y.tail(n);
    const Vec3 T = q.derivative(u).head<3>().normalized();
    std::optional<VecX> x = project_in_normal_plane(problem, problem.wrap(X), P, T);
    if (!x) {
      // Far from the curve in the unknowns (a parameterisation with a large speed, e.g. a rational
      // one near the end of its range): start from the curve point Gauss-Newton finds instead.
      const CorrectorResult g = gauss_newton(problem, problem.wrap(X), CorrectorOptions{1e-13 * problem.scale(), 30});
      if (g.status == CorrectorStatus::kConverged) x = project_in_normal_plane(problem, g.x, P, T);
    }
    if (!x) return kInf;
    *on_curve = X + problem.difference(problem.wrap(X), *x);  // unwrapped like X
    const Vec3 c = problem.point(*x);
    double d = (c - P).norm();
    if (problem.kind() != PairKind::kImplicitImplicit)
      d = std::max(d, (to_vec3(problem.first().point(X[0], X[1])) - c).norm());
    if (problem.kind() == PairKind::kParametricParametric)
      d = std::max(d, (to_vec3(problem.second().point(X[2], X[3])) - c).norm());
    return d;
  }

  QuinticPiece piece(const HermiteEnd& a, const HermiteEnd& b) const {
    // The piece's length h is the arc length of its own 3D part: a fixed point of
    // h -> length(piece(h)), reached in a few iterations from the chord (docs/math/curve_spline.md §1).
    double h = (b.value.head<3>() - a.value.head<3>()).norm();
    QuinticPiece q = quintic_hermite(a, b, h);
    for (int it = 0; it < 12; ++it) {
      const double length = piece_length_3d(q);
      const bool done = std::fabs(length - h) <= 1e-14 * h;
      h = length;
      q = quintic_hermite(a, b, h);
      if (done) break;
    }
    return q;
  }

  void between(const Node& a, const Node& b, int depth) {
    const QuinticPiece q = piece(side(a, b.end.value.head<3>(), true), side(b, a.end.value.head<3>(), false));
    double measured = 0;
    VecX mid;
    for (double u : {0.25, 0.5, 0.75}) {
      VecX on_curve;
      measured = std::max(measured, deviation(q, u, &on_curve));
      if (u == 0.5) mid = on_curve;
    }
    const double bound = kSplineDeviationSafety * measured;
    if (bound <= tolerance || depth >= options.max_halvings || mid.size() == 0) {
      pieces.push_back(q);
      max_deviation = std::max(max_deviation, bound);
      return;
    }
    // Halve: the true curve point found for u = 1/2 becomes an exact point of the spline.
    Node m = make_node(problem, problem.wrap(mid), q.derivative(0.5).head<3>());
    m.end.value.tail(n) = mid;
    ++inserted;
    between(a, m, depth + 1);
    smooth.push_back(m.regular);
    between(m, b, depth + 1);
  }
};

// Closed branches through a singular point start there, so that the C0 knot is the seam.
void start_at_singular_point(std::vector<Node>* nodes) {
  const std::size_t m = nodes->size() - 1;  // the last repeats the first
  for (std::size_t i = 1; i < m; ++i)
    if (!(*nodes)[i].regular) {
      std::rotate(nodes->begin(), nodes->begin() + static_cast<long>(i), nodes->begin() + static_cast<long>(m));
      nodes->back() = nodes->front();
      return;
    }
}

}  // namespace

CurveSpline fit_curve_spline(const Problem& problem, const std::vector<VecX>& points, const std::vector<Vec3>& tangents,
                             bool closed, const CurveSplineOptions& options,
                             const std::vector<std::vector<Vec3>>* half_branches) {
  if (points.size() < 2 || tangents.size() != points.size())
    throw std::invalid_argument("fit_curve_spline: needs >= 2 points, each with a tangent");
  const auto started = std::chrono::steady_clock::now();
  const int n = problem.dim();
  std::vector<Node> nodes;
  for (std::size_t i = 0; i < points.size(); ++i) {
    nodes.push_back(make_node(problem, points[i], tangents[i]));
    if (nodes.back().regular || !half_branches || i >= half_branches->size()) continue;
    for (const Vec3& h : (*half_branches)[i])
      nodes.back().branches.emplace_back(h.normalized(), parameter_direction(problem, points[i], h.normalized()));
  }
  if (closed) start_at_singular_point(&nodes);
  // Unwrap the periodic unknowns along the branch.
  for (std::size_t i = 1; i < nodes.size(); ++i)
    nodes[i].end.value.tail(n) = VecX(nodes[i - 1].end.value.tail(n)) + problem.difference(nodes[i - 1].x, nodes[i].x);

  // Repeated points (a zero-length piece has no tangent to measure along) are dropped.
  nodes.erase(std::unique(nodes.begin(), nodes.end(),
                          [](const Node& a, const Node& b) { return a.end.value.head<3>() == b.end.value.head<3>(); }),
              nodes.end());
  if (nodes.size() < 2) throw std::invalid_argument("fit_curve_spline: the points coincide");
  Fit fit{problem, options, options.tolerance > 0 ? options.tolerance : 1e-9 * problem.scale(), n, {}, {}, 0, 0};
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    if (i > 0) fit.smooth.push_back(nodes[i].regular);
    fit.between(nodes[i], nodes[i + 1], 0);
  }
  CurveSpline out;
  out.tolerance = fit.tolerance;
  out.max_deviation = fit.max_deviation;
  out.within_tolerance = fit.max_deviation <= fit.tolerance;
  out.pieces = static_cast<int>(fit.pieces.size());
  out.inserted_points = fit.inserted;
  out.c0_knots = static_cast<int>(std::count(fit.smooth.begin(), fit.smooth.end(), false));
  const bool periodic = closed && nodes.front().regular && out.c0_knots == 0;
  std::vector<bool> smooth = fit.smooth;
  if (periodic) smooth.push_back(true);
  else if (closed) ++out.c0_knots;  // the seam at the singular point
  const BSplineCurve clamped = bspline_from_pieces(fit.pieces, fit.smooth, false);
  const BSplineCurve stacked = periodic ? bspline_from_pieces(fit.pieces, smooth, true) : clamped;
  out.curve = stacked.slice(0, 3);
  // A p-curve is periodic with the 3D curve only when its parameters return to their start
  // (a loop around a cylinder ends one period away: that p-curve stays clamped).
  const VecX winding = nodes.back().end.value.tail(n) - nodes.front().end.value.tail(n);
  auto pcurve = [&](int first) {
    const bool returns = winding.segment(first, 2).norm() <= 1e-12 * (1 + nodes.front().end.value.tail(n).norm());
    return (periodic && returns ? stacked : clamped).slice(3 + first, 2);
  };
  if (problem.kind() != PairKind::kImplicitImplicit) out.pcurves.push_back(pcurve(0));
  if (problem.kind() == PairKind::kParametricParametric) out.pcurves.push_back(pcurve(2));
  out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return out;
}

}  // namespace ssimarch
