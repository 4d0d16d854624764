// Sphere of centre c and radius r, both forms.
//
// Parametric (longitude u, latitude v), in the frame (e0, e1, e2) of `axis` (default z):
//   F(u,v) = c + r (cos v cos u e0 + cos v sin u e1 + sin v e2),
//   u in [0, 2 pi] periodic, v in [-pi/2, pi/2]; degenerate at the poles v = +-pi/2 (Fu = 0).
//   Fu x Fv = r^2 cos v (outward unit normal): the normal points outwards.
// Implicit: f(p) = (|p - c|^2 - r^2) / (2 r), negative inside; grad f = (p - c)/r, so
//   |grad f| = 1 exactly on the sphere and f is the signed distance to first order.
// Box: c +- r, inflated by kPrimitiveBoxMargin.
#pragma once

#include <cmath>
#include <numbers>

#include "ssimarch/surface/frame.hpp"

namespace ssimarch {

/// Relative margin added to each side of a primitive's box (fraction of its largest side).
inline constexpr double kPrimitiveBoxMargin = 0.05;

class Sphere {
 public:
  /// Throws InputError for r <= 0 or non-finite data.
  Sphere(const Vec3& center, double radius, const Vec3& axis = Vec3::UnitZ(),
         const std::optional<Vec3>& reference = {});

  const Vec3& center() const { return frame_.origin; }
  double radius() const { return r_; }
  const Frame& frame() const { return frame_; }
  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    T cv = cos(v);
    return frame_.to_world<T>(r_ * cv * cos(u), r_ * cv * sin(u), r_ * sin(v));
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    return (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - r_ * r_) / (2 * r_);
  }

 private:
  Frame frame_;
  double r_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
