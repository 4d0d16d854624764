// Where a face's boundary meets another surface (an edge-surface intersection): the points of a
// FaceRegion's boundary curves that lie on the surface, found along each boundary curve on its
// own, without any traced curve. Every point where an intersection curve crosses the face's
// boundary is one of them, so face_clip can cut a curve at each crossing whatever the step it
// was traced with (issue 28 item 2; docs/cad.md, "Trimming loops").
#pragma once

#include <vector>

#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

struct EdgeSurfaceTolerances {
  /// |signed distance| to the surface at which a point of the boundary is on it (model units):
  /// the intersection's point tolerance.
  double on_surface = 1e-12;
  /// The resolution of the search (model units): no piece of boundary shorter than this is
  /// examined, a stretch whose ends and middle are this close to the surface runs along it (a
  /// rod in a hole of its own radius) and is not split further, and points closer than this are
  /// one point. face_clip passes its boundary band (kBoundaryBand x the model size).
  double band = 1e-6;
};

/// The points of `region`'s boundary curves on `surface`, each to |g| <= on_surface, where g is
/// the signed distance to the surface (to the foot point of the surface's nearest point, signed
/// by its normal; f / |grad f| for a surface given only implicitly). Along each curve, pieces
/// are split while g may vanish inside them: g is 1-Lipschitz in arc length, so a piece of length
/// l whose ends have |g0| + |g1| > l holds no root, and one with a sign change holds one, solved by
/// the Illinois method with bisection. Termination: a piece is split only while it is longer than
/// `band`. Limits: two roots closer than `band` along the boundary (a surface touching it within
/// the band) are not separated; an arc-length bound from chords through the middle (x 1.25)
/// stands in for the exact one.
std::vector<Vec3> edge_surface_points(const FaceRegion& region, const Surface& surface,
                                      const EdgeSurfaceTolerances& tolerances);

}  // namespace ssimarch
