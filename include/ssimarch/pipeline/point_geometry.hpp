// The entry point of `ssimarch curve-geometry`: the differential geometry of an intersection
// curve at the curve point nearest to a given 3D point (docs/geometry.md).
#pragma once

#include <cstddef>
#include <optional>

#include "ssimarch/geometry/intersection_geometry.hpp"

namespace ssimarch {

struct PointGeometryQuery {
  Vec3 at;                                // a point near the curve
  GeometryMethod method = GeometryMethod::kExact;
  double step = 0.01;                     // chord between the samples of the estimate methods (model units)
  std::optional<Vec3> toward;             // orient t so that t . toward >= 0
};

struct PointGeometry {
  std::optional<VecX> x;                  // the curve point's unknowns; empty when Newton did not reach the curve
  Vec3 point = Vec3::Zero();              // problem.point(*x)
  double distance = 0;                    // |point - at|
  CurveGeometry geometry;
  bool sampled = false;                   // the method used samples along the curve
  std::size_t samples = 0;                // how many (the point included), when sampled
};

/// Projects query.at onto the curve and evaluates the geometry there by query.method.
PointGeometry geometry_at_point(const Problem& problem, const PointGeometryQuery& query);

}  // namespace ssimarch
