// A particle of a packed bed: a spherocylinder (a cylinder of diameter d and length l with two
// hemispherical caps), i.e. all points within d/2 of the segment centre +- (l/2) axis. A sphere is
// the case l = 0. Lengths are in the packing's own units (model length).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <numbers>
#include <type_traits>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

/// Templated on the scalar so that tests can rerun the kernel in long double; for double, Point is
/// the library's Vec3.
template <class T>
struct SpherocylinderT {
  using Point = Eigen::Matrix<T, 3, 1>;
  Point centre = Point::Zero();
  Point axis = Point(T(0), T(0), T(1));  ///< unit vector (callers normalise; see normalised())
  T diameter = T(1);                           ///< sigma > 0
  T length = T(0);                             ///< l >= 0, distance between the two cap centres

  T radius() const { return diameter / T(2); }
  T half_length() const { return length / T(2); }
  Point plus_cap() const { return centre + half_length() * axis; }
  Point minus_cap() const { return centre - half_length() * axis; }
  /// Volume pi d^2 l / 4 + pi d^3 / 6.
  T volume() const {
    const T pi = std::numbers::pi_v<T>;
    return pi * diameter * diameter * length / T(4) + pi * diameter * diameter * diameter / T(6);
  }
  SpherocylinderT normalised() const {
    SpherocylinderT s = *this;
    s.axis = axis.normalized();
    return s;
  }
};

using Particle = SpherocylinderT<double>;
static_assert(std::is_same_v<Particle::Point, Vec3>);

/// A sphere as a zero-length spherocylinder.
inline Particle make_sphere(const Vec3& centre, double diameter) {
  Particle p;
  p.centre = centre;
  p.diameter = diameter;
  p.length = 0.0;
  return p;
}

/// A spherocylinder of the given centre, axis (any non-zero length; made unit), diameter and length.
inline Particle make_spherocylinder(const Vec3& centre, const Vec3& axis, double diameter, double length) {
  Particle p;
  p.centre = centre;
  p.axis = axis.normalized();
  p.diameter = diameter;
  p.length = length;
  return p;
}

}  // namespace ssimarch
