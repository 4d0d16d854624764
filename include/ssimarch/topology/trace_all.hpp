// Tracing every curve of a problem: each start point's curve in both directions, skipping
// start points on curves already traced (thesis ch. 1: hunting, tracing, sorting).
#pragma once

#include <vector>

#include "ssimarch/march/tracer.hpp"

namespace ssimarch {

/// The curve through the solution x0, marched forward until an event and, unless it closed,
/// backward from x0 too; points wrapped into the domain, ordered along x0's tangent.
TracedCurve trace_curve_through(const Tracer& tracer, const VecX& x0, TraceStats* stats);

/// Traces every curve through the 3D points `starts` (each near the curve); with no start
/// points, finds start points by sampling the domain (find_start_points) and traces a curve
/// through each one not on a curve already traced (within 0.2 tracer.spacing()).
TraceResult trace_all(const Tracer& tracer, const std::vector<Vec3>& starts = {});

/// The same with a tracer of these options; throws InputError when they are invalid.
TraceResult trace_all(const Problem& problem, const TraceOptions& options, const std::vector<Vec3>& starts = {});

}  // namespace ssimarch
