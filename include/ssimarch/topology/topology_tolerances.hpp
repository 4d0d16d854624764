// Tolerances of the topology module that decide what a certified computation may conclude near
// singular points (topology/tangential_contact.cpp, topology/isolated_box.hpp), each with its unit
// and why it has its value; the tolerances that decide "this point is singular" are in
// problem/singular_tolerances.hpp.
#pragma once

namespace ssimarch {

/// |lambda| (lambda = trace Hess h on a curve of tangential contact; dimensionless ratio to its
/// values at the two ends of the bracket) at or below which a sign change of lambda along the
/// contact curve is located as a zero of lambda, a transversal branch crossing the curve
/// (topology/tangential_contact.cpp). At a transversal crossing lambda is linear along the curve
/// and regula falsi drives it to rounding (1e-12 of the ends and below); at a singular point of a
/// surface on the curve (a cone's apex, whose nappes lie on either side of a plane touching it
/// along a generator) lambda changes sign through a pole and |lambda| never falls below its end
/// values. 1e-6 separates the two by orders of magnitude.
inline constexpr double kCrossingLambdaRatio = 1e-6;

/// Largest radius, relative to max(1, the problem's scale) (model units), of the ball around an
/// isolated point within which the certified start-point search may prove the curve in a box to
/// lie (topology/isolated_box.hpp) and call the box decided. An elliptic contact moved apart or
/// together by a relative perturbation delta of the input (rounding: 1e-16) becomes nothing or a
/// loop of radius about sqrt(2 delta / curvature) ~ 1e-8 scale, so no certificate can promise
/// less; 1e-6 leaves two orders of magnitude for the interval enclosures' overestimation while
/// staying far below any marching step (the tracer resolves a loop that small as the point).
inline constexpr double kIsolatedBoxRadius = 1e-6;

}  // namespace ssimarch
