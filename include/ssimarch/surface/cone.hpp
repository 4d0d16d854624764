// Circular cone: apex o, axis e2, half-angle alpha in (0, pi/2), axial range [h0, h1].
//
// Parametric, in the frame (e0, e1, e2) of the axis, t = tan(alpha):
//   F(u,v) = o + v t (cos u e0 + sin u e1) + v e2,  u in [0, 2 pi] periodic, v in [h0, h1]
//   (v is the signed axial distance from the apex; h0 < 0 < h1 gives both nappes).
//   Degenerate at the apex v = 0 (Fu = 0). Fu x Fv = v t (cos u e0 + sin u e1 - t e2): the normal
//   points outwards (away from the axis) on the nappe v > 0 and inwards on v < 0.
// Implicit: local coordinates (a, b, h) of p - o, rho^2 = a^2 + b^2, L = max(|h0|, |h1|):
//   f(p) = (rho^2 cos^2 alpha - h^2 sin^2 alpha) / (2 L sin alpha), negative inside either nappe.
//   On the cone grad f = (|h| / L) * outward unit normal, so |grad f| = |h| / L: 1 on the rim
//   farthest from the apex, falling linearly to 0 at the apex (no polynomial f does better,
//   since every polynomial defining a cone is singular at the apex). The implicit cone is
//   infinite (both nappes); the range only trims the parametric form and the box.
// Box: the box of the trimmed piece (hull of its two rim circles), inflated by
//   kPrimitiveBoxMargin.
#pragma once

#include <cmath>

#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Cone {
 public:
  /// Throws InputError for alpha outside (0, pi/2), h0 >= h1, a zero axis or non-finite data.
  Cone(const Vec3& apex, const Vec3& axis, double half_angle, Interval range,
       const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  double half_angle() const { return alpha_; }
  const Interval& range() const { return domain_.v; }
  const ParamDomain& domain() const { return domain_; }
  /// Marks parameter directions as unbounded (ParamDomain::unbounded_u/v; surface/unbounded.hpp).
  void mark_unbounded(bool u, bool v) {
    domain_.unbounded_u = u;
    domain_.unbounded_v = v;
  }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    T rho = tan_ * v;
    return frame_.to_world<T>(rho * cos(u), rho * sin(u), v);
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    return ((q[0] * q[0] + q[1] * q[1]) * cos2_ - q[2] * q[2] * sin2_) * scale_;
  }

 private:
  Frame frame_;
  double alpha_, tan_, cos2_, sin2_, scale_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
