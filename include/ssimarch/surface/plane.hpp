// Plane through o with unit normal n = e2.
//
// Parametric: F(u,v) = o + u e0 + v e1 on a rectangle (default [-1, 1]^2), not periodic;
//   Fu x Fv = n. e0 comes from `reference` (see Frame::from_axis).
// Implicit: f(p) = (p - o) . n, the signed distance: |grad f| = 1 everywhere.
// Box: the box of the rectangle, inflated by kPrimitiveBoxMargin (so it is never flat).
#pragma once

#include "ssimarch/surface/frame.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {

class Plane {
 public:
  /// Throws InputError for a zero normal, an empty rectangle or non-finite data.
  Plane(const Vec3& point, const Vec3& normal, const ParamDomain& rectangle = {{-1, 1}, {-1, 1}},
        const std::optional<Vec3>& reference = {});

  const Frame& frame() const { return frame_; }
  const Vec3& normal() const { return frame_.e2; }
  const ParamDomain& domain() const { return domain_; }
  /// Marks parameter directions as unbounded (ParamDomain::unbounded_u/v; surface/unbounded.hpp).
  void mark_unbounded(bool u, bool v) {
    domain_.unbounded_u = u;
    domain_.unbounded_v = v;
  }
  const Box& box() const { return box_; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    return frame_.to_world<T>(u, v, T(0.0));
  }
  template <class T>
  T value(const Vec3T<T>& p) const {
    return frame_.to_local(p)[2];
  }

 private:
  Frame frame_;
  ParamDomain domain_;
  Box box_;
};

}  // namespace ssimarch
