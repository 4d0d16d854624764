// Surface pairs with closed-form intersection curves, shared by the geometry tests and the
// docs table program (bench/geometry_table.cpp). Each surface is a callable written once for
// every scalar type (double, Jet, Taylor), as the library's own surfaces are.
//
// Exact references come from the closed-form curve alone (frenet_from_derivatives on its
// Taylor coefficients), never from the surfaces, so they are independent of every method.
#pragma once

#include <cmath>
#include <numbers>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/geometry/surface_local.hpp"

namespace ssimarch::testing {

using std::cos;
using std::sin;

/// Frenet values of a closed-form curve c(s) (callable on Taylor<3>) at s0.
template <class Curve>
CurveGeometry exact_frenet(const Curve& c, double s0) {
  Vec3T<Taylor<3>> r = c(Taylor<3>::variable(0, s0));
  auto d = [&](int k) {
    double f = k == 3 ? 6.0 : (k == 2 ? 2.0 : 1.0);
    return Vec3(r.x[k] * f, r.y[k] * f, r.z[k] * f);
  };
  CurveGeometry g = frenet_from_derivatives(d(1), d(2), d(3));
  g.point = Vec3(r.x[0], r.y[0], r.z[0]);
  return g;
}

template <class Curve>
Vec3 curve_point(const Curve& c, double s) {
  Vec3T<double> r = c(s);
  return {r.x, r.y, r.z};
}
template <class Curve>
Vec3 curve_tangent(const Curve& c, double s) {
  Vec3T<Taylor<1>> r = c(Taylor<1>::variable(0, s));
  return Vec3(r.x[1], r.y[1], r.z[1]).normalized();
}

// --- Viviani (seed 004 §6): unit sphere and cylinder x^2 + y^2 - x = 0 -------------------------
struct Viviani {
  template <class T>
  Vec3T<T> operator()(const T& t) const {
    return {(1.0 + cos(t)) / 2.0, sin(t) / 2.0, sin(t / 2.0)};
  }
};
struct UnitSphereImplicit {
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return p.x * p.x + p.y * p.y + p.z * p.z - 1.0;
  }
};
struct VivianiCylinderImplicit {
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return p.x * p.x + p.y * p.y - p.x;
  }
};
struct UnitSphereParametric {  // (cos v cos u, cos v sin u, sin v)
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    return {cos(v) * cos(u), cos(v) * sin(u), sin(v)};
  }
};
struct VivianiCylinderParametric {  // (1/2 + cos p / 2, sin p / 2, q)
  template <class T>
  Vec3T<T> operator()(const T& p, const T& q) const {
    return {0.5 + cos(p) / 2.0, sin(p) / 2.0, q};
  }
};
inline double viviani_sphere_u(double t) { return std::atan2(sin(t) / 2, (1 + cos(t)) / 2); }
inline double viviani_sphere_v(double t) { return std::asin(sin(t / 2)); }

// --- Thesis pair 1: ruled surface / torus, C1 = the (1,4) torus knot (examples.md ch. 3) ------
struct TorusKnot {
  template <class T>
  Vec3T<T> operator()(const T& s) const {
    return {(4.0 + cos(4.0 * s)) * cos(s), (4.0 + cos(4.0 * s)) * sin(s), sin(4.0 * s)};
  }
};
struct RuledF1 {
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    T w = cos(4.0 * u) + sin(4.0 * u);
    return {(4.0 + cos(4.0 * u)) * cos(u) + v * w * cos(u), (4.0 + cos(4.0 * u)) * sin(u) + v * w * sin(u),
            sin(4.0 * u) + v * (sin(4.0 * u) - cos(4.0 * u))};
  }
};
struct TorusG1 {  // ((4 + cos p) sin q, (4 + cos p) cos q, sin p); C1(s) = G1(4s, pi/2 - s)
  template <class T>
  Vec3T<T> operator()(const T& p, const T& q) const {
    return {(4.0 + cos(p)) * sin(q), (4.0 + cos(p)) * cos(q), sin(p)};
  }
};

