#include "ssimarch/problem/closest_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/problem/gauss_newton.hpp"

namespace ssimarch {

namespace {

using J2 = Jet<2, 1>;

Vec2 clamp_to_domain(const ParamDomain& d, Vec2 uv) {
  auto fix = [](double x, const Interval& i, bool periodic) {
    if (periodic) {
      double P = i.hi - i.lo;
      return i.lo + (x - i.lo) - P * std::floor((x - i.lo) / P);
    }
    return std::clamp(x, i.lo, i.hi);
  };
  return {fix(uv[0], d.u, d.periodic_u), fix(uv[1], d.v, d.periodic_v)};
}

}  // namespace

Vec2 refine_closest_parameters(const Surface& surface, const Vec3& X, Vec2 uv) {
  const ParamDomain& d = surface.domain();
  // Gauss-Newton on r(u,v) = F(u,v) - X: bounded number of iterations, stops when the update
  // is below 1e-15 of the domain size. The step is halved until |r| decreases (the Gauss-Newton
  // direction descends |r|^2): undamped, it overshoots where X is far compared with the
  // surface's radius of curvature (a point 0.16 from a cylinder of radius 0.05 went to the far
  // side, a stationary point 0.25 away, from a grid point on the near side).
  const double still = 1e-15 * (1 + d.u.width() + d.v.width());
  auto distance2 = [&](const Vec2& w) {
    const Vec3T<double> p = surface.point(w[0], w[1]);
    return (Vec3(p.x, p.y, p.z) - X).squaredNorm();
  };
  for (int it = 0; it < 50; ++it) {
    Vec3T<J2> f = surface.point(J2::variable(0, uv[0]), J2::variable(1, uv[1]));
    Eigen::Matrix<double, 3, 2> A;
    Vec3 r;
    for (int i = 0; i < 3; ++i) {
      r[i] = f[i].value() - X[i];
      A(i, 0) = f[i].d(0);
      A(i, 1) = f[i].d(1);
    }
    if (!A.allFinite() || !r.allFinite()) break;
    Vec2 step = A.completeOrthogonalDecomposition().solve(-r);
    if (!step.allFinite()) break;
    Vec2 next = clamp_to_domain(d, uv + step);
    double next2 = distance2(next);
    while (!(next2 < r.squaredNorm()) && step.norm() > still) {
      step /= 2;
      next = clamp_to_domain(d, uv + step);
      next2 = distance2(next);
    }
    double moved = (next - uv).norm();
    if (!(next2 <= r.squaredNorm())) break;  // no step decreases |r|: a local minimum
    uv = next;
    if (moved <= still) break;
  }
  return uv;
}

std::optional<Vec2> closest_parameters(const Surface& surface, const Vec3& X, int grid) {
  const ParamDomain& d = surface.domain();
  double best = std::numeric_limits<double>::infinity();
  Vec2 best_uv;
  for (int i = 0; i <= grid; ++i)
    for (int j = 0; j <= grid; ++j) {
      double u = d.u.lo + d.u.width() * i / grid, v = d.v.lo + d.v.width() * j / grid;
      Vec3T<double> p = surface.point(u, v);
      double dist = (Vec3(p.x, p.y, p.z) - X).squaredNorm();
      if (dist < best) {
        best = dist;
        best_uv = {u, v};
      }
    }
  if (!std::isfinite(best)) return std::nullopt;
  return refine_closest_parameters(surface, X, best_uv);
}

std::optional<VecX> unknowns_near(const Problem& problem, const Vec3& X) {
  VecX x(problem.dim());
  switch (problem.kind()) {
    case PairKind::kImplicitImplicit:
      x = X;
      return x;
    case PairKind::kParametricImplicit: {
      auto uv = closest_parameters(problem.first(), X);
      if (!uv) return std::nullopt;
      x << (*uv)[0], (*uv)[1];
      return x;
    }
    case PairKind::kParametricParametric: {
      auto a = closest_parameters(problem.first(), X);
      auto b = closest_parameters(problem.second(), X);
      if (!a || !b) return std::nullopt;
      x << (*a)[0], (*a)[1], (*b)[0], (*b)[1];
      return x;
    }
  }
  return std::nullopt;
}

std::optional<VecX> regular_point_near(const Problem& problem, const VecX& x, double distance, double tolerance,
                                       double min_rank_ratio) {
  const Vec3 p0 = problem.point(x);
  Linearization L0 = problem.linearize(x);
  const CorrectorOptions co{tolerance, 30};
  // Directions: each unknown alone, then each pair of unknowns with both relative signs (at a
  // node of a parametric-implicit pair, the coordinate lines through it may meet the curve
  // only at the node itself).
  const int n = problem.dim();
  std::vector<VecX> directions;
  for (int i = 0; i < n; ++i) directions.push_back(VecX::Unit(n, i));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (double s : {1.0, -1.0}) directions.push_back(VecX::Unit(n, i) + s * VecX::Unit(n, j));
  for (const VecX& dir : directions) {
    double speed = (L0.point_jacobian * dir).norm();
    if (!(speed > 0)) continue;
    for (double sign : {1.0, -1.0}) {
      VecX guess = x + (sign * distance / speed) * dir;
      CorrectorResult r = gauss_newton(problem, guess, co);
      if (r.status != CorrectorStatus::kConverged || !problem.inside(r.x)) continue;
      double d = (problem.point(r.x) - p0).norm();
      if (d < 0.1 * distance || d > 3 * distance) continue;
      if (Problem::rank_ratio(problem.linearize(r.x)) >= min_rank_ratio) return r.x;
    }
  }
  return std::nullopt;
}

}  // namespace ssimarch
