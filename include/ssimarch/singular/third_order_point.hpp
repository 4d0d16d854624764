// A point where the intersection's local curve vanishes to third order: where a transversal branch
// crosses a curve of tangential contact (docs/math/tangential_contact.md §3), h = d^2 g with d = 0
// on the contact curve and g = 0 on the branch, and h's whole 2-jet is zero there.
#pragma once

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/analysis.hpp"
#include "ssimarch/singular/locate.hpp"

namespace ssimarch {

/// The point near `guess` where h's Hessian vanishes, by Gauss-Newton on the three Hessian entries
/// with their derivatives from h's cubic part (rank 2 where the branch crosses the contact curve
/// transversally: quadratic convergence), each step on a new local curve. Stops where a step no
/// longer halves the Hessian's norm (rounding); never moves farther than `radius` (model units)
/// from the guess. Returns the best point reached with its gap and sine, `hessian_norm` the norm
/// of h's Hessian there and `initial_hessian_norm` the guess's (model units^-1; infinite where no
/// local curve could be built).
struct ThirdOrderPoint {
  SingularLocation location;
  double hessian_norm = 0;
  double initial_hessian_norm = 0;
};
ThirdOrderPoint third_order_point(const Problem& problem, const SingularLocation& guess, double radius);

/// How far from a located node (model units) a point of multiplicity 3 it stands for may lie: a
/// location accepted at |grad h| <= kLocateSineTolerance lies within sqrt(kLocateSineTolerance)
/// germ lengths of such a point (grad h grows like the distance squared there; resolution_radius
/// of a point of multiplicity 3), and never less than `floor` (the caller's merge distance).
double third_order_reach(const SingularAnalysis& node, double floor);

}  // namespace ssimarch
