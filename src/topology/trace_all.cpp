#include "ssimarch/topology/trace_all.hpp"

#include <chrono>

#include "ssimarch/march/predictor.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/topology/certified_start_points.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/topology/start_points.hpp"
#include "ssimarch/topology/tangency_hunt.hpp"
#include "ssimarch/topology/through_singular.hpp"

namespace ssimarch {

namespace {

// The curve of the backward part (points reversed, tangents turned) followed by the forward part
// from its second point on: both parts start at the same point.
void join(const BranchMarch& backward, const BranchMarch& forward, TracedCurve* curve) {
  for (auto it = backward.points.rbegin(); it != backward.points.rend(); ++it)
    curve->points.push_back({it->x, it->p, -it->t});
  curve->points.insert(curve->points.end(), forward.points.begin() + 1, forward.points.end());
  curve->length = forward.length + backward.length;
  curve->start_end = to_termination(backward.event);
  curve->start_message = backward.event.message;
}

// The curve through the seed start, followed through the singular points it meets.
TracedCurve trace_branch_through(const Tracer& tracer, const CurvePoint& start, SingularRegistry* registry, int index,
                                 TraceStats* stats) {
  TracedCurve curve;
  BranchMarch forward = march_branch(tracer, start, &start, registry, index, stats);
  if (forward.closed) {
    curve.points = std::move(forward.points);
    curve.closed = true;
    curve.length = forward.length;
  } else {
    const CurvePoint back{start.x, start.p, -start.t};
    join(march_branch(tracer, back, nullptr, registry, index, stats), forward, &curve);
  }
  curve.end_end = to_termination(forward.event);
  curve.end_message = forward.event.message;
  return curve;
}

// The curve leaving node n along its unused half-branch k, and, unless it closes, the same branch
// on the other side of the node (the half-branch continuing k).
TracedCurve trace_from_half_branch(const Tracer& tracer, SingularRegistry* registry, int n, int k, int index,
                                   TraceStats* stats) {
  auto exit_of = [&](int h) {
    const HalfBranch& b = registry->node(n).branches[static_cast<std::size_t>(h)];
    return CurvePoint{b.exit_x, b.exit_point, b.direction};
  };
  auto from_node = [&](int h) {
    const SingularNode& node = registry->node(n);
    const HalfBranch& b = node.branches[static_cast<std::size_t>(h)];
    BranchMarch m;
    m.points.push_back({node.location.x, node.location.point, b.tangent_3d});
    BranchMarch rest = march_branch(tracer, exit_of(h), nullptr, registry, index, stats, n, h);
    m.points.insert(m.points.end(), rest.points.begin(), rest.points.end());
    m.length = arc_length_estimate(node.location.point, b.tangent_3d, rest.points.front().p, rest.points.front().t) + rest.length;
    m.event = rest.event;
    m.closed = rest.closed;
    return m;
  };
  registry->mark(n, k, index);
  TracedCurve curve;
  BranchMarch forward = from_node(k);
  const int c = registry->node(n).branches[static_cast<std::size_t>(k)].continuation;
  if (forward.closed) {
    curve.points = std::move(forward.points);
    curve.closed = true;
    curve.length = forward.length;
  } else if (c >= 0 && !registry->node(n).used[static_cast<std::size_t>(c)] &&
             registry->node(n).branches[static_cast<std::size_t>(c)].exit_ok) {
    registry->mark(n, c, index);
    join(from_node(c), forward, &curve);
  } else {
    curve.points = std::move(forward.points);
    curve.length = forward.length;
    curve.start_end = Termination::kSingularPoint;
    curve.start_message = "starts at the " + std::string(to_string(registry->node(n).kind.type)) + " at " +
                          describe_point(registry->node(n).location.point);
  }
  curve.end_end = to_termination(forward.event);
  curve.end_message = forward.event.message;
  return curve;
}

}  // namespace

TracedCurve trace_curve_through(const Tracer& tracer, const VecX& x0, TraceStats* stats, SingularRegistry* registry,
                                int index) {
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
  if (registry) {
    curve = trace_branch_through(tracer, start, registry, index, stats);
    for (auto& p : curve.points) p.x = P.wrap(p.x);
    return curve;
  }
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

TraceResult trace_all(const Tracer& tracer, const std::vector<Vec3>& starts, const TraceAllOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const Problem& P = tracer.problem();
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
  SingularRegistry registry(P, 1e-7 * std::max(1.0, P.scale()));
  SingularRegistry* reg = options.through_singular_points ? &registry : nullptr;
  const double radius = 0.2 * tracer.spacing();
  for (const VecX& seed : seeds) {
    const VecX x = regular_start(tracer, seed, &result.warnings);
    if (near_traced_curve(P.point(x), result.curves, radius)) continue;
    if (reg && trace_contact_from(tracer, x, &result.curves, reg)) continue;  // a curve of tangential contact
    result.curves.push_back(trace_curve_through(tracer, x, &result.stats, reg, static_cast<int>(result.curves.size())));
  }
  if (reg && options.hunt_isolated_points)
    hunt_tangencies(tracer, result.start_search, reg, &result.curves, &result.isolated_points);
  if (reg) attach_crossings(reg, &result.curves, radius);
  // Every half-branch leaving a singular point is traced once (nodes may be added meanwhile).
  for (std::size_t n = 0; reg && n < registry.nodes().size(); ++n)
    for (std::size_t k = 0; k < registry.nodes()[n].branches.size(); ++k) {
      if (registry.nodes()[n].used[k] || !registry.nodes()[n].branches[k].exit_ok) continue;
      const int index = static_cast<int>(result.curves.size());
      TracedCurve c = trace_from_half_branch(tracer, &registry, static_cast<int>(n), static_cast<int>(k), index, &result.stats);
      for (auto& p : c.points) p.x = P.wrap(p.x);
      result.curves.push_back(std::move(c));
    }
  if (reg) result.singular_points = registry.reports();
  result.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

TraceResult trace_all(const Problem& problem, const TraceOptions& options, const std::vector<Vec3>& starts,
                      const TraceAllOptions& all) {
  return trace_all(Tracer(problem, options), starts, all);
}

}  // namespace ssimarch
