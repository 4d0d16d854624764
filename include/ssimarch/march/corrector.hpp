// Correctors pull a predicted point onto the intersection curve.
#pragma once

#include <array>
#include <string_view>
#include <variant>

#include "ssimarch/march/options.hpp"
#include "ssimarch/march/problem.hpp"

namespace ssimarch {

enum class CorrectorStatus {
  kConverged,  // distance from both surfaces <= tolerance after `iterations` updates
  kDiverged,   // the distance grew twice in a row, became non-finite, or max iterations passed
  kSingular,   // newton: sigma_min(J_H) <= 1e-14 sigma_max(J_H): no Newton update is defined;
               // projection: the tangent planes are parallel, |n_F x n_G| <= 1e-14
};
std::string_view to_string(CorrectorStatus s);

struct CorrectorResult {
  VecX x;
  CorrectorStatus status = CorrectorStatus::kDiverged;
  int iterations = 0;         // Newton updates applied
  double distance = 0;        // final distance estimate (model units)
  int linearizations = 0;     // evaluations of H and J_H
  std::array<long, 2> evaluations{};  // calls of the first and second surface (any order)
};

struct CorrectorOptions {
  double tolerance = 1e-12;  // model units
  int max_iterations = 12;
};

/// Gauss-Newton with the Moore-Penrose pseudo-inverse: x <- x - J^+ H(x), the minimum-norm
/// update (spec/architecture.md; Allgower & Georg §3.3). At least one update is applied, so
/// a point's iteration count is >= 1 and its residual is that of a corrected point.
struct NewtonCorrector {
  CorrectorResult correct(const Problem& problem, const VecX& guess, const CorrectorOptions& options) const;
};

/// Seed 000's geometric corrector (spec/circular-step.md §1): from the point P0 (the mean of
/// the guess's surface points), the nearest points A on F and B on G, the line where their
/// tangent planes meet, the projections O1, O2 of A and B onto it, P1 = (O1 + O2)/2; repeat from
/// P1. Nearest points: Gauss-Newton on |S(u,v) - P|^2 for a parametric surface; for an implicit
/// one the Newton projection X <- X - f(X) grad f / |grad f|^2 onto f = 0 (the foot along the
/// gradient, which agrees with the nearest point to second order in the distance). The unknowns
/// of a round are the feet's parameters (or P1 itself, implicit-implicit); a round counts as
/// one iteration and the corrector stops when their distance from both surfaces (as
/// Linearization::distance) is <= tolerance, the same test as newton's.
struct ProjectionCorrector {
  CorrectorResult correct(const Problem& problem, const VecX& guess, const CorrectorOptions& options) const;
};

using AnyCorrector = std::variant<NewtonCorrector, ProjectionCorrector>;
AnyCorrector make_corrector(const TraceOptions& options);
CorrectorResult correct(const AnyCorrector& c, const Problem& problem, const VecX& guess, const CorrectorOptions& options);

/// Newton on the square system [H(x); x_i - value] (n equations): the point of the curve
/// where unknown i equals `value` (used to land exactly on a domain edge).
CorrectorResult solve_with_fixed_unknown(const Problem& problem, const VecX& guess, int i, double value,
                                         const CorrectorOptions& options);

}  // namespace ssimarch
