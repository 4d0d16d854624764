// Elliptic paraboloid: vertex o, axis e2 (the opening direction), focal lengths fu, fv > 0 of
// its two principal sections (fu = fv: paraboloid of revolution with focus o + f e2).
//
// Parametric (a graph over the tangent plane at the vertex, regular everywhere):
//   F(u,v) = o + u e0 + v e1 + (u^2 / (4 fu) + v^2 / (4 fv)) e2, (u, v) in a rectangle
//   (default [-1, 1]^2), not periodic. Fu x Fv = e2 - u/(2 fu) e0 - v/(2 fv) e1 points to the
//   focus side (inwards).
// Implicit: local coordinates (a, b, h) of p - o,
//   f(p) = a^2 / (4 fu) + b^2 / (4 fv) - h, negative on the focus side (grad f points outwards,
//   opposite to Fu x Fv). |grad f| = sqrt(1 + (a/(2 fu))^2 + (b/(2 fv))^2) >= 1, = 1 at the
//   vertex (f is unscaled: no polynomial f has unit gradient along a paraboloid).
// Box: the exact box of the trimmed graph (each coordinate is a separable quadratic in u, v),
//   inflated by kPrimitiveBoxMargin.
#pragma once

#include <cmath>

#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Paraboloid {
 public:
  /// Throws InputError for a focal length <= 0, an empty rectangle, a zero axis or non-finite data.
  Paraboloid(const Vec3& vertex, const Vec3& axis, double focal_u, double focal_v,
             const ParamDomain& rectangle = {{-1, 1}, {-1, 1}}, const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  double focal_u() const { return fu_; }
  double focal_v() const { return fv_; }
  const ParamDomain& domain() const { return domain_; }
  /// Marks parameter directions as unbounded (ParamDomain::unbounded_u/v; surface/unbounded.hpp).
  void mark_unbounded(bool u, bool v) {
    domain_.unbounded_u = u;
    domain_.unbounded_v = v;
  }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    return frame_.to_world<T>(u, v, u * u * ku_ + v * v * kv_);
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    auto q = frame_.to_local(p);
    return q[0] * q[0] * ku_ + q[1] * q[1] * kv_ - q[2];
  }

 private:
  Frame frame_;
  double fu_, fv_, ku_, kv_;  // k = 1 / (4 f)
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
