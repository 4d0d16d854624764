// Circular cylinder: point c on the axis, axis direction e2, radius r, axial range [h0, h1].
//
// Parametric, in the frame (e0, e1, e2) of the axis:
//   F(u,v) = c + r cos u e0 + r sin u e1 + v e2,  u in [0, 2 pi] periodic, v in [h0, h1].
//   Regular everywhere; Fu x Fv = r (cos u e0 + sin u e1): the normal points outwards.
// Implicit: with local coordinates (a, b, h) of p - c,
//   f(p) = (a^2 + b^2 - r^2) / (2 r), negative inside, |grad f| = rho / r = 1 on the cylinder.
//   The implicit cylinder is infinite; the range only trims the parametric form and the box.
// Box: the box of the trimmed piece, inflated by kPrimitiveBoxMargin.
#pragma once

#include <cmath>

#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Cylinder {
 public:
  /// Throws InputError for r <= 0, h0 >= h1, a zero axis or non-finite data.
  Cylinder(const Vec3& point, const Vec3& axis, double radius, Interval range,
           const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  double radius() const { return r_; }
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
    return frame_.to_world<T>(r_ * cos(u), r_ * sin(u), v);
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    return (q[0] * q[0] + q[1] * q[1] - r_ * r_) / (2 * r_);
  }

 private:
  Frame frame_;
  double r_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
