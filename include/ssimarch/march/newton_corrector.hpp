// The Newton corrector: Gauss-Newton with the Moore-Penrose pseudo-inverse, x <- x - J^+ H(x),
// the minimum-norm update (Allgower & Georg §3.3; problem/gauss_newton.hpp holds the solve).
#pragma once

#include "ssimarch/problem/gauss_newton.hpp"

namespace ssimarch {

struct NewtonCorrector {
  CorrectorResult correct(const Problem& problem, const UnknownVec& guess, const CorrectorOptions& options) const {
    return gauss_newton(problem, guess, options);
  }
};

}  // namespace ssimarch
