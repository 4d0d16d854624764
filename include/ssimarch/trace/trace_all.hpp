// Tracing every curve of a problem: each start point's curve in both directions, skipping
// start points on curves already traced (thesis ch. 1: hunting, tracing, sorting).
#pragma once

#include <vector>

#include "ssimarch/march/tracer.hpp"
#include "ssimarch/trace/result.hpp"
#include "ssimarch/start/start_tolerances.hpp"
#include "ssimarch/trace/singular_registry.hpp"

namespace ssimarch {

/// How trace_all treats singular points (issue 10).
struct TraceAllOptions {
  // Locate the singular points the curves meet, pass through them along the continuing
  // half-branch (trace/through_singular.hpp) and trace every half-branch once; report them in
  // TraceResult::singular_points. Off: curves stop next to singular points (the plain tracer).
  bool through_singular_points = true;
  // Hunt the isolated points (TraceResult::isolated_points) and the curves of tangential
  // contact that no traced curve met (trace/tangency_hunt.hpp): only inside the certified
  // search's uncertain regions, none after a fully certified search, a grid over the domain
  // (parametric-implicit pairs) after sampling. Needs through_singular_points.
  bool hunt_isolated_points = true;
};

/// The curve through the solution x0, marched forward until an event and, unless it closed,
/// backward from x0 too; points wrapped into the domain, ordered along x0's tangent. With a
/// registry, the curve passes through the singular points it meets (recorded there as met by
/// curve `index`). With `join_at`, a march that comes within join_radius (model units) of one of
/// those curves stops there (Termination::kReachedTracedCurve): trace_all passes the loose ends
/// of curves traced before, which the new curve then continues.
TracedCurve trace_curve_through(const Tracer& tracer, const VecX& x0, TraceStats* stats,
                                SingularRegistry* registry = nullptr, int index = 0,
                                const std::vector<TracedCurve>* join_at = nullptr, double join_radius = 0);

/// Traces every curve through the 3D points `starts` (each near the curve); with no start
/// points, finds start points by sampling the domain (find_start_points) and traces a curve
/// through each one not on a curve already traced (within kResolutionFraction tracer.spacing());
/// then (options) every half-branch leaving a singular point that no curve followed yet. A trace
/// that reaches a loose end of a curve traced before (an open end that stopped away from the
/// boundary and from located singular points) stops there and continues that curve (closing it
/// when it reaches both of its loose ends): one branch is one curve.
/// Each curve starts along the tangent whose largest component is positive, so that its
/// direction does not depend on the order of the two surfaces. Every march is bounded by max_length and by the run-away
/// bound branch_length_bound(problem, kResolutionFraction spacing); an end stopped by the latter says so in its message
/// (Termination::kMaxLength) and is a failure of the curve network.
TraceResult trace_all(const Tracer& tracer, const std::vector<Vec3>& starts = {}, const TraceAllOptions& options = {});

/// The same with a tracer of these options; throws InputError when they are invalid.
TraceResult trace_all(const Problem& problem, const TraceOptions& options, const std::vector<Vec3>& starts = {},
                      const TraceAllOptions& all = {});

}  // namespace ssimarch
