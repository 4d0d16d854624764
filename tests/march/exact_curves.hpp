// Exact curves written once on the scalar type, with the tools the predictor tests need:
// derivatives by Taylor jets, arc length, and the distance of a point from the curve by Newton
// on c'(s).(c(s) - X) = 0 (accurate to rounding, unlike a sampled minimum).
#pragma once

#include <cmath>
#include <functional>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"

namespace ssimarch::testing {

using T3 = Taylor<3>;
using CurveFn = std::function<Vec3T<T3>(const T3&)>;

template <class T>
Vec3T<T> torus_curve_t(const T& s) {  // C1 of the thesis (testing/surface_pairs.hpp c1)
  using std::cos;
  using std::sin;
  T r = 4.0 + cos(4.0 * s);
  return {r * cos(s), r * sin(s), sin(4.0 * s)};
}
template <class T>
Vec3T<T> viviani_t(const T& s) {  // testing/surface_pairs.hpp viviani
  using std::cos;
  using std::sin;
  return {sin(s), -1.0 - cos(s), 2.0 * sin(0.5 * s)};
}
template <class T>
Vec3T<T> helix_t(const T& s) {  // seed 000 Example 1a
  using std::cos;
  using std::sin;
  return {cos(s), sin(s), s};
}
template <class T>
Vec3T<T> rational_t(const T& t) {  // seed 000 Example 1b
  T t2 = t * t;
  return {(t2 * t - t + 1.0) / (t2 + 1.0), t2 + 4.0 * t + 3.0, 2.0 * t2 * t / (t2 + 1.0) - 7.0 * t - 2.0};
}

struct CurveDerivs {
  Vec3 c, d1, d2;
};
inline CurveDerivs derivs(const CurveFn& f, double s) {
  Vec3T<T3> v = f(T3::variable(0, s));
  CurveDerivs r;
  for (int i = 0; i < 3; ++i) {
    r.c[i] = v[i][0];
    r.d1[i] = v[i][1];
    r.d2[i] = 2 * v[i][2];
  }
  return r;
}
inline Vec3 point_at(const CurveFn& f, double s) { return derivs(f, s).c; }
inline Vec3 unit_tangent_at(const CurveFn& f, double s) { return derivs(f, s).d1.normalized(); }

/// Arc length from a to b (signed), 64-panel Gauss-Legendre (5 points per panel).
inline double arc_length(const CurveFn& f, double a, double b) {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  const int n = 64;
  double sum = 0, hw = (b - a) / n;
  for (int i = 0; i < n; ++i) {
    double m = a + (i + 0.5) * hw;
    for (int k = 0; k < 5; ++k) sum += w[k] * derivs(f, m + 0.5 * hw * x[k]).d1.norm();
  }
  return 0.5 * hw * sum;
}

/// The parameter s with arc_length(f, s0, s) = L (Newton).
inline double parameter_at_arc(const CurveFn& f, double s0, double L) {
  double s = s0 + L / derivs(f, s0).d1.norm();
  for (int it = 0; it < 50; ++it) {
    double e = arc_length(f, s0, s) - L;
    s -= e / derivs(f, s).d1.norm();
    if (std::fabs(e) < 1e-15) break;
  }
  return s;
}

/// Distance from X to the curve near parameter s_guess (local minimum by Newton).
inline double distance_to_curve(const CurveFn& f, const Vec3& X, double s_guess) {
  double s = s_guess;
  for (int it = 0; it < 100; ++it) {
    CurveDerivs d = derivs(f, s);
    double g = d.d1.dot(d.c - X), gp = d.d2.dot(d.c - X) + d.d1.squaredNorm();
    double ds = g / gp;
    s -= ds;
    if (std::fabs(ds) < 1e-16 * (1 + std::fabs(s))) break;
  }
  return (point_at(f, s) - X).norm();
}

}  // namespace ssimarch::testing
