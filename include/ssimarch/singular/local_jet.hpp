// Bivariate Taylor polynomials of the local algebraic curve h(s,t) = 0 at a point of an
// intersection (thesis ch. 5 §5.2.3; derivation in docs/math/singular_local_curve.md).
//
// A LocalJet is a Jet<2, kLocalOrder> in the orthonormal tangent-plane coordinates (s, t) of the
// point (model units). Helpers here read and change such polynomials: coefficient of s^i t^j,
// value/gradient/Hessian at a point, partial derivatives, linear changes of coordinates.
#pragma once

#include <array>
#include <complex>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

/// Order of the local expansions: twelve, the most core/jet.hpp supports. It leaves room for the
/// splitting lemma up to A11 (phi = c Y^(k+1) needs order k + 1), for the Milnor number of germs
/// whose Jacobian ideal contains M^11, and for Puiseux terms of order 6 on branches of
/// multiplicity 2 (docs/math/singular_local_curve.md §3-4).
inline constexpr int kLocalOrder = 12;
using LocalJet = Jet<2, kLocalOrder>;

/// Coefficient of s^i t^j (normalised: the Taylor coefficient, not the derivative).
inline double coef(const LocalJet& h, int i, int j) {
  const int d = i + j;
  if (i < 0 || j < 0 || d > kLocalOrder) return 0.0;
  return h[d * (d + 1) / 2 + j];  // graded layout of core/jet.hpp: (d,0), (d-1,1), ..., (0,d)
}
inline void set_coef(LocalJet& h, int i, int j, double c) {
  const int d = i + j;
  h[d * (d + 1) / 2 + j] = c;
}

/// The coefficients of the homogeneous part of degree d: c[j] of s^(d-j) t^j, j = 0..d.
std::vector<double> homogeneous_part(const LocalJet& h, int d);

/// Value, gradient and Hessian of the polynomial h at (s, t).
struct LocalValue {
  double value = 0;
  Vec2 gradient = Vec2::Zero();
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();
};
LocalValue evaluate(const LocalJet& h, const Vec2& st);

/// dh/ds (var 0) or dh/dt (var 1); the coefficients of degree kLocalOrder are unknown and set to 0.
LocalJet partial(const LocalJet& h, int var);

/// h(A (S, T)): the polynomial in new coordinates (S, T) with (s, t) = A (S, T).
LocalJet linear_substitution(const LocalJet& h, const Eigen::Matrix2d& A);

/// h(z + (S, T)): the same polynomial re-expanded about the point z (exact Taylor shift).
LocalJet shifted(const LocalJet& h, const Vec2& z);

/// h(l S, l T) / l: the same germ with lengths in units of l (model units; the coefficient of
/// degree d times l^(d - 1)), so that coefficients of different degrees can be compared
/// (problem/singular_tolerances.hpp kGermLengthRatio).
LocalJet in_germ_units(const LocalJet& h, double length);

/// The germ's own length (model units): min over degrees d > k of |h_d|^(-1 / (d - k)), |h_d| the
/// largest coefficient of degree d, capped at `cap`, for h a product of k gaps in model units (k = 1
/// for a gap; h then has units length^k). At this radius a term of degree d is as large as the
/// product of k distances: the radius of curvature of the surfaces' separation for a quadratic
/// term of a gap, the scale of the germ's features in general. It scales with the model and does
/// not depend on the size of the domains (problem/singular_tolerances.hpp kGermLengthRatio).
double germ_length(const LocalJet& h, double cap, int gap_degree = 1);

/// The largest |coefficient| of degree 2..kLocalOrder (the scale of a singular germ).
double germ_scale(const LocalJet& h);

/// h with every coefficient below `relative * germ_scale(h)` in magnitude set to 0.
LocalJet clean(const LocalJet& h, double relative);

/// Real roots of the binary form sum_j c[j] s^(d-j) t^j as unit directions (cos a, sin a), a in
/// [0, pi) (lines through the origin), sorted by a, each with its multiplicity; roots closer than `cluster` (radians)
/// are merged. `complex_roots` receives the number of non-real roots (counted with multiplicity).
struct FormRoot {
  Vec2 direction;
  int multiplicity = 1;
};
std::vector<FormRoot> binary_form_roots(const std::vector<double>& c, int* complex_roots = nullptr,
                                        int* distinct_roots = nullptr);

}  // namespace ssimarch
