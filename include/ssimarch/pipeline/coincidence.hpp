// Coincident surfaces: two surfaces that share a region have no intersection curve there, and a
// trace that finds no curve must say so instead of reporting "0 curves" (issue 13). Checked by
// sampling the first surface and measuring each sample's distance from the second.
#pragma once

#include <optional>

#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// The region two surfaces share, as far as the samples show it.
struct Coincidence {
  int samples = 0;         ///< samples of the first surface with a finite distance from the second
  int shared = 0;          ///< of them, within the tolerance of the second surface
  Box region;              ///< bounding box of the shared samples (model length)
  double max_distance = 0; ///< largest distance of a shared sample from the second surface
};

/// Samples `grid` x `grid` points of the first surface (its parameter grid; for an implicit surface,
/// grid^3 points of the problem's box moved onto it by Newton along the gradient) and measures
/// their distance from the second (nearest point of a parametric surface; |g| / |grad g| for an
/// implicit one). Returns the shared region when at least 2 grid samples (more than one row of the
/// grid: a line of tangential contact is not a shared region) lie within `tolerance` (model
/// length) of the second surface, else nothing.
std::optional<Coincidence> find_coincidence(const Problem& problem, double tolerance, int grid = 16);

/// The same test with the roles given: `sampled` is sampled (an implicit one in `box`) and the
/// distances are measured from `other`.
std::optional<Coincidence> find_coincidence(const Surface& sampled, const Surface& other, const Box& box,
                                            double tolerance, int grid = 16);

/// Whether the surfaces share a region, tested before any tracing (issue 28: a rod's B-spline
/// against its hole's, the same cylinder, ran for minutes): a coarse grid of each surface in turn
/// (kCoincidenceProbeGrid^2 samples, so that the smaller one is covered too), and where one finds
/// a shared region, the full test in that order. The region found, or nothing.
std::optional<Coincidence> probe_coincidence(const Problem& problem, double tolerance);

/// Samples per parameter direction of probe_coincidence's coarse grid.
inline constexpr int kCoincidenceProbeGrid = 4;

}  // namespace ssimarch
