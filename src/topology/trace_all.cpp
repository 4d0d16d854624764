#include "ssimarch/topology/trace_all.hpp"

#include <chrono>

#include "ssimarch/march/predictor.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/topology/certified_start_points.hpp"
#include "ssimarch/topology/start_points.hpp"

namespace ssimarch {

TracedCurve trace_curve_through(const Tracer& tracer, const VecX& x0, TraceStats* stats) {
  const Problem& P = tracer.problem();
  TracedCurve curve;
  DynamicCurveJet j = curve_jet_dynamic(P, x0, 1);
  ++stats->jet_evaluations;
  stats->add_surface_evaluations(jet_evaluation_cost(P, 1));
  CurvePoint start{x0, P.point(x0), j.tangent()};
  if (j.status != CurveJetStatus::kOk) {
    curve.points.push_back(start);
    curve.start_end = curve.end_end = Termination::kSingularPoint;
    curve.start_message = curve.end_message = "the start point " + describe_point(start.p) + " is a singular point";
    return curve;
  }
  ++stats->points;
  stats->record_iterations(1);
  MarchResult forward = tracer.march_until_event(start, Direction::kForward, tracer.limits(), stats);
  if (forward.event.kind == EventKind::kClosed) {
    curve.points = std::move(forward.points);
    curve.closed = true;
    curve.length = forward.length;
  } else {
    MarchLimits open = tracer.limits();
    open.detect_closure = false;
    MarchResult backward = tracer.march_until_event(start, Direction::kBackward, open, stats);
    for (auto it = backward.points.rbegin(); it != backward.points.rend(); ++it)
      curve.points.push_back({it->x, it->p, -it->t});
    curve.points.insert(curve.points.end(), forward.points.begin() + 1, forward.points.end());
    curve.length = forward.length + backward.length;
    curve.start_end = to_termination(backward.event);
    curve.start_message = backward.event.message;
  }
  curve.end_end = to_termination(forward.event);
  curve.end_message = forward.event.message;
  for (auto& p : curve.points) p.x = P.wrap(p.x);
  return curve;
}

TraceResult trace_all(const Tracer& tracer, const std::vector<Vec3>& starts) {
  const auto t0 = std::chrono::steady_clock::now();
  TraceResult result;
  if (tracer.problem().disjoint()) {  // no intersection is a result (issue 11 item 6)
    result.start_search = {"box", true, 0, 0, {}, "no intersection: the boxes of the two implicit surfaces do not overlap"};
    result.warnings.push_back(result.start_search.note);
    return result;
  }
  if (!starts.empty()) result.start_search.method = "given";
  std::vector<VecX> seeds = starts.empty() ? automatic_start_points(tracer, &result.stats, &result.start_search)
                                           : start_points_near(tracer, starts, &result.stats, &result.warnings,
                                                               &result.failed_starts);
  const double radius = 0.2 * tracer.spacing();
  for (const VecX& seed : seeds) {
    const VecX x = regular_start(tracer, seed, &result.warnings);
    if (near_traced_curve(tracer.problem().point(x), result.curves, radius)) continue;
    result.curves.push_back(trace_curve_through(tracer, x, &result.stats));
  }
  result.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

TraceResult trace_all(const Problem& problem, const TraceOptions& options, const std::vector<Vec3>& starts) {
  return trace_all(Tracer(problem, options), starts);
}

}  // namespace ssimarch
