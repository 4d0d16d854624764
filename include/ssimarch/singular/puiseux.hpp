// Puiseux expansion of one half-branch of a plane curve germ h(s, t) = 0 (the local algebraic
// curve of thesis ch. 5 §5.2.3; Wall, "Singular points of plane curves" (2004), ch. 2: Newton
// polygon and Newton-Puiseux algorithm; derivation in docs/math/singular_local_curve.md §4).
//
// In the half-branch's frame, X >= 0 along its unit tangent d and W along rot90(d), the branch is
//   W(X) = sum_j b_j X^(j/q),
// q its multiplicity along d (1 for a smooth branch, 2 for a cusp A2 or a ramphoid cusp A4, ...).
// With X = tau^q the branch is a power series W(tau) solving H(tau^q, W(tau)) = 0,
// H(X, W) = h(X d + W n). The leading term b_p tau^p is a root of the edge polynomial of the Newton
// polygon of H for the slope p/q; every further term is a root of the edge polynomial of the
// Newton polygon of G(tau, V) = H(tau^Q, W_(j-1)(tau) + V) on an edge steeper than the last term
// (once the branch is separated from the others that edge runs from V^0 to V^1 and the term is
// the linear b_j = -r_(j+m) / [H_W]_m); a fractional slope refines tau (Q grows, up to 6). Multiple
// roots (branches still sharing the term) are refined as simple roots of a derivative of the edge
// polynomial, so that the later term that separates them is not swamped by eps^(1/m) errors. The
// expansion stops (truncated) where a term would depend on monomials beyond the jet.
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
/// `through` (X, W) > 0 in the half-branch's frame: a point of it (its crossing of a small circle),
/// which picks the branch wherever several share the terms found so far (a tacnode's or an
/// oscnode's two branches on one side, a ramphoid cusp's two halves): each term is a root of the
/// edge polynomial of the Newton polygon of H(tau^Q, W + V) for the edges steeper than the last
/// term (Wall 2004 §2.1), and the root whose partial sum passes nearest that point is taken.
/// `length` (model units, > 0): the germ length over which the terms are weighed
/// (LocalCurve::germ_length); the expansion is computed for h(length .) / length and returned in
/// model units.
PuiseuxExpansion puiseux_expansion(const LocalJet& h, const Vec2& d, double leading, int p, int q, double order = 6,
                                   const Vec2* through = nullptr, double length = 1.0);

/// p / q: the exponent gamma as a fraction with q <= 4 (gamma = 0, straight within resolution, is 2/1).
std::pair<int, int> exponent_fraction(double gamma);

}  // namespace ssimarch
