// A CAD face's loops in its surface's parameter plane, for deciding on which side of them a point
// far from the boundary lies (docs/cad.md, "Trimming loops"). face_region's 3D test, the sign of
// (p - c) . inward at the nearest boundary point c, is exact near the boundary but far from it
// takes the side of whatever edge is nearest in space (a torus fillet patch kept whole circles of
// the torus a quarter turn away, certified). Here the boundary curves are sampled, mapped by the
// surface's nearest points to (u, v), unwrapped across closed seams, and a point is inside when a
// ray from its (u, v) along one parameter crosses them an odd number of times (Jordan).
#pragma once

#include <optional>
#include <vector>

#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

class ParameterLoops {
 public:
  /// The loops of `region` on `surface` (which carries the face); empty where the surface is not
  /// parametric, a boundary point has no nearest point, or the face goes all the way round in
  /// both periodic directions (no ray leaves it).
  static std::optional<ParameterLoops> build(const FaceRegion& region, const Surface& surface);

  /// Whether the point of the surface with parameters uv lies inside the loops.
  bool contains(const Vec2& uv) const;

  /// How far the sampled loops may stray from the boundary (model units): the largest distance
  /// of a boundary curve's point from the chord between its two neighbouring samples. A point
  /// closer than a few of these to the boundary is better decided in 3D.
  double resolution() const { return resolution_; }

  /// The largest distance of a boundary sample from the surface (model units): zero for an exact
  /// model; CAD files carry edges off their faces' surfaces by their modelling tolerance
  /// (Ventilator.stp: 1.2e-3 on an extruded blade).
  double edge_gap() const { return edge_gap_; }

 private:
  struct Segment {
    Vec2 a, b;
  };
  std::vector<Segment> segments_;
  int ray_ = 1;                     // the parameter the ray runs along (0: u, 1: v); the other is the abscissa
  double period_abscissa_ = 0;      // the abscissa's period (0: not periodic)
  double period_ray_ = 0;           // the ray parameter's period, where the face stays inside one turn of it
  double ray_lo_ = 0, ray_hi_ = 0;  // the loops' extent along the ray parameter (unwrapped)
  double abscissa_extent_ = 0;      // and along the other
  double resolution_ = 0;
  double edge_gap_ = 0;
};

}  // namespace ssimarch
