// Puiseux expansion of one half-branch of a plane curve germ h(s, t) = 0 (the local algebraic
// curve of thesis ch. 5 §5.2.3; Wall, "Singular points of plane curves" (2004), ch. 2: Newton
// polygon and Newton-Puiseux algorithm; derivation in docs/math/singular_local_curve.md §4).
//
// In the half-branch's frame, X >= 0 along its unit tangent d and W along rot90(d), the branch is
//   W(X) = sum_j b_j X^(j/q),
// q its multiplicity along d (1 for a smooth branch, 2 for a cusp A2 or a ramphoid cusp A4, ...).
// With X = tau^q the branch is a power series W(tau) solving H(tau^q, W(tau)) = 0,
// H(X, W) = h(X d + W n). The leading term b_p tau^p is a root of the edge polynomial of the Newton
// polygon of H for the slope p/q (refined by Newton from the measured leading coefficient); every
// further coefficient is linear: with m the order of H_W(tau^q, W(tau)) and r = H(tau^q, W_(j-1)),
// b_j = -r_(j+m) / [H_W]_m, valid while the residual has no term below j + m (the branch is
// separated from the others); the expansion stops (truncated) where that fails.
#pragma once

#include <utility>
#include <vector>

#include "ssimarch/singular/local_jet.hpp"

namespace ssimarch {

struct PuiseuxTerm {
  double exponent = 0;     // j / q
  double coefficient = 0;  // b_j (model units^(1 - exponent))
};

struct PuiseuxExpansion {
  int denominator = 1;              // q
  std::vector<PuiseuxTerm> terms;   // increasing exponent, zero coefficients left out
  double max_exponent = 0;          // the exponent up to which the terms are complete
  bool complete = false;            // every term up to the requested order was determined
};

/// The expansion of the half-branch of h leaving the origin along the unit tangent `d` (in (s, t))
/// whose leading offset is about `leading` X^(p/q) along rot90(d), up to exponent `order`.
PuiseuxExpansion puiseux_expansion(const LocalJet& h, const Vec2& d, double leading, int p, int q, double order = 6);

/// p / q: the exponent gamma as a fraction with q <= 4 (gamma = 0, straight within resolution, is 2/1).
std::pair<int, int> exponent_fraction(double gamma);

}  // namespace ssimarch
