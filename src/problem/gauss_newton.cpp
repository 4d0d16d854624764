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

namespace {

double side_residual(const SideCondition& side, const Linearization& L, const UnknownVec& x) {
  return side.kind == SideCondition::Kind::kPlane ? side.normal.dot(L.point) - side.value
                                                  : x[side.unknown] - side.value;
}

bool side_satisfied(const SideCondition& side, const Linearization& L, double tolerance) {
  return side.kind == SideCondition::Kind::kFixedUnknown ||
         std::fabs(side.normal.dot(L.point) - side.value) <= tolerance;
}

}  // namespace

CorrectorResult constrained_newton(const Problem& problem, const UnknownVec& guess, const SideCondition& side,
                                   const CorrectorOptions& options, bool polish) {
  CorrectorResult r;
  r.x = guess;
  const int n = problem.dim();
  bool polishing = false;
  for (int it = 1; it <= options.max_iterations + 1 + (polish ? 1 : 0); ++it) {
    const Linearization L = problem.linearize(r.x);
    ++r.linearizations;
    ++r.evaluations[0];
    ++r.evaluations[1];
    r.distance = L.distance;
    if (!L.h.allFinite() || !L.jacobian.allFinite()) break;
    if (it > 1 && L.distance <= options.tolerance && side_satisfied(side, L, options.tolerance)) {
      if (!polish || polishing) {
        r.status = CorrectorStatus::kConverged;
        return r;
      }
      polishing = true;
    } else if (it > options.max_iterations) {
      break;
    }
    UnknownMat A(n, n);
    A.topRows(n - 1) = L.jacobian;
    if (side.kind == SideCondition::Kind::kPlane) {
      A.row(n - 1) = (L.point_jacobian.transpose() * side.normal).transpose();
    } else {
      A.row(n - 1).setZero();
      A(n - 1, side.unknown) = 1.0;
    }
    UnknownVec rhs(n);
    rhs.head(n - 1) = L.h;
    rhs[n - 1] = side_residual(side, L, r.x);
    const Eigen::FullPivLU<UnknownMat> lu(A);
    if (!lu.isInvertible()) {
      r.status = CorrectorStatus::kSingular;
      return r;
    }
    r.x -= lu.solve(rhs);
    r.iterations = it;
  }
  r.status = CorrectorStatus::kDiverged;
  return r;
}

CorrectorResult solve_with_fixed_unknown(const Problem& problem, const UnknownVec& guess, int i, double value,
                                         const CorrectorOptions& options) {
  UnknownVec start = guess;
  start[i] = value;
  return constrained_newton(problem, start, SideCondition::fixed_unknown(i, value), options);
}

CorrectorResult solve_on_plane(const Problem& problem, const UnknownVec& guess, const Vec3& normal, double offset,
                               const CorrectorOptions& options) {
  return constrained_newton(problem, guess, SideCondition::plane(normal, offset), options, /*polish=*/true);
}

}  // namespace ssimarch
