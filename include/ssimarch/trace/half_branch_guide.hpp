#pragma once
// The curve next to a singular point as its half-branches' expansions give it, for the length's
// refinement (march/refined_arc_length.hpp, CurveGuide): over the common tangent plane each
// half-branch is W(X) = sum b_j X^(j/q) (singular/half_branches.hpp, `expansion`), exact to
// X^(7/q) where the chord's middle is only within its sagitta, X^2 kappa / 8.

#include <vector>

#include "ssimarch/march/refined_arc_length.hpp"
#include "ssimarch/trace/singular_registry.hpp"

namespace ssimarch {

/// Both ends of a chord must lie within this fraction of the chord (dimensionless, default 1e-3)
/// of a half-branch's expansion (across the tangent, in the tangent plane) for the expansion to
/// place the chord's middle: a chord on another branch, or farther out than the expansion holds,
/// keeps the plain guess.
inline constexpr double kHalfBranchGuideFit = 1e-3;

/// The expansion's point must lie within this fraction of the chord (dimensionless, default 1/4)
/// of the chord's middle: the expansion lies in the common tangent plane, off the curve by its
/// normal curvature times X^2, which near the point is below the chord's own sagitta and farther
/// out is not.
inline constexpr double kHalfBranchGuideReach = 0.25;

/// A CurveGuide over the analysed nodes (copied): for a chord whose ends both lie on one
/// half-branch's expansion (the nearest, within kHalfBranchGuideFit), the expansion's point halfway
/// between their X.
CurveGuide half_branch_guide(const std::vector<SingularNode>& nodes);

}  // namespace ssimarch
