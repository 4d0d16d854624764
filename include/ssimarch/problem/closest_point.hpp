// Nearest points on a parametric surface and initial unknowns for a 3D point near the curve.
#pragma once

#include <optional>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch {

/// Parameters (u,v) of the point of a parametric surface nearest to X: the best point of a
/// `grid` x `grid` sampling of the domain, then Gauss-Newton on |F(u,v) - X|^2 kept inside the
/// domain (periodic directions wrap). Empty when no sample is finite.
std::optional<Vec2> closest_parameters(const Surface& surface, const Vec3& X, int grid = 24);

/// Same, starting from a known guess (no sampling).
Vec2 refine_closest_parameters(const Surface& surface, const Vec3& X, Vec2 uv);

/// The unknowns x of H whose 3D point(s) are nearest to X: (u,v) of F and (p,q) of G for
/// parametric pairs, X itself for implicit-implicit pairs. Not yet on the curve: correct it.
std::optional<VecX> unknowns_near(const Problem& problem, const Vec3& X);

/// A regular point of the curve about `distance` (model units) from the solution x, for when
/// x is a singular point (rank ratio of J_H below `min_rank_ratio`): Newton from x offset along
/// each unknown in turn (both signs), keeping the first solution whose Jacobian has rank ratio
/// >= min_rank_ratio and whose 3D distance from x is in (0.1, 3] * distance. Empty when none is
/// found (an isolated singular point has no regular neighbours).
std::optional<VecX> regular_point_near(const Problem& problem, const VecX& x, double distance, double tolerance,
                                       double min_rank_ratio = kSuspectSingularRankRatio);

}  // namespace ssimarch
