// A particle of a packed bed: a spherocylinder (a cylinder of diameter d and length l with two
// hemispherical caps), i.e. all points within d/2 of the segment centre +- (l/2) axis. A sphere is
// the case l = 0. Lengths are in the packing's own units (model length).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <numbers>

namespace ssimarch::porosity {

template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

template <class T>
struct SpherocylinderT {
  Vec3<T> centre = Vec3<T>::Zero();
  Vec3<T> axis = Vec3<T>(T(0), T(0), T(1));  ///< unit vector (callers normalise; see normalised())
  T diameter = T(1);                           ///< sigma > 0
  T length = T(0);                             ///< l >= 0, distance between the two cap centres

  T radius() const { return diameter / T(2); }
  T half_length() const { return length / T(2); }
  Vec3<T> plus_cap() const { return centre + half_length() * axis; }
  Vec3<T> minus_cap() const { return centre - half_length() * axis; }
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

/// A sphere as a zero-length spherocylinder.
inline Particle make_sphere(const Vec3<double>& centre, double diameter) {
  Particle p;
  p.centre = centre;
  p.diameter = diameter;
  p.length = 0.0;
  return p;
}

}  // namespace ssimarch::porosity
