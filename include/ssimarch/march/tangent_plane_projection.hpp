// Seed 000's geometric corrector (seed 000 §2): from the point P0 (the mean of the guess's
// surface points), the nearest points A on F and B on G, the line where their tangent planes
// meet, the projections O1, O2 of A and B onto it, P1 = (O1 + O2)/2; repeat from P1.
//
// Nearest points: Gauss-Newton on |S(u,v) - P|^2 for a parametric surface; for an implicit one
// the Newton projection X <- X - f(X) grad f / |grad f|^2 onto f = 0 (the foot along the
// gradient, which agrees with the nearest point to second order in the distance). The unknowns
// of a round are the feet's parameters (or P1 itself, implicit-implicit); a round counts as one
// iteration and the corrector stops by the convergence rule Newton uses (ConvergenceRule:
// distance from both surfaces, as Linearization::distance, <= tolerance).
#pragma once

#include "ssimarch/problem/gauss_newton.hpp"

namespace ssimarch {

struct TangentPlaneProjection {
  CorrectorResult correct(const Problem& problem, const UnknownVec& guess, const CorrectorOptions& options) const;
};

}  // namespace ssimarch
