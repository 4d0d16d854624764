// The part of a surface that a CAD face keeps: the region inside its trimming loops (a STEP
// face's outer and inner bounds, docs/cad.md "Trimming loops"). pipeline/face_clip.hpp cuts the
// traced curves of an intersection to the regions of its surfaces; io/ builds regions from
// STEP faces. The interface is geometric (3D points), so a region does not depend on the form,
// parametric or implicit, in which the intersection uses its surface.
#pragma once

#include <array>
#include <string>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

class FaceRegion {
 public:
  virtual ~FaceRegion() = default;

  /// Where a point stands against the boundary: the nearest boundary point and the signed
  /// distance (p - nearest) . inward, > 0 inside, where inward = unit(n x T) points into the
  /// face across the boundary (T the boundary's direction, the face interior on its left seen
  /// from the face normal n; ISO 10303-42 §5.4.24).
  struct Side {
    double signed_distance = 0;
    Vec3 nearest = Vec3::Zero();
  };
  /// For a point p of the surface and the surface's own unit normal there (Fu x Fv of its
  /// parameterisation; for implicit forms of the primitives the outward gradient, which is
  /// the same direction). The sign is reliable near the boundary (within the distance to the
  /// boundary's other parts); far away it is that of the nearest boundary edge.
  virtual Side side(const Vec3& p, const Vec3& surface_normal) const = 0;
  /// The boundary as curves c_i(s), s in boundary_range(i), i < boundary_curves(): the edges of
  /// the loops (seams left out), for the edge-surface intersections that place a traced curve's
  /// crossings whatever its step (pipeline/edge_surface_points.hpp).
  virtual int boundary_curves() const = 0;
  virtual std::array<double, 2> boundary_range(int i) const = 0;
  virtual Vec3 boundary_point(int i, double s) const = 0;
  /// For messages, e.g. "STEP face #20 of part.step".
  virtual std::string name() const = 0;
};

}  // namespace ssimarch
