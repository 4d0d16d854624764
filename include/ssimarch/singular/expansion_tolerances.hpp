// Tolerances of the singular module's series algebra on half-branches and local charts
// (singular/tangent_plane_expansion.cpp, singular/collapsed_row_chart.cpp), each with its unit
// and why it has its value. The tolerances that decide "this point is singular" are in
// problem/singular_tolerances.hpp.
#pragma once

namespace ssimarch {

/// A coefficient of a half-branch's expansion over the tangent plane (singular/
/// tangent_plane_expansion.cpp) at or below this times the sum of the magnitudes of the 3D
/// series' terms of the same order counts as zero (dimensionless: both carry the same units per
/// order). The composition and reversion add and cancel such terms (the Viviani node's X^2 over
/// the tangent plane is 0 from terms of size 1/4), with rounding of a few hundred machine
/// epsilons at order 6; 1e-12 keeps every term that is more than that.
inline constexpr double kTangentPlaneTermZero = 1e-12;

/// A row of a parametric rectangle is collapsed (maps to one point: a cone's apex, a sphere's
/// pole) when 33 equally spaced points of it lie within this times the problem's scale of each
/// other (dimensionless). As surface/degenerate_edges.hpp's kDegenerateEdgeRelative: an exact pole
/// is one point to rounding, a regular row is a curve of non-zero length.
inline constexpr double kCollapsedRowRelative = 1e-12;

/// The height of a surface over the other along a collapsed row vanishes to order m in the
/// distance C from the row (singular/collapsed_row_chart.cpp): its C^m coefficient psi_m(w)
/// counts as zero along the whole row when at most this times the largest C^m coefficient of the
/// surface's own point (dimensionless: both carry the same units). m = 1 where the surface's
/// generators at the point leave the other's tangent plane (a cone's apex); on a smooth pole at a
/// singular point of the curve psi_1 is rounding, ~1e-16 of it.
inline constexpr double kRowOrderZero = 1e-10;

/// A root w of psi(w) = N . F_across(w, row) along a collapsed row is simple (a branch of the
/// intersection leaves the row transversally in the parameters, and is a smooth branch in 3D)
/// when |psi'(w)| is at least this times |F_across(w, row)| (both per unit parameter, so the
/// ratio is the rate, per radian-like unit of the row's parameter, at which the generator turns
/// out of the other surface's tangent plane). Below it the root is double to rounding (a
/// generator touching the other surface: a cusp-like branch) and the chart is not built.
inline constexpr double kSimpleRowRootRatio = 1e-8;

/// Two branch germs from different roots of a collapsed row are one branch of the curve (a smooth
/// curve through a sphere's pole meets the pole's row twice, at w and w + pi) when their tangent
/// lines agree to this (unit vectors) and their offsets Y(X) from that line differ by at most
/// this times rho on the circle of radius rho = 1e-2 times the problem's scale (dimensionless).
/// Both are exact series to rounding, which leaves them ~1e-14 apart; distinct branches sharing
/// their tangent (a tacnode) separate by their curvature or a later term, far above it.
inline constexpr double kSameBranchRelative = 1e-9;

}  // namespace ssimarch
