// Local derivative data of one surface at one point, to third order, and the normal projections
// of a curve's second and third derivatives that every intersection-geometry formula is built on
// (thesis §2.2 and ch. 3; seed 004 §4).
//
// This layer knows nothing of the Surface class: the data come from jets (parametric_local /
// implicit_local below take any callable written once for every scalar type) or from the
// surface module's jets (see intersection_geometry.hpp).
//
// For a curve c(s) on the surface with c' = t (unit, in the tangent plane) and c'' = c2, and a
// unit normal N of the surface at the point:
//   normal_curvature = c''.N  = II(t,t)                                            (eq 2.18)
//   third_normal     = c'''.N = III(t,t,t) + 3 II(t, w2)                          (eq 3.25, lambda)
// parametric: II(a,b) = L a_u b_u + M (a_u b_v + a_v b_u) + N a_v b_v with (a_u, a_v) the
//   coordinates of a in (F_u, F_v), w2 = F_u u'' + F_v v'' from
//   E u'' + F v'' = c''.F_u - F_uu.F_u u'^2 - 2 F_uv.F_u u'v' - F_vv.F_u v'^2 (and with F_v)
//   (thesis ch. 3, the E_u/2 ... form written with the dot products it abbreviates);
// implicit:   c''.grad f = -D^2f[t,t],  c'''.grad f = -(D^3f[t,t,t] + 3 D^2f[t,c''])
//   (seed 004 §4, eqs 4.6, 4.19-4.20), projected on N by dividing by grad f.N.
// Both are linear in N, so they hold for either orientation of the normal.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <variant>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

/// F and its partial derivatives to order 3 at (u, v).
struct ParametricLocal {
  Vec3 p, fu, fv, fuu, fuv, fvv, fuuu, fuuv, fuvv, fvvv;
};

/// f and its partial derivatives to order 3 at p. third[i](j,k) = d^3 f / dx_i dx_j dx_k.
struct ImplicitLocal {
  Vec3 p;
  double value = 0;
  Vec3 grad;
  Eigen::Matrix3d hess;
  std::array<Eigen::Matrix3d, 3> third;

  /// D^3 f[a, b, .] as a vector (component i = sum_jk f_ijk a_j b_k).
  Vec3 third_contract(const Vec3& a, const Vec3& b) const {
    return {a.dot(third[0] * b), a.dot(third[1] * b), a.dot(third[2] * b)};
  }
};

using SurfaceLocal = std::variant<ParametricLocal, ImplicitLocal>;

/// Point of the surface data.
Vec3 local_point(const SurfaceLocal& s);
/// Unit normal: unit(F_u x F_v) or unit(grad f); NaN where that vector is zero.
Vec3 unit_normal(const SurfaceLocal& s);
/// Whether all derivative data are finite.
bool is_finite(const SurfaceLocal& s);

/// Coordinates (a_u, a_v) of a tangent vector a in the basis (F_u, F_v): the least-squares
/// solution of the first-fundamental-form system [E F; F G] (a_u, a_v) = (a.F_u, a.F_v).
Vec2 tangent_coordinates(const ParametricLocal& s, const Vec3& a);

/// Second fundamental form II(a, b) with respect to the unit normal `normal` (a, b tangent).
double second_form(const SurfaceLocal& s, const Vec3& a, const Vec3& b, const Vec3& normal);
/// c''.N for a unit-speed curve on the surface with tangent t (eq 2.18 / eq 4.6).
double normal_curvature(const SurfaceLocal& s, const Vec3& t, const Vec3& normal);
/// c'''.N (lambda of eqs 3.25 and 4.19-4.20) for a unit-speed curve with c' = t, c'' = c2.
double third_normal(const SurfaceLocal& s, const Vec3& t, const Vec3& c2, const Vec3& normal);

/// Derivative data of a parametric surface F(u, v), given as a callable written for any scalar
/// (F(T u, T v) -> Vec3T<T>), from one evaluation with third-order jets.
template <class Fn>
ParametricLocal parametric_local(const Fn& F, double u, double v) {
  using J = Jet<2, 3>;
  Vec3T<J> r = F(J::variable(0, u), J::variable(1, v));
  auto d = [&](int i, int j) {
    return Vec3(r.x.derivative({i, j}), r.y.derivative({i, j}), r.z.derivative({i, j}));
  };
  return {d(0, 0), d(1, 0), d(0, 1), d(2, 0), d(1, 1), d(0, 2), d(3, 0), d(2, 1), d(1, 2), d(0, 3)};
}

/// Derivative data of an implicit surface f(p) = 0, given as a callable written for any scalar
/// (f(Vec3T<T>) -> T), from one evaluation with third-order jets.
template <class Fn>
ImplicitLocal implicit_local(const Fn& f, const Vec3& p) {
  using J = Jet<3, 3>;
  J r = f(Vec3T<J>(J::variable(0, p.x()), J::variable(1, p.y()), J::variable(2, p.z())));
  ImplicitLocal s;
  s.p = p;
  s.value = r.value();
  auto e = [](int i, int j, int k) {
    std::array<int, 3> a{0, 0, 0};
    ++a[static_cast<std::size_t>(i)];
    if (j >= 0) ++a[static_cast<std::size_t>(j)];
    if (k >= 0) ++a[static_cast<std::size_t>(k)];
    return a;
  };
  for (int i = 0; i < 3; ++i) {
    s.grad[i] = r.derivative(e(i, -1, -1));
    for (int j = 0; j < 3; ++j) {
      s.hess(i, j) = r.derivative(e(i, j, -1));
      for (int k = 0; k < 3; ++k) s.third[static_cast<std::size_t>(i)](j, k) = r.derivative(e(i, j, k));
    }
  }
  return s;
}

}  // namespace ssimarch
