// Degenerate edges of a parametric form: edges of the parameter rectangle that F maps to one
// point (the poles v = +-pi/2 of a sphere, the apex edge of a cone whose range ends at 0, a
// Bezier or B-spline patch whose whole edge row of control points coincides, as in the exact
// rational spheres). F_w = 0 along such an edge, so no curve point there has a (u,v) tangent:
// the tracer passes a curve through the point in a local chart (docs/math/poles.md).
#pragma once

#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// One degenerate edge: the parameter that is constant on it (0 = u, 1 = v), the constant
/// (its bound), whether it is the upper bound, and the one point the edge maps to.
struct DegenerateEdge {
  int parameter = 0;
  double value = 0;
  bool upper = false;
  Vec3 point = Vec3::Zero();
};

/// The degenerate edges of a parametric surface: each non-periodic edge whose 33 equally spaced
/// samples all lie within kDegenerateEdgeRelative * (the diagonal of the surface's box) of the
/// first (exact poles are equal to rounding; a regular edge is a curve of non-zero length).
/// Empty for a surface without a parametric form.
std::vector<DegenerateEdge> degenerate_edges(const Surface& surface);

/// Whether the non-periodic parameter `parameter` (0 = u, 1 = v) closes a seam: F on its lower
/// edge equals F on its upper edge at each of 33 samples (within the same relative size), as
/// for the full circle of an exact rational B-spline sphere or cylinder. The tracer then treats
/// the parameter as periodic, so a curve crossing the seam is one curve.
bool closes_seam(const Surface& surface, int parameter);

/// Relative size (of the box diagonal) below which an edge counts as one point.
inline constexpr double kDegenerateEdgeRelative = 1e-12;

}  // namespace ssimarch
