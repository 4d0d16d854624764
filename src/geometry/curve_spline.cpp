#include "ssimarch/geometry/curve_spline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "ssimarch/core/contract.hpp"
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

// A traced point is on both surfaces to the tracer's tolerance in 3D; where the surfaces meet at
// a small angle (near a singular point, where they touch) that leaves it farther from the curve,
// by the tolerance over the angle (1e-9 off for a residual of 1e-14 next to ex22's cusp). Newton
// steps of least norm on H alone, x -= J^T (J J^T)^-1 H, put it on the curve to rounding before
// its jet is taken: quadratic convergence from the tracer's tolerance takes two or three. The
// iteration stops when a step no longer moves the 3D point beyond rounding, or when a step is not
// at most half the previous one (no longer contracting: that step is not taken). Steps that halve
// at least go from the tracer's tolerance to rounding in log2(tolerance / rounding) iterations, so
// the loop is bounded by the tolerances themselves. A point where J J^T is singular (the singular
// point itself) is kept as traced.
VecX onto_curve(const Problem& problem, VecX x) {
  const double rounding = 1e-15 * problem.scale();
  double previous = std::numeric_limits<double>::infinity();
  while (true) {
    const Linearization L = problem.linearize(x);
    const MatX J = L.jacobian;
    const VecX dx = -J.transpose() * (J * J.transpose()).ldlt().solve(VecX(L.h));
    const double moved = (L.point_jacobian * dx).norm();
    if (!dx.allFinite() || !(moved <= 0.5 * previous)) break;
    x = problem.wrap(x + dx);
    if (moved <= rounding) break;
    previous = moved;
  }
  return x;
}

