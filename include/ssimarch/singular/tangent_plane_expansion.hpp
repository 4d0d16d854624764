// A half-branch's Puiseux expansion re-expressed over the common tangent plane at the singular
// point (docs/math/singular_local_curve.md §4, "The expansion frame").
//
// The local curve's chart (s, t) is the tangent plane only to first order where it is linear in
// a parametric surface's parameters: there P(s, t) - P0 = s e1 + t e2 + O(|(s,t)|^2), and the
// surface's own second- and higher-order terms enter the chart coefficients. The reported
// expansion is geometric, the same for every pair kind and parametrisation:
//   X = (P - P0) . T,   W = (P - P0) . (N x T),   W = sum_j c_j X^(j/Q),
// T the half-branch's unit 3D tangent, N the chart's unit normal (the common normal at a singular
// point). Pure series algebra, no iterative solve (so nothing diverges near a sphere's pole): the
// chart expansion W_c(X_c), parametrised X_c = tau^Q, is composed with the chart's exact 3D jet
// P(s, t) to give P(tau); X(tau) = tau^Q (1 + a(tau)) is reverted to tau(sigma) with X = sigma^Q,
// and W(tau(sigma)) read off. For implicit charts P(s, t) = P0 + s e1 + t e2 + w N exactly, so the
// result is the chart expansion itself (to rounding).
#pragma once

#include "ssimarch/singular/local_curve.hpp"
#include "ssimarch/singular/puiseux.hpp"

namespace ssimarch {

/// The expansion `chart` of the half-branch leaving along the unit chart direction `d` (in (s, t),
/// offset along rot90(d)), over the tangent plane of `curve` at its origin, to the same exponent
/// (`max_exponent`, `complete` as in `chart`: the term of exponent e depends only on the chart's
/// terms up to e). Terms below kTangentPlaneTermZero times the 3D series' term of the same order
/// are left out (they vanish: rounding of the composition).
PuiseuxExpansion tangent_plane_expansion(const LocalCurve& curve, const Vec2& d, const PuiseuxExpansion& chart);

}  // namespace ssimarch
