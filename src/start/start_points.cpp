#include "ssimarch/start/start_points.hpp"

#include <algorithm>
#include <functional>
#include <limits>

#include "ssimarch/march/pole_passage.hpp"
#include "ssimarch/march/trim_landing.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/locate.hpp"
#include "ssimarch/start/start_tolerances.hpp"
#include "ssimarch/start/nearest_point_tree.hpp"

namespace ssimarch {

namespace {

using Consider = std::function<void(const VecX&)>;

double sample(const Interval& iv, int i, int count) { return iv.lo + iv.width() * (i + 0.5) / count; }

using Bounds = std::vector<Interval>;

void sample_parametric_implicit(const Bounds& B, int n, const Consider& consider) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      VecX x(2);
      x << sample(B[0], i, n), sample(B[1], j, n);
      consider(x);
    }
}

void sample_implicit_implicit(const Bounds& B, int n, const Consider& consider) {
  const int m = std::min(n, 16);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        VecX x(3);
        x << sample(B[0], i, m), sample(B[1], j, m), sample(B[2], k, m);
        consider(x);
      }
}

// Pairs each sample of F with the nearest sample of G: n^2 corrector runs and n^2 nearest-neighbour
// queries of O(log n) each (a k-d tree; the scan it replaces made start_samples = 300 cost 8e9
// distances). docs/marching.md states the cost.
void sample_parametric_parametric(const Problem& P, const Bounds& B, int n, const Consider& consider) {
  std::vector<Vec3> gp;
  std::vector<Vec2> guv;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double p = sample(B[2], i, n), q = sample(B[3], j, n);
      Vec3T<double> g = P.second().point(p, q);
      gp.emplace_back(g.x, g.y, g.z);
      guv.emplace_back(p, q);
    }
  const internal::NearestPointTree tree(std::move(gp));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double u = sample(B[0], i, n), v = sample(B[1], j, n);
      Vec3T<double> f = P.first().point(u, v);
      const std::size_t best = tree.nearest(Vec3(f.x, f.y, f.z));
      VecX x(4);
      x << u, v, guv[best][0], guv[best][1];
      consider(x);
    }
}

}  // namespace

std::vector<VecX> find_start_points(const Tracer& tracer, TraceStats* stats) {
  return find_start_points_in(tracer, tracer.problem().bounds(), tracer.options().start_samples, stats);
}

std::vector<VecX> find_start_points_in(const Tracer& tracer, const std::vector<Interval>& box, int samples,
                                       TraceStats* stats) {
  const Problem& P = tracer.problem();
  const CorrectorOptions co{tracer.options().tolerance, 20};
  std::vector<VecX> found;
  std::vector<Vec3> found_points;
  const double separation = 0.5 * tracer.spacing();
  const Consider consider = [&](const VecX& guess) {
    CorrectorResult r = gauss_newton(P, guess, co);
    stats->linearizations += r.linearizations;
    stats->add_surface_evaluations(r.evaluations);
    if (r.status != CorrectorStatus::kConverged || !P.inside(r.x)) return;
    Vec3 p = P.point(r.x);
    for (const Vec3& q : found_points)
      if ((q - p).norm() < separation) return;
    found.push_back(r.x);
    found_points.push_back(p);
  };
  const int n = samples;
  switch (P.kind()) {
    case PairKind::kParametricImplicit: sample_parametric_implicit(box, n, consider); break;
    case PairKind::kImplicitImplicit: sample_implicit_implicit(box, n, consider); break;
    case PairKind::kParametricParametric: sample_parametric_parametric(P, box, n, consider); break;
  }
  return found;
}

std::vector<VecX> start_points_near(const Tracer& tracer, const std::vector<Vec3>& points, TraceStats* stats,
                                    std::vector<std::string>* warnings, int* failed) {
  const Problem& P = tracer.problem();
  const CorrectorOptions co{tracer.options().tolerance, 30};
  std::vector<VecX> seeds;
  for (const Vec3& X : points) {
    auto x = unknowns_near(P, X);
    CorrectorResult r;
    if (x) {
      r = gauss_newton(P, *x, co);
      stats->linearizations += r.linearizations;
      stats->add_surface_evaluations(r.evaluations);
      // A start given on a singular point of the curve (a cusp, a node: the Jacobian drops rank,
      // so Gauss-Newton refuses to step) that is already on the curve within the tolerance is a
      // start: regular_start and trace_all's singular-start registration take it from there.
      if (r.status == CorrectorStatus::kSingular && P.linearize(*x).distance <= co.tolerance) {
        r.status = CorrectorStatus::kConverged;
        r.x = *x;
      }
    }
    if (!x || r.status != CorrectorStatus::kConverged) {
      ++*failed;
      warnings->push_back("start point " + describe_point(X) + " could not be moved onto the intersection (corrector " +
                          std::string(x ? to_string(r.status) : "had no initial guess") + ")");
      continue;
    }
    seeds.push_back(r.x);
  }
  return seeds;
}

VecX regular_start(const Tracer& tracer, const VecX& x, std::vector<std::string>* warnings) {
  const Problem& P = tracer.problem();
  const CorrectorOptions co{tracer.options().tolerance, tracer.options().max_corrector_iterations};
  // A boundary root beyond a trim stands for the curve's crossing of the trim's face.
  const std::optional<UnknownVec> trimmed = onto_trims(P, x, co);
  if (!trimmed) return x;
  if (*trimmed != x) return VecX(*trimmed);
  // A start on a degenerate edge (a pole) has no tangent in its parameters: start from the
  // curve point next to it in the pole's chart (march/pole_passage.hpp).
  const std::vector<Pole> poles = problem_poles(P);
  if (const Pole* pole = pole_at(poles, x, 1e-9))
    if (auto y = leave_pole(P, *pole, x, 0.5 * tracer.options().step_length, co)) return y->x;
  if (!(Problem::rank_ratio(P.linearize(x)) < kSuspectSingularRankRatio)) return x;
  // A low rank ratio says "near a singular point" only up to the point's order (it falls like
  // d^3 at a quadruple point); the start is on one only within singular_start_radius of it.
  const SingularLocation s = locate_singular_point(P, x);
  if (s.status == LocateStatus::kConverged &&
      (s.point - P.point(x)).norm() > singular_start_radius(tracer.options().tolerance, P.scale()))
    return x;
  auto y = regular_point_near(P, x, 0.5 * tracer.options().step_length, tracer.options().tolerance);
  if (!y) return x;
  if (warnings)
    warnings->push_back("start point " + describe_point(P.point(x)) +
                        " is a singular point of the curve; tracing from the regular point " +
                        describe_point(P.point(*y)) + " next to it");
  return *y;
}

}  // namespace ssimarch