Node make_node(const Problem& problem, const VecX& traced, const Vec3& hint) {
  Node node;
  const VecX x = onto_curve(problem, traced);
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

// A candidate piece with what its check measured: the largest distance at u = 1/4, 1/2, 3/4 and
// the curve point found for u = 1/2 (unwrapped unknowns; empty when the projection failed).
struct Checked {
  QuinticPiece q;
  double measured = 0;
  VecX mid;
  int start_continuity = 2;  // the highest continuity the piece allows at its ends (§2)
  int end_continuity = 2;
};

// The piece whose 3D part has arc length h, built by build(h): a fixed point of
// h -> length(build(h)), reached in a few iterations from the chord (docs/math/curve_spline.md §1).
// The iteration contracts (the length depends on h only through the end derivatives' scaling);
// it stops at rounding (1e-14 relative) or when a correction is not at most half the previous
// one, which bounds it by log2 of the chord's relative error over rounding.
template <class Build>
QuinticPiece at_own_length(double chord, const Build& build) {
  double h = chord;
  QuinticPiece q = build(h);
  double previous = std::numeric_limits<double>::infinity();
  while (true) {
    const double length = piece_length_3d(q);
    const double correction = std::fabs(length - h);
    if (!(correction <= 0.5 * previous)) break;
    h = length;
    q = build(h);
    if (correction <= 1e-14 * h) break;
    previous = correction;
  }
  return q;
}

struct Fit {
  const Problem& problem;
  CurveSplineOptions options;
  double tolerance;
  int n;
  std::vector<QuinticPiece> pieces;
  std::vector<int> joins;  // per join between consecutive pieces: 2 at a regular point, 0 at a singular one
  std::vector<int> start_continuity, end_continuity;  // per piece
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

  Checked check(const QuinticPiece& q) const {
    Checked c{q, 0, VecX()};
    for (double u : {0.25, 0.5, 0.75}) {
      VecX on_curve;
      c.measured = std::max(c.measured, deviation(q, u, &on_curve));
      if (u == 0.5) c.mid = on_curve;
    }
    return c;
  }

  // The piece in arc length s (§1).
  static QuinticPiece arc_length_piece(const HermiteEnd& a, const HermiteEnd& b) {
    return at_own_length((b.value.head<3>() - a.value.head<3>()).norm(),
                         [&](double h) { return quintic_hermite(a, b, h); });
  }

  // The piece from a singular point (its half-branch tangent known) to a regular point in the
  // parameter u in [0, 2h] with arc length s = u^2 / (4h) from the singular end (mirrored when it
  // is b). At a cusp the half-branch is analytic in sqrt(s), not in s (s^(3/2) terms), so the
  // quintic in u converges as h^3, where one in s converges as h^(3/2); in u the singular end has
  // dy/du = 0 and d2y/du2 = y_s / (2h), the regular end dy/du = y_s and d2y/du2 = y_ss ± y_s / (2h)
  // (docs/math/curve_spline.md §1). The join at the regular end is C1 (y_uu != y_ss there).
  static QuinticPiece root_piece(const HermiteEnd& a, const HermiteEnd& b, bool singular_at_a) {
    const double sign = singular_at_a ? 1.0 : -1.0;  // ds/du's sign for s measured along the piece
    return at_own_length((b.value.head<3>() - a.value.head<3>()).norm(), [&](double h) {
      HermiteEnd singular = singular_at_a ? a : b, regular = singular_at_a ? b : a;
      singular.second = sign * singular.first / (2 * h);
      singular.first.setZero();
      singular.order = 2;
      regular.second += sign * regular.first / (2 * h);
      return singular_at_a ? quintic_hermite(singular, regular, 2 * h) : quintic_hermite(regular, singular, 2 * h);
    });
  }

  void between(const Node& a, const Node& b, int depth) {
    const HermiteEnd ea = side(a, b.end.value.head<3>(), true), eb = side(b, a.end.value.head<3>(), false);
    Checked best = check(arc_length_piece(ea, eb));
    // At a singular end with a one-sided tangent (the other end regular) the piece in sqrt(s) is
    // tried too and the one measured closer kept: a cusp needs it, a node's or tacnode's smooth
    // half-branch is interpolated better in s.
    const bool singular_a = ea.order == 1 && eb.order == 2, singular_b = eb.order == 1 && ea.order == 2;
    if (singular_a || singular_b) {
      Checked root = check(root_piece(ea, eb, singular_a));
      (singular_a ? root.end_continuity : root.start_continuity) = 1;
      if (root.measured < best.measured) best = root;
    }
    const double bound = kSplineDeviationSafety * best.measured;
    if (bound <= tolerance || depth >= options.max_halvings || best.mid.size() == 0) {
      pieces.push_back(best.q);
      start_continuity.push_back(best.start_continuity);
      end_continuity.push_back(best.end_continuity);
      max_deviation = std::max(max_deviation, bound);
      return;
    }
    // Halve: the true curve point found for u = 1/2 becomes an exact point of the spline.
    const VecX mid = best.mid;
    Node m = make_node(problem, problem.wrap(mid), best.q.derivative(0.5).head<3>());
    m.end.value.tail(n) = mid;
    ++inserted;
    between(a, m, depth + 1);
    joins.push_back(m.regular ? 2 : 0);
    between(m, b, depth + 1);
  }

  // The continuity of each join: the point's, lowered where a piece in sqrt(s) meets it.
  std::vector<int> continuity() const {
    std::vector<int> c(joins);
    for (std::size_t j = 0; j < c.size(); ++j) c[j] = std::min({c[j], end_continuity[j], start_continuity[j + 1]});
    return c;
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
  SSIMARCH_EXPECTS(points.size() >= 2 && tangents.size() == points.size(),
                   "fit_curve_spline: needs >= 2 points, each with a tangent");
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
  SSIMARCH_EXPECTS(nodes.size() >= 2, "fit_curve_spline: the points coincide");
  Fit fit{problem, options, options.tolerance > 0 ? options.tolerance : 1e-9 * problem.scale(), n, {}, {}, {}, {}, 0, 0};
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    if (i > 0) fit.joins.push_back(nodes[i].regular ? 2 : 0);
    fit.between(nodes[i], nodes[i + 1], 0);
  }
  CurveSpline out;
  out.tolerance = fit.tolerance;
  out.max_deviation = fit.max_deviation;
  out.within_tolerance = fit.max_deviation <= fit.tolerance;
  out.pieces = static_cast<int>(fit.pieces.size());
  out.inserted_points = fit.inserted;
  for (const QuinticPiece& q : fit.pieces) out.length += piece_length_3d(q);
  const std::vector<int> continuity = fit.continuity();
  out.c0_knots = static_cast<int>(std::count(continuity.begin(), continuity.end(), 0));
  out.c1_knots = static_cast<int>(std::count(continuity.begin(), continuity.end(), 1));
  const bool periodic = closed && nodes.front().regular && out.c0_knots == 0 && out.c1_knots == 0;
  std::vector<int> wrapped = continuity;
  if (periodic) wrapped.push_back(2);
  else if (closed) ++out.c0_knots;  // the seam at the singular point
  const BSplineCurve clamped = bspline_from_pieces(fit.pieces, continuity, false);
  const BSplineCurve stacked = periodic ? bspline_from_pieces(fit.pieces, wrapped, true) : clamped;
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
