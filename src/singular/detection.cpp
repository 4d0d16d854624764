#include "ssimarch/singular/detection.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <optional>
#include <utility>

#include "ssimarch/core/error.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"
#include "ssimarch/singular/analysis.hpp"

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

// A start of the hunt and the 3D size of its grid cell.
struct GridStart {
  VecX x;
  double cell = 0;
};

// Starting unknowns spread over the box B of the unknowns: a grid over the first surface's
// parameters (the second surface's nearest parameters added for parametric-parametric pairs) or
// over the 3D box. A start's cell is the larger image of one grid step at the start itself, at
// least the image at the middle of the box: a surface's metric varies over its domain (a torus's
// outer equator is (R + r) / (R - r) times its inner one), and a node attracts the starts of its
// own cells, not of the middle's.
std::vector<GridStart> grid_starts(const Problem& problem, const std::vector<Interval>& B, int n) {
  std::vector<GridStart> starts;
  auto lerp = [&](int k, int i) { return B[static_cast<std::size_t>(k)].lo + B[static_cast<std::size_t>(k)].width() * i / (n - 1); };
  if (problem.kind() == PairKind::kImplicitImplicit) {
    const int m = std::max(3, n / 2);  // n^3 would be wasteful: the local curve reaches far
    const double cell = Vec3(B[0].width(), B[1].width(), B[2].width()).norm() / (m - 1);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        for (int k = 0; k < m; ++k) {
          VecX x(3);
          x << B[0].lo + B[0].width() * i / (m - 1), B[1].lo + B[1].width() * j / (m - 1), B[2].lo + B[2].width() * k / (m - 1);
          starts.push_back({x, cell});
        }
    return starts;
  }
  // The 3D size of one grid step at (u, v).
  auto cell_at = [&](double u, double v) {
    using J = Jet<2, 1>;
    const Vec3T<J> F = problem.first().point(J::variable(0, u), J::variable(1, v));
    const Vec3 Fu(F.x.d(0), F.y.d(0), F.z.d(0)), Fv(F.x.d(1), F.y.d(1), F.z.d(1));
    return std::max(Fu.norm() * B[0].width(), Fv.norm() * B[1].width()) / (n - 1);
  };
  const double middle = cell_at(lerp(0, n / 2), lerp(1, n / 2));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = lerp(0, i), v = lerp(1, j);
      VecX x(problem.dim());
      if (problem.kind() == PairKind::kParametricImplicit) {
        x << u, v;
      } else {
        const Vec3T<double> P = problem.first().point(u, v);
        auto pq = closest_parameters(problem.second(), Vec3(P.x, P.y, P.z));
        if (!pq) continue;
        x << u, v, (*pq)[0], (*pq)[1];
      }
      const double here = cell_at(u, v);
      starts.push_back({x, std::isfinite(here) ? std::max(here, middle) : middle});
    }
  return starts;
}

// The start's Newton target: where Newton's step on grad h = 0 leads from x0, if the surfaces
// come within a cell there and the step stays within about one cell (every critical point of h
// attracts the grid points around it).
std::optional<VecX> newton_target(const Problem& problem, const VecX& x0, double cell, double max_sine) {
  const Linearization L0 = problem.linearize(x0);
  if (!(L0.distance <= cell) || L0.normal_first.cross(L0.normal_second).norm() > max_sine) return std::nullopt;
  const LocalCurve c = local_curve(problem, x0);
  if (c.status != LocalCurveStatus::kOk) return std::nullopt;
  const LocalValue v = evaluate(c.h, Vec2::Zero());
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix2d> cod(v.hessian);
  const Vec2 step = -cod.solve(v.gradient);
  if (!step.allFinite() || step.norm() > cell) return std::nullopt;
  return c.unknowns_at(step);
}

bool near_any(const std::vector<Vec3>& points, const Vec3& p, double r) {
  for (const Vec3& q : points)
    if ((q - p).norm() <= r) return true;
  return false;
}

