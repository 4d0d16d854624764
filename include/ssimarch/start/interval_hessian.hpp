// The residual H of a problem with its first and second derivatives over a box of unknowns, by
// nested forward differentiation (start/gradient.hpp): what the saddle test (saddle_box) and the
// convex function of isolated tangencies (isolated_box) bound their Hessians with.
#pragma once

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/start/krawczyk.hpp"

namespace ssimarch {

/// h[r].v.v = H_r, h[r].d[i].v = dH_r/dx_i, h[r].d[i].d[j] = d2H_r/dx_i dx_j, each enclosing its
/// range over the box.
using IntervalSecond = Gradient<IntervalGradient, kMaxSystemDimension>;

/// H and its derivatives to order 2 over `box` (P.dim() intervals) into h[0 .. P.dim() - 2].
void interval_second_derivatives(const Problem& P, const IntervalBox& box, IntervalSecond* h);

}  // namespace ssimarch
