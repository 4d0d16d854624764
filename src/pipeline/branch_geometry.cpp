#include "ssimarch/pipeline/branch_geometry.hpp"

#include <limits>

#include "ssimarch/singular/analysis.hpp"

namespace ssimarch {

namespace {

// t, n, b, kappa, tau, kappa' of the smooth half-branch b: X -> P(X d + W(X) n), W = sum b_j X^j.
CurveGeometry smooth_branch(const LocalCurve& curve, const HalfBranch& b) {
  using T = Taylor<kLocalOrder>;
  const Vec2 d = b.tangent, nrm(-d[1], d[0]);
  T W(0.0);
  for (const PuiseuxTerm& term : b.chart_expansion.terms) W[static_cast<int>(std::lround(term.exponent))] = term.coefficient;
  const T X = T::variable(0, 0.0);
  const std::array<T, 2> st = {d[0] * X + nrm[0] * W, d[1] * X + nrm[1] * W};
  Vec3 c[3];
  for (int k = 0; k < 3; ++k) {
    const T p = compose<2, 1, kLocalOrder>(curve.point[static_cast<std::size_t>(k)], st);
    c[0][k] = p[1], c[1][k] = 2 * p[2], c[2][k] = 6 * p[3];
  }
  return frenet_from_derivatives(c[0], c[1], c[2]);
}

}  // namespace

std::optional<BranchGeometry> singular_branch_geometry(const Problem& problem, const VecX& x, const Vec3* toward,
                                                       double reach) {
  SingularAnalysisOptions options;
  options.half_branches = false;  // after the reach test
  SingularAnalysis a = analyse_singular_point(problem, x, options);
  const SingularLocation& s = a.location;
  if (s.status != LocateStatus::kConverged || (s.point - problem.point(x)).norm() > reach || !a.analysed())
    return std::nullopt;
  with_half_branches(problem, &a);
  const LocalCurve& curve = a.curve;
  const std::vector<HalfBranch>& branches = a.branches;
  if (branches.empty()) return std::nullopt;
  const HalfBranch* best = &branches.front();
  double best_cos = -std::numeric_limits<double>::infinity();
  for (const HalfBranch& b : branches) {
    const double c = toward ? b.tangent_3d.dot(toward->normalized()) : 0.0;
    if (c > best_cos) best_cos = c, best = &b;
  }
  BranchGeometry out;
  out.x = s.x;
  // A smooth branch needs its offset through X^3 for t, n, b, kappa, tau and kappa'.
  const bool smooth = best->chart_expansion.denominator == 1 && best->chart_expansion.max_exponent >= 3;
  if (smooth) {
    out.geometry = smooth_branch(curve, *best);
  } else {
    out.geometry.status = GeometryStatus::kSingular;
    out.geometry.t = best->tangent_3d;
    out.geometry.kappa = std::numeric_limits<double>::infinity();
  }
  const Linearization L = problem.linearize(s.x);
  out.geometry.point = s.point;
  out.geometry.theta = normal_angle(L.normal_first, L.normal_second);
  return out;
}

}  // namespace ssimarch
