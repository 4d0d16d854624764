// 3-vectors: Vec3T<T> for formulas written once for every scalar type (double, Jet, Taylor),
// and the Eigen type Vec3 for double-precision linear algebra.
//
// Why not Eigen::Matrix<Jet,3,1>: every custom scalar would need an Eigen::NumTraits
// specialisation and Eigen's expression templates obscure the jets' cost (style.md 3.3).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

namespace ssimarch {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

template <class T>
struct Vec3T {
  T x{}, y{}, z{};

  Vec3T() = default;
  Vec3T(T a, T b, T c) : x(std::move(a)), y(std::move(b)), z(std::move(c)) {}
  explicit Vec3T(const Vec3& v) : x(v.x()), y(v.y()), z(v.z()) {}

  T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  friend Vec3T operator+(const Vec3T& a, const Vec3T& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3T operator-(const Vec3T& a, const Vec3T& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3T operator-(const Vec3T& a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3T operator*(const T& s, const Vec3T& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend Vec3T operator*(const Vec3T& a, const T& s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3T operator/(const Vec3T& a, const T& s) { return {a.x / s, a.y / s, a.z / s}; }
};

template <class T>
T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// A constant double vector lifted to scalar type T.
template <class T>
Vec3T<T> lift(const Vec3& v) {
  return {T(v.x()), T(v.y()), T(v.z())};
}

/// o + a*e0 + b*e1 + c*e2: a point given in a local frame, for any scalar.
template <class T>
Vec3T<T> from_frame(const Vec3& o, const Vec3& e0, const Vec3& e1, const Vec3& e2, const T& a, const T& b, const T& c) {
  return {o.x() + a * e0.x() + b * e1.x() + c * e2.x(), o.y() + a * e0.y() + b * e1.y() + c * e2.y(),
          o.z() + a * e0.z() + b * e1.z() + c * e2.z()};
}

/// Components of (p - o) along an orthonormal frame e0, e1, e2.
template <class T>
std::array<T, 3> to_frame(const Vec3T<T>& p, const Vec3& o, const Vec3& e0, const Vec3& e1, const Vec3& e2) {
  T dx = p.x - o.x(), dy = p.y - o.y(), dz = p.z - o.z();
  return {dx * e0.x() + dy * e0.y() + dz * e0.z(), dx * e1.x() + dy * e1.y() + dz * e1.z(),
          dx * e2.x() + dy * e2.y() + dz * e2.z()};
}

}  // namespace ssimarch
