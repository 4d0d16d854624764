// The pieces of one march (tracer.cpp), each in its own file: the branch-jump guards and the
// verdict where no step can be taken (step_guards.cpp), landing on the domain edge
// (domain_edge.cpp), and the loop closure test (loop_closure.cpp).
#pragma once

#include "ssimarch/march/options.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"

namespace ssimarch::internal {

/// Angle between two vectors, atan2(|a x b|, a.b), in [0, pi].
double angle_between(const Vec3& a, const Vec3& b);

/// The guards on a corrected point p1 reached from `cur` by a prediction `predicted` that
/// advanced `arc`: the chord |p1 - cur.p| is in [0.25, 1.75] arc, the correction
/// |p1 - predicted| is <= max_correction_ratio arc, and p1 lies ahead of cur (along cur.t).
bool chord_is_plausible(const CurvePoint& cur, const Vec3& p1, const Vec3& predicted, double arc, const TraceOptions& o);

/// The guard on the tangents at both ends of a step: they turn by <= max_turn_angle.
bool turn_is_plausible(const Vec3& t0, const Vec3& t1, const TraceOptions& o);

/// What the middle of a step shows (kMidpointDeviationRatio): the cubic Hermite interpolant
/// of the ends x0, x1 (unknowns) with unit tangents dx0, dx1 (derivatives of the unknowns along
/// the 3D arc, scaled by the 3D chord) at its middle; `deviation` its first-order distance from
/// both surfaces (model units), `rank_ratio` Problem::rank_ratio there.
struct MidpointProbe {
  double deviation = 0;
  double rank_ratio = 1;
};
MidpointProbe probe_midpoint(const Problem& problem, const UnknownVec& x0, const UnknownVec& dx0, const UnknownVec& x1,
                             const UnknownVec& dx1, double chord, TraceStats* stats);

/// The event where no step >= min_step could be taken after `cur` (jet rank ratio `rank_ratio`):
/// kSingularSuspected when J_H or the normals are nearly degenerate there, else kStepUnderflow.
Event stuck_event(const Problem& problem, const CurvePoint& cur, double rank_ratio, double min_step, TraceStats* stats);

/// x1, the corrected point after `cur`, is outside the domain: lands on the first bound the
/// chord cur.x -> x1 crosses (Newton with that unknown fixed), appends the landed point to *r
/// when it differs from cur, and returns the kDomainEdge event.
Event land_on_domain_edge(const Problem& problem, const CurvePoint& cur, const UnknownVec& x1, const CorrectorOptions& co,
                          TraceStats* stats, MarchResult* r);

/// The unknown on whose bound x lies (within 1e-12 relative) while the tangent dx (in the
/// unknowns) points out of the domain across it, or -1. A march starting there ends at once: its
/// first step would leave the domain, and the corrector can put it back on the curve beyond an
/// excursion outside the domain (a step over a stretch the domain does not hold; stress seed 1
/// pair 74).
int bound_left_at(const Problem& problem, const UnknownVec& x, const UnknownVec& dx);

/// The pole whose degenerate edge the chord cur.x -> x1 crosses first (before any other
/// boundary), or nullptr.
const Pole* crossed_pole(const Problem& problem, const std::vector<Pole>& poles, const CurvePoint& cur, const UnknownVec& x1);

/// Whether the march closed: the start lies on the chord cur.p -> p1 within twice the chord's
/// sagitta (from the turn cur.t -> t1) plus `slack` (model units), and the tangents agree.
bool closes_loop(const CurvePoint& start, const CurvePoint& cur, const Vec3& p1, const Vec3& t1, double slack);

}  // namespace ssimarch::internal
