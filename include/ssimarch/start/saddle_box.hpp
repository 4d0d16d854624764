// Deciding a box around a singular point of the curve without deciding its root (docs/topology.md,
// "Singular points: saddle boxes"). At a singular point the turning systems have a root with a
// singular Jacobian, which no Krawczyk test can prove; the branch and bound leaves a cluster of
// undecided boxes there. A box S around it is still decided, without locating anything, when
//
//   (a) no closed branch lies in S: the curve in S is the zero set of a function of two variables
//       on a disc (h(u, v) itself for a parametric-implicit pair; f restricted to the surface
//       g = 0 for an implicit pair, when g = 0 is proven to be a graph over a face of S), and the
//       Hessian determinant of that function is proven negative on all of S, so it has no local
//       extremum there; a closed branch would bound a disc in S on which it has one (the function
//       vanishes on the loop and not on the whole disc) — so there is none (a node is such a
//       saddle; an isolated point or a tacnode is not, and stays undecided: a perturbation of the
//       input within rounding can create a small loop there);
//   (b) every other piece of the curve in S reaches the boundary of S: the face systems of S
//       (H = 0 with one unknown held at a face of S) are solved for all their roots with
//       certificates; those roots are start points, so every arc through S is traced from them.
//
// Implemented for two unknowns (parametric-implicit) and three (implicit-implicit); four
// (parametric-parametric) would need the reduction to two variables on a proven graph of three
// equations and is not done: such boxes stay undecided.
#pragma once

#include <vector>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/start/krawczyk.hpp"

namespace ssimarch {

struct SaddleBoxResult {
  bool decided = false;         // (a) and (b) above both proven
  bool saddle = false;          // (a) proven
  std::vector<VecX> crossings;  // roots of the face systems: points of the curve on the boundary of S
  long boxes = 0;               // boxes examined by the face systems
};

/// Whether the function of two variables whose zero set is the curve in `box` is proven to have
/// no local extremum there (condition (a)); false where unproven or for four unknowns.
bool saddle_everywhere(const Problem& problem, const IntervalBox& box);

/// Conditions (a) and (b) for `box` (in the unknowns of H, inside their bounds).
SaddleBoxResult decide_saddle_box(const Problem& problem, const IntervalBox& box, const RootSearchOptions& options);

}  // namespace ssimarch
