#include "ssimarch/march/refined_arc_length.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Dense>

#include "march_steps.hpp"
#include "ssimarch/march/arc_length.hpp"
#include "ssimarch/march/tracer.hpp"

namespace ssimarch {

namespace {

// A piece's end: its point and, where the normals define one, its unit tangent, oriented along
// the curve's travel.
struct PieceEnd {
  UnknownVec x;
  Vec3 p;
  std::optional<Vec3> t;
};

struct Refinement {
  const Problem& problem;
  CorrectorOptions corrector;  // the point tolerance
  CorrectorOptions tight;      // the tightened one (kRefinementToleranceRatio)
  double allowance;            // what a piece's two levels may disagree by (model units)
  double floor;                // shortest chord that is split (model units)
  const CurveGuide& guide;
};

std::optional<Vec3> curve_tangent(const Problem& P, const UnknownVec& x, const Vec3& along) {
  const Linearization L = P.linearize(x);
  const Vec3 t = L.normal_first.cross(L.normal_second);
  if (!(t.norm() > kRefinementTangentSine)) return std::nullopt;
  return t.dot(along) < 0 ? Vec3(-t.normalized()) : Vec3(t.normalized());
}

// A listed point's tangent for the segment along `chord`, oriented as traced, where the normals'
// n1 x n2 and the listed one agree (to kRefinementTangentAgreement): the tracer's tangent is the
// normals' except where it was made otherwise, and then one of the two may be off: at a pole of a
// surface's parametrisation the normals' (0.03 rad on a rational B-spline sphere), at a landing on
// the domain's edge next to a node the predictor's (1e-3 rad in OpenCASCADE's bug32850); a piece
// with an end without a tangent is measured from its other end's and converges as it is halved.
// Where the normals give none (a singular point) the listed tangent is that of one of the point's
// half-branches, whose line is this segment's at a cusp (both half-branches leave along one ray),
// a node or a tacnode (the curve goes straight through); it is taken, along the chord, where it
// lies within kShortfallMaxTurn of the chord, as a tangent of the segment's own branch does.
std::optional<Vec3> end_tangent(const Problem& P, const CurvePoint& c, const Vec3& chord) {
  if (!(c.t.norm() > 0)) return std::nullopt;
  const Vec3 listed = c.t.normalized();
  if (const std::optional<Vec3> t = curve_tangent(P, c.x, listed)) {
    if (internal::angle_between(*t, listed) <= kRefinementTangentAgreement) return t;
    return std::nullopt;
  }
  const Vec3 t = listed.dot(chord) < 0 ? Vec3(-listed) : listed;
  if (internal::angle_between(t, chord) <= kShortfallMaxTurn) return t;
  return std::nullopt;
}

// The curve's point on the plane to the point tolerance, then to the tightened one where the
// surfaces' rounding allows (else as the first solve left it).
CorrectorResult on_plane(const Refinement& r, const UnknownVec& guess, const Vec3& normal, double offset) {
  const CorrectorResult s = solve_on_plane(r.problem, guess, normal, offset, r.corrector);
  if (s.status != CorrectorStatus::kConverged) return s;
  const CorrectorResult t = solve_on_plane(r.problem, s.x, normal, offset, r.tight);
  return t.status == CorrectorStatus::kConverged ? t : s;
}

// A listed point with its tangent (end_tangent), moved onto the curve to the tightened tolerance
// across that tangent (by at most the floor, which turns the tangent by nothing measurable); where
// that fails (a singular point, whose normals are parallel) as listed.
PieceEnd polished(const Refinement& r, const CurvePoint& c, const Vec3& chord) {
  const std::optional<Vec3> t = end_tangent(r.problem, c, chord);
  if (t) {
    const CorrectorResult s = on_plane(r, c.x, *t, t->dot(c.p));
    if (s.status == CorrectorStatus::kConverged && (r.problem.point(s.x) - c.p).norm() <= r.floor)
      return PieceEnd{r.problem.wrap(s.x), r.problem.point(s.x), t};
  }
  return PieceEnd{c.x, c.p, t};
}

// The circle through both ends tangent to the curve at each end that has a tangent (the
// circular-arc estimate; with one tangent, the arc c theta / sin theta that turns by 2 theta); the
// chord where neither has one.
double piece_estimate(const PieceEnd& a, const PieceEnd& b) {
  const Vec3 d = b.p - a.p;
  const double c = d.norm();
  if (!(c > 0)) return 0;
  if (a.t && b.t) return arc_length_estimate(a.p, *a.t, b.p, *b.t);
  if (!a.t && !b.t) return c;
  const double theta = internal::angle_between(a.t ? *a.t : *b.t, d / c);
  return theta < 1e-8 ? c : c * theta / std::sin(theta);
}

// The curve's point on the plane across the middle of the chord a -> b (the curve crosses it from
// a's side to b's, which orients its tangent); empty where the corrector fails or lands farther
// from either end than the chord (on another branch).
std::optional<PieceEnd> middle(const Refinement& r, const PieceEnd& a, const PieceEnd& b) {
  const Vec3 d = b.p - a.p;
  const double c = d.norm();
  const Vec3 n = d / c;
  UnknownVec guess = a.x + 0.5 * r.problem.difference(a.x, b.x);
  if (r.guide)
    if (const std::optional<Vec3> g = r.guide(a.p, b.p)) {
      // One Gauss-Newton step of point(x) = g with H(x) = 0: both surfaces' points moved to the
      // guide's (the point is the first surface's; H the second's difference from it, or its value).
      const Linearization L = r.problem.linearize(guess);
      const int dim = r.problem.dim();
      Eigen::MatrixXd A(3 + dim - 1, dim);
      Eigen::VectorXd rhs(3 + dim - 1);
      A.topRows(3) = L.point_jacobian;
      A.bottomRows(dim - 1) = L.jacobian;
      rhs.head(3) = *g - L.point;
      rhs.tail(dim - 1) = -L.h;
      const UnknownVec dx = A.completeOrthogonalDecomposition().solve(rhs);
      if (dx.allFinite()) guess += dx;
    }
  const CorrectorResult s = on_plane(r, guess, n, n.dot(0.5 * (a.p + b.p)));
  if (s.status != CorrectorStatus::kConverged) return std::nullopt;
  const Vec3 p = r.problem.point(s.x);
  if (!((p - a.p).norm() < c && (p - b.p).norm() < c)) return std::nullopt;
  // Off the chord by no more than an arc turning as the ends' tangents do can be (its sagitta,
  // c tan(Phi / 4) / 2 <= c Phi / 4 for Phi <= pi, doubled): a point farther out lies on a
  // neighbouring branch, which next to a cusp runs closer than the step.
  if (a.t && b.t) {
    const double off = (p - 0.5 * (a.p + b.p)).norm();
    if (!(off <= 0.5 * c * internal::angle_between(*a.t, *b.t) + r.floor)) return std::nullopt;
  }
  return PieceEnd{r.problem.wrap(s.x), p, curve_tangent(r.problem, s.x, n)};
}

// The piece a -> b whose own estimate is e0, split while its halves disagree with it by more than
// the allowance and converge: a level whose disagreement is not below kRefinementConvergence of
// its parent's is a strike, and kRefinementStrikes in a row stop (one alone is the estimates'
// approach to their asymptotic order: a parent whose estimate agreed with its halves by chance).
double refine(const Refinement& r, const PieceEnd& a, const PieceEnd& b, double e0, double parent_diff, int strikes) {
  if (!((b.p - a.p).norm() > r.floor)) return e0;
  const std::optional<PieceEnd> m = middle(r, a, b);
  if (!m) return e0;
  const double left = piece_estimate(a, *m), right = piece_estimate(*m, b);
  const double diff = std::fabs(left + right - e0);
  strikes = diff > kRefinementConvergence * parent_diff ? strikes + 1 : 0;
  if (diff <= r.allowance || strikes >= kRefinementStrikes) return left + right;
  return refine(r, a, *m, left, diff, strikes) + refine(r, *m, b, right, diff, strikes);
}

}  // namespace

std::vector<double> segment_lengths(const Problem& problem, const std::vector<CurvePoint>& points, bool closed,
                                    const CorrectorOptions& corrector, const CurveGuide& guide) {
  const std::vector<SegmentLength> s = segment_length_estimates(points, closed);
  std::vector<double> out(s.size());
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < s.size(); ++i) {
    out[i] = s[i].estimate + s[i].shortfall;
    if (s[i].error <= kSegmentLengthTolerance * s[i].estimate) continue;
    const CurvePoint &a = points[i], &b = points[(i + 1) % n];
    const Refinement r{
        problem,
        corrector,
        {kRefinementToleranceRatio * corrector.tolerance, corrector.max_iterations + kRefinementExtraIterations},
        kSegmentLengthTolerance * s[i].estimate,
        kRefinementFloorRatio * corrector.tolerance,
        guide};
    // A singular point's listed tangent is one of its half-branches', which need not point along
    // this segment (end_tangent).
    const PieceEnd pa = polished(r, a, b.p - a.p), pb = polished(r, b, b.p - a.p);
    // The points' own value is the first level: the shortfall is the part of the segment's length
    // that the circle misses, so a refinement that cannot go on keeps it.
    out[i] = refine(r, pa, pb, piece_estimate(pa, pb) + s[i].shortfall, std::numeric_limits<double>::infinity(), 0);
  }
  return out;
}

double curve_length(const Problem& problem, const std::vector<CurvePoint>& points, bool closed,
                    const CorrectorOptions& corrector, const CurveGuide& guide) {
  double sum = 0;
  for (double l : segment_lengths(problem, points, closed, corrector, guide)) sum += l;
  return sum;
}

}  // namespace ssimarch
