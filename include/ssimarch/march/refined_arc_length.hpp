#pragma once
// The length of a traced curve to a stated relative error (issue 26 item 4). The points give each
// segment's length with an error estimate (march/arc_length.hpp: the circular-arc estimate, its
// shortfall and what may remain); a segment whose estimate may be off by more than
// kSegmentLengthTolerance of its length is bisected on the curve itself (the curve's point on the
// plane across the middle of each chord, problem/gauss_newton.hpp solve_on_plane) until two
// levels agree. That is where the points do not resolve the curve: next to a cusp, where the
// curvature grows like s^(-1/2) and the circle's estimate of the first segment is off by a fixed
// fraction of its turning, through the tight turns of a narrow loop, across a seam where the
// curvature jumps. Derivation and measurements: docs/marching.md, "Length.".

#include <functional>
#include <optional>
#include <vector>

#include "ssimarch/march/result.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// Relative error a segment's length may keep (dimensionless, default 1e-10): a tenth of the 1e-9
/// a curve's length promises, so that the errors of its segments add up within it.
inline constexpr double kSegmentLengthTolerance = 1e-10;

/// Sine of the angle between the two surfaces' normals (dimensionless, default 1e-8) below which
/// a point gets no tangent n1 x n2: at a singular point, where the curve has two directions, and
/// so close to one that the cross product is rounding. A piece with such an end is measured from
/// the tangent at its other end (the circle through both ends tangent there) or by its chord.
inline constexpr double kRefinementTangentSine = 1e-8;

/// Angle (radians, default 1e-8) within which a listed point's tangent and its normals' n1 x n2
/// must agree for a refined segment's end to keep a tangent (refined_arc_length.cpp, end_tangent).
inline constexpr double kRefinementTangentAgreement = 1e-8;

/// Pieces whose chord is shorter than this many point tolerances (dimensionless, default 1e3) are
/// not split: their points are fixed only to 1e-3 of the chord, so a finer split measures noise.
inline constexpr double kRefinementFloorRatio = 1e3;

/// The points of a refined segment are solved to this fraction of the point tolerance
/// (dimensionless, default 1e-3), with kRefinementExtraIterations more corrector updates than the
/// march allows. Within the point tolerance of both surfaces a point may lie tolerance / sin(alpha)
/// across the curve where the surfaces meet at the angle alpha: next to a cusp 1e-7 off at a
/// tolerance of 2e-12, which moved lengths by 1e-9. Newton's last updates there converge
/// quadratically, so a few more reach the curve itself.
inline constexpr double kRefinementToleranceRatio = 1e-3;
inline constexpr int kRefinementExtraIterations = 8;

/// Where the caller knows the curve better than a chord does: a 3D point near where the curve
/// crosses the plane across the middle of the chord a -> b, or nothing. Next to a singular point
/// the curve's other branches run closer than the chord's sagitta (a ramphoid cusp's two halves
/// X^2 +- X^(5/2) are 2 X^(5/2) apart) and the corrector, started from the middle of the ends'
/// unknowns, may land on either; a half-branch's expansion (trace/trace_all.cpp) starts it on its
/// own.
using CurveGuide = std::function<std::optional<Vec3>(const Vec3& a, const Vec3& b)>;

/// A piece is split again only while its halves' disagreement falls below this fraction
/// (dimensionless, default 3/4) of its parent's, allowing kRefinementStrikes - 1 levels in a row
/// where it does not (default 2: one): on a resolved arc it falls like 2^-5 per level (the circle's
/// error is h^5 kappa'^2 / 1440), next to a cusp like 2^-2; a parent whose estimate agreed with its
/// halves by chance (the cardioid at steps of 1: 1.75e-7, then 4.3e-7 and 1.2e-6 for its halves)
/// is passed; where it keeps not falling the points' own rounding is being measured.
inline constexpr double kRefinementConvergence = 0.75;
inline constexpr int kRefinementStrikes = 2;

/// Per segment (the order of segment_length_estimates; model units): the estimate plus its
/// shortfall where what may remain wrong is within kSegmentLengthTolerance of the segment, else
/// the sum over its bisected pieces. A piece is split while its two halves disagree with it by
/// more than that tolerance of the segment and by at most half of what its parent's halves
/// disagreed (a refinement that does not converge measures noise and stops), never below
/// kRefinementFloorRatio point tolerances; so the work is bounded by log2 of the segment over the
/// floor in depth. Callers keep the estimate for curves of tangential contact (trace_all, the face
/// clip): their normals are parallel everywhere and no point of them can be found on a plane.
std::vector<double> segment_lengths(const Problem& problem, const std::vector<CurvePoint>& points, bool closed,
                                    const CorrectorOptions& corrector, const CurveGuide& guide = {});

/// The sum of segment_lengths (model units).
double curve_length(const Problem& problem, const std::vector<CurvePoint>& points, bool closed,
                    const CorrectorOptions& corrector, const CurveGuide& guide = {});

}  // namespace ssimarch
