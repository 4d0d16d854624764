// The part of a surface that a CAD face keeps: the region inside its trimming loops (a STEP
// face's outer and inner bounds, docs/cad.md "Trimming loops"). pipeline/face_clip.hpp cuts the
// traced curves of an intersection to the regions of its surfaces; io/ builds regions from
// STEP faces. The interface is geometric (3D points), so a region does not depend on the form,
// parametric or implicit, in which the intersection uses its surface.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

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
  /// Parameters inside boundary_range(i) where curve i is less smooth than elsewhere (a
  /// B-spline's knots), for quadratures that must not straddle them; none by default.
  virtual std::vector<double> boundary_breaks(int i) const {
    (void)i;
    return {};
  }
  /// d boundary_point / ds. By default central differences of 1e-6 of the range (one-sided at
  /// the ends), which lose ~1e-10 of the speed to rounding; regions that know their curves
  /// override it exactly.
  virtual Vec3 boundary_derivative(int i, double s) const {
    const auto [lo, hi] = boundary_range(i);
    const double h = 1e-6 * (hi - lo);
    const double a = s - h < lo ? lo : s - h, b = s + h > hi ? hi : s + h;
    return (boundary_point(i, b) - boundary_point(i, a)) / (b - a);
  }
  /// For messages, e.g. "STEP face #20 of part.step".
  virtual std::string name() const = 0;

  // The model's topology, where the region comes from one (pipeline/shared_boundary.hpp).
  /// The solid the face bounds, as a key equal to another region's exactly when both faces bound
  /// the same occurrence of the same solid (a STEP MANIFOLD_SOLID_BREP placed once); empty when the
  /// face bounds no solid or its model has no topology.
  virtual std::string solid() const { return {}; }
  /// The model's id of boundary curve i's edge (a STEP EDGE_CURVE instance): two faces of one
  /// solid that list the same id share that edge, the same curve over the same range. 0: unknown.
  virtual std::int64_t boundary_edge(int i) const {
    (void)i;
    return 0;
  }
  /// The model's ids of boundary curve i's two vertices (its ends), 0 where unknown.
  virtual std::array<std::int64_t, 2> boundary_edge_vertices(int i) const {
    (void)i;
    return {0, 0};
  }
  /// The vertices of the boundary's edges: the model's id and the point.
  virtual std::vector<std::pair<std::int64_t, Vec3>> boundary_vertices() const { return {}; }
};

}  // namespace ssimarch
