// The one tolerance of the closed-form sections (docs/math/closed_form_quadrics.md).
#pragma once

namespace ssimarch {

/// Relative size (of the largest coefficient of the conic or of the axial polynomial) below which
/// a closed-form section counts a discriminant, a quadratic term or a squared radius as zero: the
/// surfaces touch (a double line, a double circle, a single point) rather than cross or miss. It
/// decides "tangential", like the thresholds of problem/singular_tolerances.hpp, and sits with
/// them in spirit: the coefficients come from a few products of the inputs, so they carry ~1e-15
/// relative rounding; 1e-10 leaves five orders of margin and is the order at which
/// kCurveJetRankTolerance stops trusting the jets of a near-tangency. Dimensionless.
inline constexpr double kClosedFormDegeneracy = 1e-10;

}  // namespace ssimarch
