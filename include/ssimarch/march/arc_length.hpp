#pragma once
// The arc length of a traced curve from its points and unit tangents, without new surface
// evaluations: the circular-arc estimate per segment (march/tracer.hpp, arc_length_estimate)
// falls short where the curvature varies or the curve twists; arc_length_shortfall estimates
// that shortfall from the neighbouring segments (derivation: docs/marching.md, "Length.").

#include <vector>

#include "ssimarch/march/result.hpp"

namespace ssimarch {

/// Largest turning angle (radians, default 0.5) of a segment whose neighbours enter the
/// shortfall's curvature differences: beyond it the points do not resolve the curve's turning
/// (a corner, a cusp, a branch point's kink), and the segment gets no correction.
constexpr double kShortfallMaxTurn = 0.5;

/// Sum over the segments (and the closing one if `closed`) of the circular-arc estimate's
/// shortfall h^5/1440 (kappa'^2 - 2 kappa kappa'' + 3 kappa^2 tau^2), with the signed curvature
/// kappa and the torsion tau estimated from the segments' turning angles and osculating planes
/// (model units; 0 for fewer than three segments). Add it to the sum of arc_length_estimate.
double arc_length_shortfall(const std::vector<CurvePoint>& points, bool closed);

/// One segment's length as the points give it: the circular-arc estimate, its shortfall (0 where
/// the window does not resolve the curve) and what may remain wrong of their sum (model units):
/// where a shortfall is added, the next term of its expansion, |shortfall| min(1, Phi^2) with Phi
/// the window's largest turning angle (the expansion is in powers of h kappa <= Phi); where none
/// is, the circle's own correction at that angle, h Phi^2 / 24.
struct SegmentLength {
  double estimate = 0;
  double shortfall = 0;
  double error = 0;
};

/// Per segment, in the order of arc_length_shortfalls.
std::vector<SegmentLength> segment_length_estimates(const std::vector<CurvePoint>& points, bool closed);

/// The length of each segment between consecutive listed points (points i -> i + 1), as the curve
/// records it: its measured TracedCurve::segment_lengths where they match its points, else the
/// estimate plus its shortfall. What the network's edges and the VTP arc length sum, so that they
/// add up to the curve's length.
std::vector<double> recorded_segment_lengths(const TracedCurve& c);

/// The same per segment: entry i belongs to the segment from points[i] to the next point (the
/// last, of a closed curve not repeating its first point, to the closing segment).
std::vector<double> arc_length_shortfalls(const std::vector<CurvePoint>& points, bool closed);

}  // namespace ssimarch
