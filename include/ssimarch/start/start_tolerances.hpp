// Tolerances of the start-point stage (start/), each with its unit and why it has its value:
// when a start point counts as lying on a singular point (start/start_points.cpp, regular_start;
// trace/trace_all.cpp, register_singular_start), when two starts are on one curve, and how small
// a ball the certified search may call an isolated point. The tolerances that decide "this point
// is singular" are in problem/singular_tolerances.hpp.
#pragma once

#include <cmath>

namespace ssimarch {

/// The distance (fraction of Tracer::spacing(), dimensionless) below which two curves are taken
/// for one: a start point this close to a traced curve is on it (trace/trace_all.cpp), and the
/// run-away bound counts passes of a branch at least this far apart
/// (trace/branch_length_bound.hpp). A fifth of the spacing: the tracer's points are within the
/// tolerance of the curve, far below it, while two distinct curves closer than a fifth of a step
/// are beyond what the step resolves anyway (they are found by the certified search instead).
inline constexpr double kResolutionFraction = 0.2;

/// Largest radius, relative to max(1, the problem's scale) (model units), of the ball around an
/// isolated point within which the certified start-point search may prove the curve in a box to
/// lie (start/isolated_box.hpp) and call the box decided. An elliptic contact moved apart or
/// together by a relative perturbation delta of the input (rounding: 1e-16) becomes nothing or a
/// loop of radius about sqrt(2 delta / curvature) ~ 1e-8 scale, so no certificate can promise
/// less; 1e-6 leaves two orders of magnitude for the interval enclosures' overestimation while
/// staying far below any marching step (the tracer resolves a loop that small as the point).
inline constexpr double kIsolatedBoxRadius = 1e-6;

/// Radius (model units) within which a start point is on the singular point located from it:
/// scale (tolerance / scale)^(1/4). Along any direction from a singular point of multiplicity m
/// the residual grows like d^m / scale^(m-1) (the local curve's lowest terms, scaled by the
/// model), so within (tolerance scale^(m-1))^(1/m) a point cannot be told from the singular
/// point by the residual the corrector drives to the tolerance; m = 4, the quadruple point, the
/// highest multiplicity the classifier names short of `multiple_point`, gives the largest such
/// radius. Default tolerance 1e-12: 0.0245 for the four-petal rose (scale 71), 0.0101 for the
/// devil's curve (scale 22), whose certified starts lie within 5e-6 of its node.
inline double singular_start_radius(double tolerance, double scale) {
  return scale * std::sqrt(std::sqrt(tolerance / scale));
}

}  // namespace ssimarch
