// Orthonormal frames that place a primitive at an arbitrary position and orientation.
//
// A primitive is written in local coordinates (a, b, c) along (e0, e1, e2) with e2 its axis
// (or normal); world point p = origin + a e0 + b e1 + c e2. e0 is the direction of u = 0 of
// every rotational parameterisation.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

struct Frame {
  Vec3 origin = Vec3::Zero();
  Vec3 e0 = Vec3::UnitX(), e1 = Vec3::UnitY(), e2 = Vec3::UnitZ();

  /// Right-handed orthonormal frame with e2 = axis/|axis|. e0 is `reference` with its axial
  /// component removed, normalised; without a reference, the coordinate axis least aligned with
  /// the axis (first of x, y, z on ties) projected the same way, so axis = z gives e0 = x,
  /// e1 = y. Throws InputError (where = `what`) for a zero or non-finite axis, or a reference
  /// (anti)parallel to the axis (|sin angle| < 1e-9).
  static Frame from_axis(const Vec3& origin, const Vec3& axis, const std::optional<Vec3>& reference = {},
                         const std::string& what = "frame");

  template <class T>
  Vec3T<T> to_world(const T& a, const T& b, const T& c) const {
    return from_frame(origin, e0, e1, e2, a, b, c);
  }
  Vec3 to_world(double a, double b, double c) const { return origin + a * e0 + b * e1 + c * e2; }
  template <class T>
  std::array<T, 3> to_local(const Vec3T<T>& p) const {
    return to_frame(p, origin, e0, e1, e2);
  }
};

/// Axis-aligned box of a set given by its half-extents around a centre.
inline Box box_from_center(const Vec3& center, const Vec3& half) {
  return {{center.x() - half.x(), center.x() + half.x()},
          {center.y() - half.y(), center.y() + half.y()},
          {center.z() - half.z(), center.z() + half.z()}};
}

/// Smallest box containing both.
Box box_union(const Box& a, const Box& b);

/// Every side moved outwards by `relative` times the largest side (at least `absolute`), so a
/// flat set gets a box of non-zero thickness.
Box inflate(const Box& b, double relative, double absolute = 0.0);

}  // namespace ssimarch
