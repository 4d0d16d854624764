#include "ssimarch/pipeline/point_geometry.hpp"

namespace ssimarch {

PointGeometry geometry_at_point(const Problem& problem, const PointGeometryQuery& q) {
  PointGeometry r;
  r.x = geometry::project_to_curve(problem, q.at);
  if (!r.x) return r;
  geometry::GeometryContext ctx;
  const Vec3* o = q.toward ? &*q.toward : nullptr;
  r.sampled = q.method == geometry::GeometryMethod::kEstimate || q.method == geometry::GeometryMethod::kBarnhillKersey ||
              q.method == geometry::GeometryMethod::kMixed;
  if (r.sampled) ctx = geometry::sample_context(problem, *r.x, q.step, o, 2);
  if (o) ctx.orientation = *o;
  r.geometry = geometry::evaluate_geometry(problem, *r.x, q.method, ctx);
  r.point = problem.point(*r.x);
  r.distance = (r.point - q.at).norm();
  if (r.sampled) r.samples = ctx.previous.size() + 1 + ctx.next.size();
  return r;
}

}  // namespace ssimarch
