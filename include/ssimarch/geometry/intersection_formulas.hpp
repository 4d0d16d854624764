// Closed-form differential geometry of the intersection curve of two surfaces at one point,
// from their local derivative data (surface_local.hpp). One function per method of issue 4;
// the formulas and their sources are in docs/geometry.md and next to each definition.
//
// `orientation` (optional, may be null) orients t: t.orientation >= 0. Without it each method
// uses its natural orientation (N_1 x N_2 for the transversal formulas, grad f x grad g for
// Willmore).
#pragma once

#include <vector>

#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/geometry/surface_local.hpp"

namespace ssimarch {

/// Ye-Maekawa, transversal (thesis ch. 3, eqs 3.11-3.15, 3.23-3.25; seed 004 §4 for implicit
/// surfaces):
///   t = unit(N1 x N2), c'' = [(k1 - k2 cos th) N1 + (k2 - k1 cos th) N2] / sin^2 th,
///   c''' = -kappa^2 t + [(l1 - l2 cos th) N1 + (l2 - l1 cos th) N2] / sin^2 th,
///   kappa' = c'''.n, tau = c'''.b / kappa.
/// kSingular where sin(theta) < tol.singular_sin_theta.
CurveGeometry ye_maekawa_transversal(const SurfaceLocal& first, const SurfaceLocal& second,
                                     const Vec3* orientation, const GeometryTolerances& tol = {});

/// Stoyanov (thesis ch. 3, eqs 3.8-3.9): c'' = a1 N1 + a2 N2 from the
/// Gram system [N1.N1 N1.N2; N2.N1 N2.N2] (a1, a2) = (c''.N1, c''.N2). The third derivative is
/// found the same way (its normal-plane part from the Gram system with right-hand side
/// (c'''.N1, c'''.N2), plus -kappa^2 t); the thesis stops at c''. kSingular as above.
CurveGeometry stoyanov(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                       const GeometryTolerances& tol = {});

/// Willmore's operator method for two implicit surfaces (seed 004 §4,
/// eqs 4.7-4.23): h = grad f x grad g, Delta = h.grad, k = h x Delta h, Delta k = h x Delta^2 h,
///   kappa = |k| / |h|^3, c'' = (k x h) / |h|^4, tau = -Delta h . Delta k / |k|^2,
///   kappa' = (k.Delta k / (|k| |h|^3) - 3 |k| (h.Delta h) / |h|^5) / |h|
/// (the last: Delta applied to eq 4.14, divided by |h| = ds/dparameter). kSingular where
/// sin(theta) < tol.singular_sin_theta.
CurveGeometry willmore(const ImplicitLocal& f, const ImplicitLocal& g, const Vec3* orientation,
                       const GeometryTolerances& tol = {});

/// The tangent directions and curvatures of the branches through a tangential point (normals
/// parallel, contact of order one), Ye-Maekawa (thesis ch. 3, tangential case,
/// eqs 3.1-3.6 and 3.16-3.22 with the corrections in docs/geometry.md):
///  * direction(s): (II_1 - II_2)(t, t) = 0 in the common tangent plane (eq 3.2);
///  * curvature vector c'' = k N + g m (m = N x t) with k = II_1(t,t) = II_2(t,t), c''.t = 0
///    (eq 3.22) and g from equal third normal derivatives c'''.N on both surfaces (eq 3.21).
/// For two parametric surfaces this is computed literally with the thesis' a_ij, b_ij and
/// (u'', v'') system (ye_maekawa_tangential_thesis); otherwise in an orthonormal basis of the
/// tangent plane, which is the same equations written without parameters.
/// Returns the branches (status kTangentialSecondOrder, or kZeroCurvature), or one entry with
/// status kIsolatedPoint / kHigherOrderContact / kNonFinite. Each branch's t is oriented by
/// `orientation` when given.
std::vector<CurveGeometry> ye_maekawa_tangential(const SurfaceLocal& first, const SurfaceLocal& second,
                                                 const Vec3* orientation, const GeometryTolerances& tol = {});

/// The thesis' own parametric form of the tangential formulas (eqs 3.3-3.6, 3.16-3.22 with
/// b12 without the factor 2, a13 with the corrected sign, eq 3.18's second line corrected).
std::vector<CurveGeometry> ye_maekawa_tangential_thesis(const ParametricLocal& first,
                                                        const ParametricLocal& second,
                                                        const Vec3* orientation,
                                                        const GeometryTolerances& tol = {});

/// Ye-Maekawa as the option `ye-maekawa` runs it: transversal where sin(theta) >=
/// tol.singular_sin_theta, else the tangential branch whose tangent is closest to
/// `orientation` (the first branch without one).
CurveGeometry ye_maekawa(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                         const GeometryTolerances& tol = {});

/// The unit tangent alone, as the estimate needs it at every sample: unit(N1 x N2) (eq 2.19)
/// at transversal points, the tangential branch closest to `orientation` (eq 3.6) otherwise.
/// Returns a NaN vector where no direction exists.
Vec3 intersection_tangent(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                          const GeometryTolerances& tol = {});

}  // namespace ssimarch
