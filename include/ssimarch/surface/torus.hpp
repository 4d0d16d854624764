// Torus: centre c, axis e2, major radius R (centre to tube centre), minor radius r (tube).
//
// Parametric, in the frame (e0, e1, e2) of the axis:
//   F(u,v) = c + (R + r cos v)(cos u e0 + sin u e1) + r sin v e2,  u, v in [0, 2 pi], both
//   periodic. Fu x Fv = r (R + r cos v) n with n = cos v (cos u e0 + sin u e1) + sin v e2 the
//   outward normal; regular where R + r cos v != 0 (everywhere when R > r).
// Implicit: local coordinates (a, b, h) of p - c, rho^2 = a^2 + b^2, s = a^2 + b^2 + h^2,
//   f(p) = ((s + R^2 - r^2)^2 - 4 R^2 rho^2) / (8 R^2 r), negative inside the tube.
//   On the torus grad f = (rho / R) n, so |grad f| = rho / R = 1 + (r/R) cos v: 1 on the top and
//   bottom circles, between (R - r)/R and (R + r)/R elsewhere (the quartic is the polynomial of
//   least degree; none has unit gradient everywhere on the torus).
//   R <= r (horn and spindle tori) is allowed: the surface then passes through the axis, where
//   both forms are singular.
// Box: c +- (R sqrt(1 - e2_i^2) + r) per coordinate i, inflated by kPrimitiveBoxMargin.
#pragma once

#include <cmath>

#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Torus {
 public:
  /// Throws InputError for R <= 0, r <= 0, a zero axis or non-finite data.
  Torus(const Vec3& center, const Vec3& axis, double major_radius, double minor_radius,
        const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  double major_radius() const { return R_; }
  double minor_radius() const { return r_; }
  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    T rho = R_ + r_ * cos(v);
    return frame_.to_world<T>(rho * cos(u), rho * sin(u), r_ * sin(v));
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    T rho2 = q[0] * q[0] + q[1] * q[1];
    T w = rho2 + q[2] * q[2] + (R_ * R_ - r_ * r_);
    return (w * w - (4 * R_ * R_) * rho2) / (8 * R_ * R_ * r_);
  }

 private:
  Frame frame_;
  double R_, r_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