// Whether s is a point found before: within the merge distance of one, or within the resolution
// radius of the more degenerate of the two (resolution_radius: a location that stopped short of
// it), which then stands for both.
// `resolution` holds each found point's (resolution radius, Milnor number).
bool known_or_replaced(const Problem& problem, const SingularLocation& s, double merge,
                       std::vector<SingularLocation>* found, std::vector<std::pair<double, int>>* resolution) {
  for (const SingularLocation& f : *found)
    if (problem.difference(f.x, s.x).norm() <= merge) return true;
  SingularAnalysisOptions without_branches;
  without_branches.half_branches = false;
  const SingularAnalysis a = analyse_singular_point(problem, s, without_branches);
  const std::pair<double, int> mine{resolution_radius(a), a.kind.milnor};
  for (std::size_t i = 0; i < found->size(); ++i) {
    auto& [radius, milnor] = (*resolution)[i];
    if (((*found)[i].point - s.point).norm() > std::max(radius, mine.first)) continue;
    if (mine.second > milnor) (*found)[i] = s, radius = mine.first, milnor = mine.second;
    return true;
  }
  resolution->push_back(mine);
  return false;
}

}  // namespace

std::vector<SingularLocation> hunt_singular_points(const Problem& problem, const HuntOptions& options) {
  if (options.grid < 3) throw InputError("hunt_singular_points.grid", "needs at least 3 samples per direction");
  if (options.region_grid < 2) throw InputError("hunt_singular_points.region_grid", "needs at least 2 samples per direction");
  const std::vector<std::vector<Interval>> boxes = options.regions.empty() ? std::vector<std::vector<Interval>>{problem.bounds()} : options.regions;
  std::vector<SingularLocation> found;
  std::vector<std::pair<double, int>> resolution;  // per found point (known_or_replaced)
  std::vector<Vec3> located;  // every point a location ended at, singular or not
  for (const auto& box : boxes) {
    const int n = options.regions.empty() ? options.grid : options.region_grid;
    for (const auto& [x0, cell] : grid_starts(problem, box, n)) {
      if (options.regions.empty() && options.consider && !options.consider(x0)) continue;
      if (options.holds_none) {
        VecX step(static_cast<Eigen::Index>(box.size()));
        for (std::size_t k = 0; k < box.size(); ++k) step[static_cast<Eigen::Index>(k)] = box[k].width() / (n - 1);
        if (options.holds_none(x0, step)) continue;
      }
      // A box narrower than the grid of the whole domain still admits starts a domain cell away.
      const double reach = options.regions.empty() ? cell : std::max(cell, 1e-3 * problem.scale());
      const std::optional<VecX> x = newton_target(problem, x0, reach, options.max_sine);
      if (!x) continue;
      const Vec3 p = problem.point(*x);
      if (near_any(located, p, 0.1 * reach) || (options.skip && options.skip(p))) continue;
      SingularLocation s = locate_singular_point(problem, *x, options.locate);
      if (s.status == LocateStatus::kFailed) continue;
      located.push_back(s.point);
      if (s.status != LocateStatus::kConverged || !problem.inside(s.x, 1e-9)) continue;
      if (!known_or_replaced(problem, s, options.merge_distance, &found, &resolution)) {
        found.push_back(s);
        if (options.on_found) options.on_found(s);
      }
    }
  }
  return found;
}

std::vector<SingularLocation> singular_points_at_poles(const Problem& problem, const LocateOptions& options) {
  std::vector<SingularLocation> found;
  const double tol = 1e-9 * problem.scale();
  for (const Pole& pole : problem_poles(problem)) {
    std::optional<VecX> x = unknowns_near(problem, pole.point);
    if (!x) continue;
    (*x)[pole.unknown] = pole.value;  // on the edge itself
    if (!(problem.linearize(*x).distance <= tol)) continue;  // the pole is not on the other surface
    const SingularLocation s = locate_singular_point(problem, *x, options);
    if (s.status != LocateStatus::kConverged || !problem.inside(s.x, 1e-9)) continue;
    bool known = false;
    for (const auto& f : found) known = known || (f.point - s.point).norm() <= tol;
    if (!known) found.push_back(s);
  }
  return found;
}

}  // namespace ssimarch
