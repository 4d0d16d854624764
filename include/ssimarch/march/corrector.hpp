// Correctors pull a predicted point onto the intersection curve.
#pragma once

#include <string_view>

#include "ssimarch/march/problem.hpp"

namespace ssimarch {

enum class CorrectorStatus {
  kConverged,  // distance from both surfaces <= tolerance after `iterations` updates
  kDiverged,   // the distance grew twice in a row, became non-finite, or max iterations passed
  kSingular,   // sigma_min(J_H) <= 1e-14 sigma_max(J_H): no Newton update is defined
};
std::string_view to_string(CorrectorStatus s);

struct CorrectorResult {
  VecX x;
  CorrectorStatus status = CorrectorStatus::kDiverged;
  int iterations = 0;         // Newton updates applied
  double distance = 0;        // final distance estimate (model units)
  int linearizations = 0;     // evaluations of H and J_H
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

/// Newton on the square system [H(x); x_i - value] (n equations): the point of the curve
/// where unknown i equals `value` (used to land exactly on a domain edge).
CorrectorResult solve_with_fixed_unknown(const Problem& problem, const VecX& guess, int i, double value,
                                         const CorrectorOptions& options);

}  // namespace ssimarch
