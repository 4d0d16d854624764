// Ellipsoid: centre c, semi-axes r0, r1, r2 along the frame (e0, e1, e2) of `axis` (default z;
// e0 from `reference`, see Frame::from_axis).
//
// Parametric: F(u,v) = c + r0 cos v cos u e0 + r1 cos v sin u e1 + r2 sin v e2,
//   u in [0, 2 pi] periodic, v in [-pi/2, pi/2]; degenerate at v = +-pi/2 (Fu = 0); the normal
//   Fu x Fv points outwards.
// Implicit: local coordinates (a, b, h) of p - c, m = min(r0, r1, r2),
//   f(p) = (m / 2) ((a/r0)^2 + (b/r1)^2 + (h/r2)^2 - 1), negative inside.
//   On the ellipsoid |grad f| = m |(a/r0^2, b/r1^2, h/r2^2)| lies in [m / max r_i, 1]: 1 at the
//   ends of the shortest semi-axis (a sphere r0 = r1 = r2 gives Sphere's f exactly).
// Box: c +- sqrt(sum_k (r_k e_k,i)^2) per coordinate i, inflated by kPrimitiveBoxMargin.
#pragma once

#include <array>
#include <cmath>

#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Ellipsoid {
 public:
  /// Throws InputError for a radius <= 0, a zero axis or non-finite data.
  Ellipsoid(const Vec3& center, const std::array<double, 3>& radii, const Vec3& axis = Vec3::UnitZ(),
            const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  const std::array<double, 3>& radii() const { return r_; }
  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    using std::cos;
    using std::sin;
    T cv = cos(v);
    return frame_.to_world<T>(r_[0] * cv * cos(u), r_[1] * cv * sin(u), r_[2] * sin(v));
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    return (q[0] * q[0] * inv2_[0] + q[1] * q[1] * inv2_[1] + q[2] * q[2] * inv2_[2] - 1.0) * half_min_;
  }

 private:
  Frame frame_;
  std::array<double, 3> r_, inv2_;
  double half_min_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
