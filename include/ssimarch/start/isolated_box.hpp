// Deciding a box around an isolated point of the curve (docs/math/isolated_box.md). At an
// isolated tangency (two spheres touching, a plane on a torus' outer equator) every system of
// the certified start-point search has a root with a singular Jacobian there, which no Krawczyk
// test proves or excludes: the branch and bound leaves a cluster of undecided boxes around it.
// Such a box S is decided without deciding the root, for every pair kind alike, by one function
// that vanishes on the curve and is proven strictly convex on S:
//
//   Q(x) = sigma l.H(x) + c |H(x)|^2,
//
// l the left singular vector of J_H(x0) for its smallest singular value (the rank drop at the
// located point x0: l = 1 for a parametric-implicit pair, (1, -mu) with grad f = mu grad g for an
// implicit pair, the common normal for a parametric pair), sigma = +-1 and c >= 0 chosen at x0 so
// that Hess Q(x0) is positive definite, which it can be exactly when x0 is an elliptic (isolated)
// tangency. If the interval enclosure of Hess Q over S has its eigenvalues above lambda > 0
// (Gershgorin's discs of V^T [Hess Q] V, V the eigenvectors of Hess Q(x0)), Taylor's theorem from
// x0 on the convex S gives Q(y) >= Q(x0) - |grad Q(x0)| d + lambda d^2 / 2 (d = |y - x0|), so every
// zero of Q in S, and every point of the curve in S, lies within
//
//   r = (|grad Q(x0)| + sqrt(|grad Q(x0)|^2 - 2 lambda Q(x0))) / lambda
//
// of x0 (none at all when the root is imaginary), and Q >= -depth on S with
// depth = G^2 / (2 lambda) - Q(x0). The box is decided when r times a bound on the point map's
// Jacobian over S, the radius in model units, is at most `max_radius`, and the depth in model
// units (Q over |grad (l.H)| at x0: to first order the distance between the surfaces) is at most
// `max_depth`: the surfaces then overlap in S by no more than a gap the tracer treats as a
// contact, and the curve in S is the located point or a loop within `radius` of it (a
// perturbation of the input within rounding makes such a loop; no certificate can say more).
#pragma once

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/start/krawczyk.hpp"

namespace ssimarch {

struct IsolatedBoxResult {
  bool decided = false;  // every point of H = 0 in the box lies within `radius` of point(x0)
  double radius = 0;     // model units; 0 when the box holds no point of the curve at all
  double lambda = 0;     // the proven lower bound of Hess Q's eigenvalues over the box (0: none)
  double depth = 0;      // model units: how far the surfaces can overlap in the box, at most
};

/// Whether every point of the curve in `box` (inside the bounds of the unknowns, holding x0, a
/// located singular point) lies within max_radius of point(x0), the surfaces overlapping there by
/// at most max_depth (both model units), by the test above.
IsolatedBoxResult decide_isolated_box(const Problem& problem, const VecX& x0, const IntervalBox& box, double max_radius,
                                      double max_depth);

}  // namespace ssimarch
