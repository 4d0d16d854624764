// Whether a start point lies on a curve traced before, decided by the geometry rather than by a
// distance tied to the step (issue 26): two components whose points are farther apart than the
// traced curve's own accuracy are two components. A traced curve is known at its points (within
// the corrector's tolerance) and between them to the accuracy of the cubic Hermite arc through
// two points and their unit tangents, whose error is of higher order than the chord's sagitta
// (O(c^4) against O(c^2) for a chord c; Farin, Curves and Surfaces for CAGD, 5th ed., §7.2; with
// the end derivatives of Goldapp's circle rule, CAGD 8 (1991), exact to O(phi^6) on arcs). A
// start is on the curve when it is within the Hermite arc's accuracy of it; a start within the
// old resolution radius of the chord but farther from the arc (two lines 2e-3 apart, two circles
// of a torus cut 1e-6 below its top) is on another component and is traced.
#pragma once

#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/march/result.hpp"

namespace ssimarch {

/// Whether p lies on one of the curves: within `radius` (model units) of a chord and within
/// on_curve_distance(tolerance, sagitta of that segment) of the segment's cubic Hermite arc.
/// `tolerance`: how well the curve's points are known where p is (model units; the corrector's
/// tolerance over the sine of the angle between the normals, trace_all.cpp).
/// Segments whose tangents are not known (zero or not finite) or that turn by more than
/// kOnCurveMaxTurn (trace/trace_tolerances.hpp) fall back to the chord within `radius`.
bool on_traced_curve(const Vec3& p, const std::vector<TracedCurve>& curves, double radius, double tolerance);

/// Distance from p to the segment [a, b] (the chord of two traced points).
double chord_distance(const Vec3& p, const Vec3& a, const Vec3& b);

/// Distance from p to the cubic Hermite arc of the segment (a, ta) -> (b, tb) (unit tangents in
/// the direction of travel), minimised over the arc's parameter.
double hermite_arc_distance(const Vec3& p, const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb);

}  // namespace ssimarch
