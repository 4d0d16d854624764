// The differential geometry of an intersection curve at a singular point, along one of its
// half-branches (issue 10 item 6: the `mixed` method uses the located singular point and its
// half-branch tangents there, not the degenerate closed-form formulas, which divide by
// sin^2(theta) = 0). The branch is the Puiseux expansion of its offset in the tangent plane,
// W(X) = sum b_j X^(j/q) (singular/puiseux.hpp), lifted to 3D by the jet of the first surface's
// point P(s, t) (singular/local_curve.hpp): for q = 1 the space curve X -> P(X d + W(X) n) is
// smooth and regular at X = 0 and frenet_from_derivatives gives t, n, b, kappa, tau, kappa';
// for q > 1 (a cusp-like half-branch) only its tangent exists and kappa is infinite.
#pragma once

#include <optional>

#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

struct BranchGeometry {
  VecX x;                   // the located singular point's unknowns
  CurveGeometry geometry;   // along the chosen half-branch, t pointing away from the point
};

/// The singular point within `reach` (model units) of the curve point x, located to full
/// precision, and the geometry along its half-branch whose tangent is closest to `toward`
/// (the first half-branch when null); nullopt when there is none (x is regular, a near miss,
/// an isolated point).
std::optional<BranchGeometry> singular_branch_geometry(const Problem& problem, const VecX& x, const Vec3* toward,
                                                       double reach);

}  // namespace ssimarch
