#include "ssimarch/problem/gauss_newton.hpp"

#include <cmath>

#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch {

std::string_view to_string(CorrectorStatus s) {
  switch (s) {
    case CorrectorStatus::kConverged: return "converged";
    case CorrectorStatus::kDiverged: return "diverged";
    case CorrectorStatus::kSingular: return "singular";
  }
  return "?";
}

ConvergenceRule::Verdict ConvergenceRule::judge(const Linearization& L, const CorrectorOptions& options,
                                                CorrectorResult* r) {
  ++r->linearizations;
  ++r->evaluations[0];
  ++r->evaluations[1];
  r->distance = L.distance;
  if (!std::isfinite(L.distance)) return Verdict::kDiverging;
  if (L.distance <= options.tolerance) {
    r->status = CorrectorStatus::kConverged;
    r->point = L.point;
    return Verdict::kConverged;
  }
  growth_ = L.distance > previous_ ? growth_ + 1 : 0;
  if (growth_ >= 2) return Verdict::kDiverging;
  previous_ = L.distance;
  return Verdict::kContinue;
}

CorrectorResult gauss_newton(const Problem& problem, const UnknownVec& guess, const CorrectorOptions& options) {
  CorrectorResult r;
  r.x = guess;
  Linearization L = problem.linearize(r.x);
  ++r.linearizations;
  r.evaluations = {1, 1};
  ConvergenceRule rule(L.distance);
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (!L.h.allFinite() || !L.jacobian.allFinite()) {
      r.status = CorrectorStatus::kDiverged;
      r.distance = L.distance;
      return r;
    }
    const Eigen::JacobiSVD<EquationJacobian> svd(L.jacobian, Eigen::ComputeThinU | Eigen::ComputeThinV);
    // One equation: the ratio needs the point Jacobian's SVD; more: the one just computed.
    const double rank = L.jacobian.rows() == 1 ? Problem::rank_ratio(L) : Problem::rank_ratio(svd.singularValues());
    if (rank <= kNewtonRankRatio) {
      r.status = CorrectorStatus::kSingular;
      r.distance = L.distance;
      return r;
    }
    r.x -= svd.solve(L.h);
    r.iterations = it;
    L = problem.linearize(r.x);
    const ConvergenceRule::Verdict v = rule.judge(L, options, &r);
    if (v == ConvergenceRule::Verdict::kConverged) return r;
    if (v == ConvergenceRule::Verdict::kDiverging) break;
  }
  r.status = CorrectorStatus::kDiverged;
  return r;
}

CorrectorResult solve_with_fixed_unknown(const Problem& problem, const UnknownVec& guess, int i, double value,
                                         const CorrectorOptions& options) {
  CorrectorResult r;
  r.x = guess;
  r.x[i] = value;
  const int n = problem.dim();
  for (int it = 1; it <= options.max_iterations; ++it) {
    Linearization L = problem.linearize(r.x);
    ++r.linearizations;
    ++r.evaluations[0];
    ++r.evaluations[1];
    r.distance = L.distance;
    if (!L.h.allFinite() || !L.jacobian.allFinite()) break;
    if (L.distance <= options.tolerance && it > 1) {
      r.status = CorrectorStatus::kConverged;
      return r;
    }
    UnknownMat A(n, n);
    A.topRows(n - 1) = L.jacobian;
    A.row(n - 1).setZero();
    A(n - 1, i) = 1.0;
    UnknownVec rhs(n);
    rhs.head(n - 1) = L.h;
    rhs[n - 1] = r.x[i] - value;
    const Eigen::FullPivLU<UnknownMat> lu(A);
    if (!lu.isInvertible()) {
      r.status = CorrectorStatus::kSingular;
      return r;
    }
    r.x -= lu.solve(rhs);
    r.iterations = it;
  }
  Linearization L = problem.linearize(r.x);
  ++r.linearizations;
  ++r.evaluations[0];
  ++r.evaluations[1];
  r.distance = L.distance;
  r.status = L.distance <= options.tolerance ? CorrectorStatus::kConverged : CorrectorStatus::kDiverged;
  return r;
}

}  // namespace ssimarch
