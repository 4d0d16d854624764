#include "ssimarch/singular/detection.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>

#include "ssimarch/core/error.hpp"

namespace ssimarch {

Vec3 oriented_tangent(const Problem& problem, const VecX& x) {
  const Linearization L = problem.linearize(x);
  const int n = problem.dim();
  VecX v(n);
  // v_j = (-1)^j det(J without column j): J v = 0 (Laplace expansion of [J; e_j]).
  for (int j = 0; j < n; ++j) {
    MatX minor(n - 1, n - 1);
    for (int c = 0, k = 0; c < n; ++c)
      if (c != j) minor.col(k++) = L.jacobian.col(c);
    v[j] = ((j % 2) ? -1.0 : 1.0) * minor.determinant();
  }
  return L.point_jacobian * v;
}

StepSignals step_signals(const Problem& problem, const VecX& a, const VecX& b, const DetectionThresholds& thresholds) {
  StepSignals s;
  const Linearization La = problem.linearize(a), Lb = problem.linearize(b);
  s.sine_a = La.normal_first.cross(La.normal_second).norm();
  s.sine_b = Lb.normal_first.cross(Lb.normal_second).norm();
  s.rank_a = Problem::rank_ratio(La);
  s.rank_b = Problem::rank_ratio(Lb);
  const Vec3 ta = oriented_tangent(problem, a), tb = oriented_tangent(problem, b);
  const double na = ta.norm(), nb = tb.norm();
  s.tangent_cos = (na > 0 && nb > 0) ? ta.dot(tb) / (na * nb) : 0.0;
  s.flipped = s.tangent_cos < 0;
  s.near_singular = std::min(s.sine_a, s.sine_b) < thresholds.sine || std::min(s.rank_a, s.rank_b) < thresholds.rank_ratio;
  return s;
}

namespace {

// The Newton step towards a critical point of h = g(F(u,v)) from (u, v) (second-order jet).
bool newton_to_critical_point(const Problem& problem, const Vec2& z, Vec2* step) {
  using J = Jet<2, 2>;
  const Vec3T<J> F = problem.first().point(J::variable(0, z[0]), J::variable(1, z[1]));
  const J g = problem.second().value(F);
  if (!is_finite(g)) return false;
  Eigen::Matrix2d H;
  H << g.derivative({2, 0}), g.derivative({1, 1}), g.derivative({1, 1}), g.derivative({0, 2});
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix2d> cod(H);
  *step = -cod.solve(Vec2(g.d(0), g.d(1)));
  return step->allFinite();
}

}  // namespace

std::vector<SingularLocation> hunt_singular_points(const Problem& problem, const HuntOptions& options) {
  if (problem.kind() != PairKind::kParametricImplicit)
    throw InputError("hunt_singular_points", "implemented for parametric-implicit pairs only");
  if (options.grid < 3) throw InputError("hunt_singular_points.grid", "needs at least 3 samples per direction");
  const auto& B = problem.bounds();
  const int n = options.grid;
  auto at = [&](int i, int j) {
    return Vec2(B[0].lo + B[0].width() * i / (n - 1), B[1].lo + B[1].width() * j / (n - 1));
  };
  std::vector<SingularLocation> found;
  const Vec2 spacing(B[0].width() / (n - 1), B[1].width() / (n - 1));
  // Starts: grid points whose Newton step for grad h = 0 stays within one cell (every critical
  // point of h, the singular points among them, attracts the grid points around it).
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Vec2 step;
      if (!newton_to_critical_point(problem, at(i, j), &step)) continue;
      if (std::fabs(step[0]) > spacing[0] || std::fabs(step[1]) > spacing[1]) continue;
      VecX x(2);
      x << at(i, j)[0] + step[0], at(i, j)[1] + step[1];
      bool known = false;
      for (const auto& f : found) known = known || problem.difference(f.x, x).norm() <= 1e-3 * spacing.norm();
      if (known) continue;
      SingularLocation s = locate_singular_point(problem, x, options.locate);
      if (s.status != LocateStatus::kConverged || !problem.inside(s.x, 1e-9)) continue;
      known = false;
      for (const auto& f : found) known = known || problem.difference(f.x, s.x).norm() <= options.merge_distance;
      if (!known) found.push_back(s);
    }
  return found;
}

}  // namespace ssimarch
