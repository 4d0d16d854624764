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

/// Newton on the square system [H(x); x_i - value] (n equations): the point of the curve
/// where unknown i equals `value` (used to land exactly on a domain edge).
CorrectorResult solve_with_fixed_unknown(const Problem& problem, const UnknownVec& guess, int i, double value,
                                         const CorrectorOptions& options);

}  // namespace ssimarch
