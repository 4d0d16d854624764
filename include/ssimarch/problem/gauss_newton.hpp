// Solving H(x) = 0 near a guess: Gauss-Newton with the Moore-Penrose pseudo-inverse (the
// minimum-norm update; Allgower & Georg, Numerical Continuation Methods, §3.3), Newton on a
// square system with one unknown fixed, and the convergence rule every corrector shares.
#pragma once

#include <array>
#include <limits>
#include <string_view>

#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

enum class CorrectorStatus {
  kConverged,  // distance from both surfaces <= tolerance after `iterations` updates
  kDiverged,   // the distance grew twice in a row, became non-finite, or max iterations passed
  kSingular,   // newton: rank ratio of J_H <= kNewtonRankRatio: no Newton update is defined;
               // projection: the tangent planes are parallel, |n_F x n_G| <= kParallelPlanesSinTheta
               // (problem/singular_tolerances.hpp)
};
std::string_view to_string(CorrectorStatus s);

struct CorrectorResult {
  UnknownVec x;
  // point(x) from the linearisation that judged x converged (so the caller need not evaluate
  // the surface again); NaN unless status is kConverged.
  Vec3 point = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  CorrectorStatus status = CorrectorStatus::kDiverged;
  int iterations = 0;         // updates applied
  double distance = 0;        // final distance estimate (model units)
  int linearizations = 0;     // evaluations of H and J_H
  std::array<long, 2> evaluations{};  // calls of the first and second surface (any order)
};

struct CorrectorOptions {
  double tolerance = 1e-12;  // model units
  int max_iterations = 12;
};

/// The convergence rule of every corrector: after each update, judge the linearization at the
/// new point. Converged when its distance is <= tolerance; diverging when the distance is not
/// finite or grew twice in a row (the CorrectorStatus::kDiverged conditions).
class ConvergenceRule {
 public:
  enum class Verdict { kConverged, kContinue, kDiverging };
  explicit ConvergenceRule(double initial_distance) : previous_(initial_distance) {}
  /// Counts L (one linearization, one call of each surface) in *r, records its distance, and
  /// sets r->status = kConverged when it is.
  Verdict judge(const Linearization& L, const CorrectorOptions& options, CorrectorResult* r);

 private:
  double previous_;
  int growth_ = 0;
};

/// Gauss-Newton x <- x - J^+ H(x) from `guess`. At least one update is applied, so a point's
/// iteration count is >= 1 and its residual is that of a corrected point.
CorrectorResult gauss_newton(const Problem& problem, const UnknownVec& guess, const CorrectorOptions& options);

/// The one equation that, added to H(x) = 0, makes the system square and picks one point of the
/// curve: an unknown fixed at a value (a parameter bound), or the point on a plane
/// normal . point(x) = offset (a trim's face, the plane beyond a pole).
struct SideCondition {
  enum class Kind { kFixedUnknown, kPlane };
  Kind kind = Kind::kFixedUnknown;
  int unknown = 0;              ///< kFixedUnknown: which
  Vec3 normal = Vec3::UnitZ();  ///< kPlane: unit normal
  double value = 0;             ///< the unknown's value, or the plane's offset (model units)

  static SideCondition fixed_unknown(int i, double value) { return {Kind::kFixedUnknown, i, Vec3::UnitZ(), value}; }
  static SideCondition plane(const Vec3& normal, double offset) { return {Kind::kPlane, 0, normal, offset}; }
};

/// Newton on the square system [H(x); c(x)] with c the side condition (Jacobian [J_H; grad c]):
/// converged when the linearization's distance and, for a plane, |normal . point - offset| are
/// both <= tolerance after at least one update (a fixed unknown is linear: each update keeps it to
/// rounding, so only the distance is judged). `polish`: one update more past convergence, for a
/// curve meeting the plane at a shallow angle, whose point along the curve is fixed only to
/// residual / sin(angle); the extra step of a quadratically converging iteration brings it to
/// rounding, so both surface orders land on one point. kSingular when the square Jacobian is.
CorrectorResult constrained_newton(const Problem& problem, const UnknownVec& guess, const SideCondition& side,
                                   const CorrectorOptions& options, bool polish = false);

/// constrained_newton with unknown i fixed at `value` (starting from the guess with x_i = value):
/// the point of the curve on a domain edge.
CorrectorResult solve_with_fixed_unknown(const Problem& problem, const UnknownVec& guess, int i, double value,
                                         const CorrectorOptions& options);

/// constrained_newton on the plane normal . point = offset, polished: the point of the curve on a
/// trim's face (docs/math/poles.md §2) or on the plane beyond a pole.
CorrectorResult solve_on_plane(const Problem& problem, const UnknownVec& guess, const Vec3& normal, double offset,
                               const CorrectorOptions& options);

}  // namespace ssimarch
