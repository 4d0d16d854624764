// Spherocylinder (capsule): centre c, axis e2, radius r, length L >= 0 of the cylindrical part
// (total length L + 2 r; L = 0 is a sphere). The set of points at distance r from the segment
// c +- (L/2) e2.
//
// Parametric, piecewise, v = arc length along a meridian, in [-(L/2 + pi r/2), L/2 + pi r/2],
// u in [0, 2 pi] periodic, radial direction d(u) = cos u e0 + sin u e1:
//   |v| <= L/2:  F = c + r d(u) + v e2                                   (cylinder)
//   v > L/2:     F = c + r cos t d(u) + (L/2 + r sin t) e2, t = (v - L/2)/r   (upper hemisphere)
//   v < -L/2:    F = c + r cos t d(u) + (-L/2 + r sin t) e2, t = (v + L/2)/r  (lower hemisphere)
//   The pieces join C1 at v = +-L/2 (position and unit-speed tangent continue; second
//   derivatives jump, as the meridian's curvature jumps from 0 to 1/r). Jets taken exactly at a
//   join give the one-sided derivatives of the cylinder piece. Degenerate at the poles
//   (Fu = 0). Fu x Fv points outwards.
// Implicit: local coordinates (a, b, h) of p - c, h' = clamp(h, -L/2, L/2),
//   f(p) = (a^2 + b^2 + (h - h')^2 - r^2) / (2 r) = (dist(p, segment)^2 - r^2) / (2 r):
//   negative inside, C1 across the planes h = +-L/2, |grad f| = dist / r = 1 on the capsule.
// Box: segment ends +- r, inflated by kPrimitiveBoxMargin.
#pragma once

#include <cmath>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Capsule {
 public:
  /// Throws InputError for r <= 0, L < 0, a zero axis or non-finite data.
  Capsule(const Vec3& center, const Vec3& axis, double radius, double length,
          const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  double radius() const { return r_; }
  double length() const { return 2 * half_; }
  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    double v0 = primal(v);
    if (v0 >= -half_ && v0 <= half_) return frame_.to_world<T>(r_ * cos(u), r_ * sin(u), v);
    double end = v0 > 0 ? half_ : -half_;
    T t = (v - end) / r_;
    T rho = r_ * cos(t);
    return frame_.to_world<T>(rho * cos(u), rho * sin(u), end + r_ * sin(t));
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    double h0 = primal(q[2]);
    T dh = h0 > half_ ? q[2] - half_ : (h0 < -half_ ? q[2] + half_ : T(0.0));
    return (q[0] * q[0] + q[1] * q[1] + dh * dh - r_ * r_) / (2 * r_);
  }

 private:
  Frame frame_;
  double r_, half_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
