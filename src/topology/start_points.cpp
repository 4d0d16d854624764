#include "ssimarch/topology/start_points.hpp"

#include <algorithm>
#include <functional>
#include <limits>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

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

// Pairs each sample of F with the nearest sample of G.
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
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double u = sample(B[0], i, n), v = sample(B[1], j, n);
      Vec3T<double> f = P.first().point(u, v);
      Vec3 fp(f.x, f.y, f.z);
      std::size_t best = 0;
      double bd = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < gp.size(); ++k) {
        double d = (gp[k] - fp).squaredNorm();
        if (d < bd) {
          bd = d;
          best = k;
        }
      }
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
  if (!(Problem::rank_ratio(P.linearize(x)) < kSuspectSingularRankRatio)) return x;
  auto y = regular_point_near(P, x, 0.5 * tracer.options().step_length, tracer.options().tolerance);
  if (!y) return x;
  warnings->push_back("start point " + describe_point(P.point(x)) + " is a singular point of the curve; tracing from the regular point " +
                      describe_point(P.point(*y)) + " next to it");
  return *y;
}

}  // namespace ssimarch
