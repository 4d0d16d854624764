// Exact derivatives of surfaces by jets (automatic differentiation, core/jet.hpp), normals,
// fundamental forms and curvatures of both forms.
//
// Sign convention (both forms): the second fundamental form is taken w.r.t. the unit normal n,
//   L = Fuu . n, M = Fuv . n, N = Fvv . n  (n = Fu x Fv / |Fu x Fv|, parametric form)
// and the normal curvature in a tangent direction is the normal component of the acceleration
// of a unit-speed curve, k_n = II(w, w) / I(w, w). For an implicit surface with n = grad f/|grad f|
// differentiating grad f(c(s)) . c'(s) = 0 gives the same quantity
//   k_n = -w^T Hf w / |grad f|  (w a unit tangent vector).
// So where the parametric normal and grad f point the same way (all closed primitives: outwards)
// both forms give the same signed curvatures: a sphere of radius r has k_n = -1/r,
// L = -E/r, N = -G/r, mean curvature -1/r, Gaussian curvature 1/r^2.
//
// Degenerate points are reported, never normalised silently: the functions returning a normal
// or anything built on it return std::nullopt where
//   parametric: |Fu x Fv| <= tol (|Fu|^2 + |Fv|^2), or a non-finite derivative (a pole of a
//     sphere, the apex of a cone; tol = kDegenerateNormalTolerance, dimensionless);
//   implicit:   |grad f| <= min_gradient, or a non-finite derivative (a singular point of f = 0;
//     min_gradient = kMinGradientNorm, in units of f per model length).
#pragma once

#include <array>
#include <optional>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Dimensionless: a parametric point is degenerate when |Fu x Fv| <= this (|Fu|^2 + |Fv|^2),
/// i.e. Fu and Fv (nearly) parallel or one of them (nearly) zero relative to the other.
inline constexpr double kDegenerateNormalTolerance = 1e-12;
/// Units of f per model length: an implicit point is degenerate when |grad f| <= this.
inline constexpr double kMinGradientNorm = 1e-14;

/// All partial derivatives of F to total order K at (u,v): component i of F as a Jet<2,K> in
/// (u, v); F[i].derivative({a, b}) = d^(a+b) F_i / du^a dv^b. Throws std::logic_error if the
/// surface has no parametric form.
template <int K>
std::array<Jet<2, K>, 3> parametric_jet(const Surface& s, double u, double v) {
  using J = Jet<2, K>;
  const Vec3T<J> p = s.point<J>(J::variable(0, u), J::variable(1, v));
  return {p.x, p.y, p.z};
}

/// All partial derivatives of f to total order K at p, as a Jet<3,K> in (x, y, z). Throws
/// std::logic_error if the surface has no implicit form.
template <int K>
Jet<3, K> implicit_jet(const Surface& s, const Vec3& p) {
  using J = Jet<3, K>;
  return s.value<J>(Vec3T<J>(J::variable(0, p.x()), J::variable(1, p.y()), J::variable(2, p.z())));
}

/// d^(a+b) F / du^a dv^b from a parametric jet (a + b <= K).
template <int K>
Vec3 partial(const std::array<Jet<2, K>, 3>& F, int a, int b) {
  return {F[0].derivative({a, b}), F[1].derivative({a, b}), F[2].derivative({a, b})};
}

inline Vec3 to_vec3(const Vec3T<double>& p) { return {p.x, p.y, p.z}; }

/// F(u,v) as an Eigen vector.
Vec3 point(const Surface& s, double u, double v);

/// Fu x Fv normalised; std::nullopt at a degenerate point (see the file comment).
std::optional<Vec3> unit_normal(const Surface& s, double u, double v, double tol = kDegenerateNormalTolerance);
/// grad f normalised; std::nullopt where |grad f| <= min_gradient or it is not finite.
std::optional<Vec3> unit_normal(const Surface& s, const Vec3& p, double min_gradient = kMinGradientNorm);

/// First (E, F, G) and second (L, M, N) fundamental forms of the parametric form at (u,v), II
/// w.r.t. unit_normal(s, u, v).
struct FundamentalForms {
  double E, F, G, L, M, N;
};
/// std::nullopt at a degenerate point (no normal, so no II).
std::optional<FundamentalForms> fundamental_forms(const Surface& s, double u, double v,
                                                  double tol = kDegenerateNormalTolerance);

/// k_n = II(d, d) / I(d, d) in the parameter direction d = (du, dv) != 0.
double normal_curvature(const FundamentalForms& ff, double du, double dv);

/// Gaussian curvature K, mean curvature H (average of the principal curvatures, signed as
/// k_n above) and principal curvatures k1 >= k2.
struct Curvatures {
  double gaussian, mean, k1, k2;
};
/// From the fundamental forms: K = (LN - M^2)/(EG - F^2), H = (EN - 2FM + GL)/(2(EG - F^2)).
Curvatures curvatures(const FundamentalForms& ff);

/// grad f at p.
Vec3 gradient(const Surface& s, const Vec3& p);
/// Hessian of f at p.
Eigen::Matrix3d hessian(const Surface& s, const Vec3& p);

/// Normal curvature of the implicit form at p (p on the surface) in the direction of w:
/// k_n = -t^T Hf t / |grad f| with t the unit vector of w's tangential part (w minus its
/// component along grad f). std::nullopt where the point is degenerate or w has no tangential
/// part (|t before normalising| <= 1e-12 |w|).
std::optional<double> normal_curvature(const Surface& s, const Vec3& p, const Vec3& w,
                                       double min_gradient = kMinGradientNorm);

/// Curvatures of the implicit form at p (Goldman, "Curvature formulas for implicit curves and
/// surfaces", CAGD 22 (2005), eqs. for K and H; signs as k_n above):
///   K = -det [[Hf, g], [g^T, 0]] / |g|^4,  H = (g^T Hf g - |g|^2 trace Hf) / (2 |g|^3).
/// std::nullopt at a degenerate point.
std::optional<Curvatures> implicit_curvatures(const Surface& s, const Vec3& p, double min_gradient = kMinGradientNorm);

}  // namespace ssimarch
