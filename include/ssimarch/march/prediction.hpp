// What every predictor reads and returns, and the map from a predicted 3D point to the unknowns
// of H (docs/marching.md, "Predictors").
//
// Parameter-space predictors (tangent, taylor) return unknowns directly. The 3D predictors
// (osculating circle, Wu-Andrade circle, Stoyanov parabola, order-3 polynomial, osculating
// helix) build a 3D point Q and map it to unknowns with map_to_unknowns: the first-order map
// through the pseudo-inverse of each surface's point map, then Gauss-Newton foot-point
// iterations (projection of Q onto each parametric surface), so that the mapped guess keeps the
// predictor's order.
#pragma once

#include <array>

#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// What a predictor may use: the curve's jet at the current point (oriented along the
/// direction of travel) and, when there is one, the previous accepted point and its tangent.
struct MarchState {
  DynamicCurveJet here;
  bool has_previous = false;
  UnknownVec previous_x;
  Vec3 previous_p = Vec3::Zero();
  Vec3 previous_t = Vec3::Zero();
  // Seed 000's "reuse t from the previous step" (b = 0): the line parameter of the last circle
  // centre and the coordinate it was measured along; axis -1 when there is none.
  double circle_line_parameter = 0;
  int circle_line_axis = -1;
  // The 3D-to-parameter map stops its foot-point iterations when an update moves the point by
  // <= map_tolerance (model units); the tracer sets it to the corrector tolerance.
  double map_tolerance = 1e-12;
};

/// A guess for the corrector.
struct Prediction {
  UnknownVec x;                 // unknowns to start the corrector from
  Vec3 point = Vec3::Zero();  // the predicted 3D point (point(x) for parameter-space predictors)
  double arc = 0;         // arc length the prediction advances (h, except under the Wu-Andrade angle heuristic)
  bool fallback = false;  // fell back to the tangent step (no previous point, parallel tangents, ...)
  double circle_line_parameter = 0;  // osculating circle: the line parameter used (see MarchState)
  int circle_line_axis = -1;
  std::array<long, 2> evaluations{};  // surface calls spent (first, second)
};

/// The unknowns whose 3D point(s) are the feet of Q on the surfaces, starting from the current
/// unknowns x0: per parametric surface, Gauss-Newton foot-point iterations from x0 (the first is
/// the first-order map dx = D^+ (Q - S(x0))), at most 8, stopping once an update moves the point
/// by <= stop (model units). Implicit-implicit: Q itself. Adds the surface calls to *evaluations.
UnknownVec map_to_unknowns(const Problem& problem, const UnknownVec& x0, const Vec3& Q, double stop, std::array<long, 2>* evaluations);

/// Tangents u, v with |u x v| <= kParallelTangentsSine |u| |v| (about 1e-8 radians apart) are
/// parallel for the circle constructions: the normal planes do not meet in a usable line.
inline constexpr double kParallelTangentsSine = 1e-8;

namespace internal {
/// x + h x'(0): the tangent step, in parameter space.
Prediction tangent_step(const Problem& problem, const MarchState& s, double h);
/// The tangent step, marked as a fallback of a predictor that could not build its curve.
Prediction fallback_step(const Problem& problem, const MarchState& s, double h);
/// The prediction of a 3D predictor: Q mapped to unknowns, advancing `arc`.
Prediction prediction_at(const Problem& problem, const MarchState& s, const Vec3& Q, double arc);
}  // namespace internal

}  // namespace ssimarch
