// Private to singular/: the local curve at a point where a parametric surface without an implicit
// form has a collapsed row (docs/math/singular_local_curve.md §7).
#pragma once

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/local_curve.hpp"

namespace ssimarch {

/// The local curve at x where the parametric surface in `slot` (0: the first, 1: the second of a
/// parametric-parametric pair) has a collapsed row through its point: a whole row of its parameter
/// rectangle (interior or an edge) maps to one point P0 (a cone's apex, a sphere's pole, as an
/// expression or a B-spline patch whose row of control points coincides), P0 lies on the other
/// surface and the other surface is regular there. The chart is the other surface's; h is the
/// product of the equations of the real branches through P0, each a series from the degenerate
/// surface's jets at a root of the row (status kOk). kDegenerate where any of that fails (no
/// collapsed row, P0 off the other surface, no real branch, a branch tangent to the row).
LocalCurve collapsed_row_curve(const Problem& problem, const VecX& x, int slot);

}  // namespace ssimarch
