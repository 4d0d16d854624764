#include "ssimarch/topology/through_singular.hpp"

#include <algorithm>
#include <optional>

namespace ssimarch {

namespace {

// Singular points one branch may pass through (a bound on the loop, far above any example).
constexpr int kMaxPassages = 1000;

Event stop(EventKind kind, const std::string& message) { return Event{kind, BudgetBound::kNone, message, VecX{}}; }

// Drops trailing points of the last march (after index `begin`) that lie beyond the located
// point s along their own tangent; the length loses their segments.
void trim_beyond(const Vec3& s, std::size_t begin, BranchMarch* out) {
  auto& pts = out->points;
  while (pts.size() > begin + 1 && (s - pts.back().p).dot(pts.back().t) <= 0) {
    const CurvePoint& a = pts[pts.size() - 2];
    out->length -= arc_length_estimate(a.p, a.t, pts.back().p, pts.back().t);
    pts.pop_back();
  }
}

// The located singular point near the end of a march stopped by kSingularSuspected, if any:
// located from the middle of the reversed step (a crossing) or from the last point (stuck).
bool locate_near(const Tracer& tracer, const CurvePoint& last, const Event& event, SingularLocation* loc) {
  const Problem& P = tracer.problem();
  const bool crossing = event.beyond.size() > 0;
  const VecX guess = crossing ? VecX(last.x + 0.5 * P.difference(last.x, event.beyond)) : last.x;
  *loc = locate_singular_point(P, guess);
  const double chord = crossing ? (P.point(event.beyond) - last.p).norm() : 0.0;
  const double reach = std::max(2 * chord, tracer.options().step_length);
  return loc->status == LocateStatus::kConverged && P.inside(loc->x, 1e-9) && (loc->point - last.p).norm() <= reach;
}

// Options whose steps are at most `cap` (model units): after a near miss the march retakes the
// stretch with steps short enough to follow the curve itself, since the step that reversed the
// orientation may have jumped to a nearby arc (two arcs 0.0365 apart in the double eight at
// 0.917); retaking the same step would repeat that jump. None when cap is below what the options
// admit (then the step is a sharp smooth turn resolved to min_step: it is taken unwatched).
std::optional<TraceOptions> short_steps(const Tracer& tracer, double cap) {
  TraceOptions o = tracer.options();
  if (!(cap > 10 * o.min_step)) return std::nullopt;
  o.step_length = std::min(o.step_length, cap);
  o.min_step_length = std::min(o.min_step_length, 0.5 * o.step_length);
  std::string error;
  if (!o.is_valid(&error)) return std::nullopt;
  return o;
}

}  // namespace

BranchMarch march_branch(const Tracer& tracer, const CurvePoint& start, const CurvePoint* close_at,
                         SingularRegistry* registry, int curve, TraceStats* stats, int from_node, int from_half) {
  const MarchLimits base = tracer.limits();
  const Problem& P = tracer.problem();
  BranchMarch out;
  out.points.push_back(start);
  CurvePoint from = start;
  bool unwatched_first = false;
  std::optional<Tracer> fine;  // short steps over the stretch of a near miss
  double fine_length = 0;
  for (int passage = 0;; ++passage) {
    MarchLimits limits = base;
    limits.watch_crossings = true;
    limits.skip_first_watch = unwatched_first;
    limits.close_at = close_at;
    limits.detect_closure = close_at != nullptr;
    limits.max_points = std::max<long>(2, base.max_points - static_cast<long>(out.points.size()) + 1);
    limits.max_length = std::max(0.0, base.max_length - out.length);
    if (fine) limits.max_length = std::min(limits.max_length, fine_length);
    MarchResult r = (fine ? *fine : tracer).march_until_event(from, Direction::kForward, limits, stats);
    const std::size_t begin = out.points.size() - 1;  // index of `from`
    out.points.insert(out.points.end(), r.points.begin() + 1, r.points.end());
    out.length += r.length;
    out.event = r.event;
    out.closed = r.event.kind == EventKind::kClosed;
    unwatched_first = false;
    if (fine && r.event.kind == EventKind::kBudget && out.length < base.max_length) {
      fine.reset();  // the stretch is passed: back to the options' steps
      from = out.points.back();
      continue;
    }
    if (r.event.kind != EventKind::kSingularSuspected || passage >= kMaxPassages) return out;
    SingularLocation loc;
    if (!locate_near(tracer, out.points.back(), r.event, &loc)) {
      if (r.event.beyond.size() == 0) return out;  // stuck, and no singular point there
      // A near miss: the orientation reversed (or the rank ratio dipped) without a singular point.
      from = out.points.back();
      const double chord = (P.point(r.event.beyond) - from.p).norm();
      fine.reset();
      if (auto o = short_steps(tracer, 0.25 * chord)) fine.emplace(P, *o);
      fine_length = 2 * chord;
      unwatched_first = !fine;
      continue;
    }
    fine.reset();
    const int n = registry->add(loc);
    loc = registry->node(n).location;  // the registry may have moved it (onto a tangent-line crossing)
    trim_beyond(loc.point, begin, &out);
    const CurvePoint last = out.points.back();
    const int in = registry->arriving_half_branch(n, last);
    registry->mark(n, in, curve);
    const SingularNode& node = registry->node(n);
    const std::string what = std::string(to_string(node.kind.type)) + " at " + describe_point(loc.point);
    const Vec3 t_in = in >= 0 ? Vec3(-node.branches[static_cast<std::size_t>(in)].tangent_3d) : last.t;
    const int k = in >= 0 ? node.branches[static_cast<std::size_t>(in)].continuation : -1;
    out.length += arc_length_estimate(last.p, last.t, loc.point, t_in);
    out.points.push_back({loc.x, loc.point, k >= 0 ? node.branches[static_cast<std::size_t>(k)].tangent_3d : t_in});
    out.end_node = n;
    if (k >= 0 && n == from_node && k == from_half) {
      out.closed = true;
      out.event = stop(EventKind::kClosed, "closed through the " + what);
      return out;
    }
    if (k < 0 || !node.branches[static_cast<std::size_t>(k)].exit_ok) {
      out.event = stop(EventKind::kSingularSuspected, "ends at the " + what);
      return out;
    }
    if (node.used[static_cast<std::size_t>(k)]) {
      out.event = stop(EventKind::kReachedTracedCurve, "goes on along a branch traced before, through the " + what);
      return out;
    }
    registry->mark(n, k, curve);
    const HalfBranch& b = node.branches[static_cast<std::size_t>(k)];
    from = CurvePoint{b.exit_x, b.exit_point, b.direction};
    out.length += arc_length_estimate(loc.point, b.tangent_3d, from.p, from.t);
    out.points.push_back(from);
  }
}

}  // namespace ssimarch
