// The longest branch the tracer can follow in a problem's region without running over itself:
// the run-away bound of trace_all (issue 11 item 2, issue 13 item 1), derived from the region's
// size and the tracer's resolution, not a fixed cap (docs/topology.md "Run-away bound").
#pragma once

#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// Cells per parameter direction of the grid that estimates a patch's area (the estimate is
/// doubled, covering the grid's under-estimate of curved cells).
inline constexpr int kAreaGridCells = 64;

/// Upper bound (model units) on the length of one branch whose distinct passes stay at least
/// `resolution` (model units) apart (passes closer than that are the same curve traced again):
/// disjoint strips of width `resolution` around the passes fit in the surface, so
///  - a pair with a parametric surface: L <= 2 A / resolution + D, A the parametric patch's
///    area (the smaller of two), D the problem's scale;
///  - implicit-implicit: disjoint tubes of radius resolution / 2 fit in the box grown by
///    resolution / 2: L <= 4 V / (pi resolution^2) + D.
/// Derivation: docs/math/branch_length_bound.md.
double branch_length_bound(const Problem& problem, double resolution);

}  // namespace ssimarch
