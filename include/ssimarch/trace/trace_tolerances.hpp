// Tolerances of the tracing stage (trace/) that decide what a traced curve of tangential contact
// may conclude, each with its unit and why it has its value; those of the start-point stage are in
// start/start_tolerances.hpp, those that decide "this point is singular" in
// problem/singular_tolerances.hpp.
#pragma once

namespace ssimarch {

/// |lambda| (lambda = trace Hess h on a curve of tangential contact; dimensionless ratio to its
/// values at the two ends of the bracket) at or below which a sign change of lambda along the
/// contact curve is located as a zero of lambda, a transversal branch crossing the curve
/// (trace/tangential_contact.cpp). At a transversal crossing lambda is linear along the curve
/// and regula falsi drives it to rounding (1e-12 of the ends and below); at a singular point of a
/// surface on the curve (a cone's apex, whose nappes lie on either side of a plane touching it
/// along a generator) lambda changes sign through a pole and |lambda| never falls below its end
/// values. 1e-6 separates the two by orders of magnitude.
inline constexpr double kCrossingLambdaRatio = 1e-6;

/// Arc distance (times the problem's scale) along a contact curve within which a point of it that
/// a march or the hunt located is taken to stand for a crossing (trace/tangential_contact.hpp
/// crossing_near): the trace's registry and `ssimarch singular` look this far both ways.
inline constexpr double kCrossingSearchReach = 0.1;

/// Fall of the Hessian's norm (ratio, dimensionless) that makes a located node a point of
/// multiplicity 3 located off it (trace/singular_registry.cpp): a march along a transversal branch
/// meets a tangent-line crossing a few 1e-9 from it, where h = u^2 v seen from (u0, 0) has the
/// node's form 2 u0 u v; refined where h vanishes to third order (singular/third_order_point.hpp)
/// the Hessian falls to rounding (1e-8 -> 1e-16 on two tori tangent along a circle), while at a
/// true node the refinement's first step leaves the merge radius and nothing falls.
inline constexpr double kThirdOrderHessianFall = 1e-6;

/// Multiple of the corrector's tolerance (model units) within which a start point is on a traced
/// curve where the curve is straight (trace/on_traced_curve.hpp): the start and the curve's points
/// are each within the tolerance of the true curve, and a straight segment's Hermite arc is the
/// segment itself, so a few tolerances separate "the same curve" from "a second component".
inline constexpr double kOnCurveToleranceMultiple = 16;

/// Fraction of a segment's sagitta (chord x turning angle / 8, model units) within which a start
/// point is on the segment's cubic Hermite arc. The arc's error is O(chord^4): on a circle far below
/// the sagitta, but where the curvature itself vanishes (the flat bottom of y = x^4, Ex. 35's
/// tacnode loops) the error of a chord symmetric about the flat point is c^4 / 32 against a
/// sagitta of c^4 / 16: half of it, so the whole sagitta is the bound. A second component closer to
/// the arc than that is not told from the first; two lines or circles 2e-3 apart at the default
/// step (sagitta 5e-4 on a circle of radius 2) are.
inline constexpr double kOnCurveSagittaFraction = 1.0;

/// Turning angle (radians) of a segment above which its Hermite arc is no measure of the curve
/// and a start within the resolution radius of the chord is on the curve, as before the test
/// (trace/on_traced_curve.hpp). The default chordal rule (sagitta 1e-4 of the model) turns by a
/// few hundredths of a radian per step; a coarse constant step on a small loop of varying
/// curvature (Ex. 35's tacnode loops at 0.04 of the model, 0.2-0.3 rad a step) strays from its
/// Hermite arcs by more than a quarter of the sagitta.
inline constexpr double kOnCurveMaxTurn = 0.1;

/// The distance (model units) within which a start point is on a traced segment of this sagitta.
inline double on_curve_distance(double tolerance, double sagitta) {
  return kOnCurveToleranceMultiple * tolerance + kOnCurveSagittaFraction * sagitta;
}

}  // namespace ssimarch
