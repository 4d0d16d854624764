// Cheap, rigorous exclusions for the certified search of a parametric-parametric pair
// (start/certified_start_points.hpp). A point (u, v, p, q) of the curve has F(u, v) = G(p, q),
// so a box U x V x P x Q holds none when the patches F(U x V) and G(P x Q) provably do not meet:
//   * implicit forms: F(U x V) misses G's implicit form (the enclosure of f_G(F(U, V)) misses
//     [-slack, slack], slack = kImplicitFormSlack x scale, the forms' rounding disagreement), or
//     G(P x Q) misses F's, when the surfaces have them (every primitive does);
//   * separating axes: the projections d . F(U x V) and d . G(P x Q) are disjoint, for d the line
//     between the patches' middles and for each patch's normal there (the separating-axis test
//     of oriented bounding boxes; Gottschalk, Lin & Manocha, "OBBTree", SIGGRAPH 1996).
//
// Why: the value test excludes H = F - G componentwise, only when the patches' world-axis boxes
// are disjoint; a rotated frame makes those boxes up to sqrt(3) times wider than the patch, and
// two surfaces that come close without meeting (nested spheres) then need small patches of both,
// a number of 4D boxes that grows as the product of the patch counts (stress seed 12 pair 4236:
// 20,502 boxes, budget spent, not certified). The implicit test decides a box by one 2D patch.
// Every enclosure is the natural interval extension intersected with the mean-value form
// s(m) + grad s(X) . (X - m) (Moore, Kearfott & Cloud, Introduction to Interval Analysis, 2009,
// §6.4; Neumaier, Interval Methods for Systems of Equations, 1990, §2.3), which shrinks with the
// patch where the natural one stalls at the dependency effect of the rotated frame.
#pragma once

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/start/interval_number.hpp"

namespace ssimarch {

/// Whether the tests apply: a parametric-parametric pair whose surfaces both evaluate on
/// intervals (the implicit one needs an implicit form of the other surface as well).
bool patch_exclusion_applies(const Problem& P);

/// Whether the box x[0..3] of (u, v, p, q) provably holds no point of the curve by one of the
/// tests above. Requires patch_exclusion_applies(P).
bool patches_cannot_meet(const Problem& P, const IntervalNumber* x);

/// Whether the hunt's singular-point test applies: the first surface parametric and the second
/// with an implicit form (parametric-implicit, or parametric-parametric with an implicit G),
/// both evaluating on intervals.
bool singular_exclusion_applies(const Problem& P);

/// Whether the patch U x V of the first surface provably holds no singular point of the curve: at
/// one, F(u, v) lies on G (f_G o F = 0) and G's normal is F's (grad f_G . F_u = grad f_G . F_v =
/// 0, the two partials of f_G o F), so one interval evaluation of f_G o F with its gradient (the
/// gap and sin(theta) bounds of docs/singular.md) excludes the patch when any of the three misses
/// 0 (by kImplicitFormSlack, relative). A patch not excluded is halved, at most `depth` times
/// along each path. Requires singular_exclusion_applies(P).
bool patch_holds_no_singular_point(const Problem& P, const IntervalNumber& u, const IntervalNumber& v, int depth);

}  // namespace ssimarch
