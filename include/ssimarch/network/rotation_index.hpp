// The rotation index of a closed branch (thesis sec. 2.1 Def. 1-2, ch. 6): the number of turns of
// its tangent seen in a plane, the integer the thesis' closing condition for loops is built on.
// Which plane (docs/topology.md "Rotation index"):
//  - a pair with a parametric surface: that surface's parameter plane (u, v), the first two
//    unknowns (for a parametric-parametric pair the scene's first surface; for
//    parametric-implicit the parametric one, as in the thesis' tables);
//  - implicit-implicit: the plane of the two largest principal axes of the curve's points
//    (docs/math/rotation_index_plane.md): no parameter plane exists, and this one depends only
//    on the curve, so it is the same whichever surface comes first.
#pragma once

#include <optional>
#include <string>

#include "ssimarch/march/result.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/march/closure_turning.hpp"  // kRotationMaxChordTurn, kRotationIndexSigma

namespace ssimarch {

struct RotationIndex {
  std::optional<int> index;  // turns of the tangent along the curve's direction of travel
  double turning = 0;        // accumulated signed turning (rad), exterior angles included
  std::string plane;         // "u,v" or "principal axes"
  std::string note;          // why the index is undefined, when it is
};

/// The rotation index of the closed curve c (its last point equals its first) in the plane
/// above: the polygon of its points in the plane (periodic unknowns unwrapped), its signed
/// exterior angles summed, atan2 in (-pi, pi] (Def. 2, eqs 2.15-2.16). `corner` says which
/// point indices lie at singular points (a cusp's reversal is allowed there).
RotationIndex rotation_index(const Problem& problem, const TracedCurve& c, const std::vector<bool>& corner = {});

}  // namespace ssimarch