// --- Thesis pair 2 (corrected): cylinder (cos u, sin u - 1, v) and the radius-2 sphere about
// (-1,-1,0); C2(s) = (cos s, sin s - 1, 2 sin(s/2)) = F2(s, 2 sin(s/2)) = G2(s/2, s/2). C2(0) =
// (1,-1,0) is the curve's double point (normals parallel).
struct CurveC2 {
  template <class T>
  Vec3T<T> operator()(const T& s) const {
    return {cos(s), sin(s) - 1.0, 2.0 * sin(s / 2.0)};
  }
};
struct CylinderF2 {
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    return {cos(u), sin(u) - 1.0, v};
  }
};
struct SphereG2 {
  template <class T>
  Vec3T<T> operator()(const T& p, const T& q) const {
    return {-1.0 + 2.0 * cos(p) * cos(q), -1.0 + 2.0 * cos(p) * sin(q), 2.0 * sin(p)};
  }
};
struct CylinderF2Implicit {  // x^2 + (y+1)^2 - 1
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return p.x * p.x + (p.y + 1.0) * (p.y + 1.0) - 1.0;
  }
};
struct SphereG2Implicit {  // |p - (-1,-1,0)|^2 - 4
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return (p.x + 1.0) * (p.x + 1.0) + (p.y + 1.0) * (p.y + 1.0) + p.z * p.z - 4.0;
  }
};

// --- Plane and ellipsoid, both placed by a rotation R and an offset o: the ellipse
// o + R (A cos t, B sin t, h), A = a sqrt(1 - h^2/c^2), B = b sqrt(1 - h^2/c^2).
struct Placement {
  Eigen::Matrix3d R;
  Vec3 o;
  Placement() {
    R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    o = Vec3(0.3, -0.2, 0.5);
  }
  template <class T>
  Vec3T<T> world(const T& a, const T& b, const T& c) const {
    return from_frame(o, Vec3(R.col(0)), Vec3(R.col(1)), Vec3(R.col(2)), a, b, c);
  }
  template <class T>
  std::array<T, 3> local(const Vec3T<T>& p) const {
    return to_frame(p, o, Vec3(R.col(0)), Vec3(R.col(1)), Vec3(R.col(2)));
  }
};
struct EllipseData {
  static constexpr double a = 2.0, b = 1.2, c = 0.8, h = 0.3;
  static double A() { return a * std::sqrt(1 - h * h / (c * c)); }
  static double B() { return b * std::sqrt(1 - h * h / (c * c)); }
};
struct Ellipse {
  Placement pl;
  template <class T>
  Vec3T<T> operator()(const T& t) const {
    return pl.world<T>(EllipseData::A() * cos(t), EllipseData::B() * sin(t), T(EllipseData::h));
  }
};
struct PlaneParametric {
  Placement pl;
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    return pl.world<T>(u, v, T(EllipseData::h));
  }
};
struct EllipsoidImplicit {
  Placement pl;
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    auto q = pl.local(p);
    const double a = EllipseData::a, b = EllipseData::b, c = EllipseData::c;
    return q[0] * q[0] / (a * a) + q[1] * q[1] / (b * b) + q[2] * q[2] / (c * c) - 1.0;
  }
};
struct PlaneImplicit {
  Placement pl;
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return pl.local(p)[2] - EllipseData::h;
  }
};
struct EllipsoidParametric {  // o + R (a cos v cos u, b cos v sin u, c sin v)
  Placement pl;
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    return pl.world<T>(EllipseData::a * cos(v) * cos(u), EllipseData::b * cos(v) * sin(u), EllipseData::c * sin(v));
  }
};

// --- Helix as cylinder and helicoid: (a cos t, a sin t, c t) --------------------------------------
struct HelixData {
  static constexpr double a = 1.5, c = 0.4;
};
struct Helix {
  template <class T>
  Vec3T<T> operator()(const T& t) const {
    return {HelixData::a * cos(t), HelixData::a * sin(t), HelixData::c * t};
  }
};
struct HelixCylinderParametric {
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    return {HelixData::a * cos(u), HelixData::a * sin(u), v};
  }
};
struct HelixCylinderImplicit {
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return p.x * p.x + p.y * p.y - HelixData::a * HelixData::a;
  }
};
struct Helicoid {  // (v cos u, v sin u, c u); the helix is v = a
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    return {v * cos(u), v * sin(u), HelixData::c * u};
  }
};

}  // namespace ssimarch::testing
