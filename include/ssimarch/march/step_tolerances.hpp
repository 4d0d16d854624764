// The tolerances of the middle-of-step probe (march/step_guards.cpp, probe_midpoint), which every
// step of the tracer passes: a branch-jump guard and the watch for singular points that a chord
// passes without reversing the tangent orientation (docs/marching.md, "The step's middle").
// Both dimensionless. The tolerances that decide "singular" at a point are in
// problem/singular_tolerances.hpp.
#pragma once

namespace ssimarch {

/// The middle of every step is probed (march/step_guards.cpp, probe_midpoint): the cubic Hermite
/// interpolant of the step's ends and unit tangents (in the unknowns, tangents scaled by the
/// chord) at its middle. On one smooth arc that turns by at most max_turn_angle (0.6 rad) this
/// point lies within 0.002 chord of the curve (a circular arc of angle phi: R (1 - cos(phi/2)) -
/// R sin^2(phi/2) / 2 = R phi^4 / 384 + ..., 0.0017 chord at 0.6 rad, 0.03 chord at pi/2); a step
/// whose probe is farther than this fraction of its chord from both surfaces (first-order
/// distance, model units over model units) did not follow one arc: it jumped to another branch
/// (a petal of the four-petal rose at a step of scale/25) and is rejected like a step that
/// turned too far. Dimensionless.
inline constexpr double kMidpointDeviationRatio = 1.0 / 16;

/// Ratio below which the rank ratio at a step's probed middle, against the smaller of its values
/// at the two ends, means that a singular point lies near the chord (a watched march stops there
/// and locates, MarchLimits::watch_crossings). Along one regular arc the rank ratio varies
/// smoothly and over a step it is close to linear, so its middle value is about the mean of the
/// ends; a fall to half the smaller end needs a zero of the ratio within about a step, i.e. a
/// singular point the chord passes: a triple point along one of its branches (the ratio falls
/// like s^2 and keeps its sign, so the orientation does not reverse), or the quadruple point of
/// the four-petal rose passed by a long step on a smooth branch (s^3). Dimensionless.
inline constexpr double kRankDipRatio = 0.5;

/// Relative margin by which the rank ratio at a watched point must lie below its neighbours'
/// values to count as a local minimum (MarchLimits::watch_crossings, kWatchRankRatio). Along a
/// curve on which the ratio is constant (a circle where a plane cuts a torus 1e-6 below its top:
/// the ratio is 1.4e-3 all round) rounding alone makes every other point a "minimum", and each
/// one cost a failed location with order-12 jets (13 s instead of 0.6 s for that circle). The
/// rounding of the ratio is ~1e-13 relative (unit normals of error ~1e-16 crossed, points within
/// the point tolerance); a true minimum near a tacnode passed at distance d with steps h differs
/// from its neighbours by h^2 / d^2 (the ratio grows like d^2 + s^2), which stays above this
/// margin for every pass within 1000 steps of the point. Dimensionless.
inline constexpr double kRankMinimumMargin = 1e-6;

}  // namespace ssimarch
