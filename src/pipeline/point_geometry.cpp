#include "ssimarch/pipeline/point_geometry.hpp"

#include "ssimarch/pipeline/branch_geometry.hpp"

namespace ssimarch {

PointGeometry geometry_at_point(const Problem& problem, const PointGeometryQuery& q) {
  PointGeometry r;
  r.x = project_to_curve(problem, q.at);
  if (!r.x) return r;
  GeometryContext ctx;
  const Vec3* o = q.toward ? &*q.toward : nullptr;
  // mixed at a singular point: the located point and its half-branch (pipeline/branch_geometry.hpp).
  if (q.method == GeometryMethod::kMixed) {
    const Linearization L = problem.linearize(*r.x);
    if (L.normal_first.cross(L.normal_second).norm() < GeometryTolerances{}.mixed_sin_theta)
      if (auto g = singular_branch_geometry(problem, *r.x, o, q.step)) {
        r.x = g->x;
        r.geometry = g->geometry;
        r.point = g->geometry.point;
        r.distance = (r.point - q.at).norm();
        return r;
      }
  }
  r.sampled = q.method == GeometryMethod::kEstimate || q.method == GeometryMethod::kBarnhillKersey ||
              q.method == GeometryMethod::kMixed;
  if (r.sampled) ctx = sample_context(problem, *r.x, q.step, o, 2);
  if (o) ctx.orientation = *o;
  r.geometry = evaluate_geometry(problem, *r.x, q.method, ctx);
  r.point = problem.point(*r.x);
  r.distance = (r.point - q.at).norm();
  if (r.sampled) r.samples = ctx.previous.size() + 1 + ctx.next.size();
  return r;
}

}  // namespace ssimarch
