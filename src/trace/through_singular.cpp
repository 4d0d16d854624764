#include "ssimarch/trace/through_singular.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ssimarch/problem/closed_form_tolerances.hpp"

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
// located from the middle of the reversed step (a crossing) or from the last point (stuck). A
// singular point of the curve is a point of it, so the surfaces meet there to the tracer's
// tolerance (contact_gap_tolerance, as the closed forms decide contact); a critical point of the
// gap beyond it is a near miss (a sphere 1e-10 above a plane: the tiny circle goes round it).
bool locate_near(const Tracer& tracer, const CurvePoint& last, const Event& event, SingularLocation* loc) {
  const Problem& P = tracer.problem();
  const bool crossing = event.beyond.size() > 0;
  const double chord = crossing ? (P.point(event.beyond) - last.p).norm() : 0.0;
  const double reach = std::max(2 * chord, tracer.options().step_length);
  auto located_from = [&](const UnknownVec& guess) {
    *loc = locate_singular_point(P, guess);
    return loc->status == LocateStatus::kConverged &&
           loc->gap <= contact_gap_tolerance(tracer.options().tolerance, P.scale()) && P.inside(loc->x, 1e-9) &&
           (loc->point - last.p).norm() <= reach;
  };
  // From the middle of the step, then (the watch saw the dip at the last point itself) from the
  // last point.
  if (crossing && located_from(UnknownVec(last.x + 0.5 * P.difference(last.x, event.beyond)))) return true;
  return located_from(last.x);
}

// Whether the curve's start lies on the stretch from the last accepted point to the singular point
// where the march stopped: the tracer tests closure on accepted chords only, and the step that
// would have crossed the singular point was not accepted. A start placed next to a singular
// point (regular_start moves starts half a step off them) is passed there on the way back. The
// allowance is the chord's sagitta bound for the turning of the tangent over it, and the
// tangents must agree (the other half-branch at a cusp runs the opposite way).
bool closes_before(const CurvePoint& start, const CurvePoint& last, const Vec3& s, double tol) {
  const Vec3 seg = s - last.p;
  const double L2 = seg.squaredNorm();
  if (!(L2 > 0)) return false;
  const double tau = (start.p - last.p).dot(seg) / L2;
  if (!(tau >= 0 && tau <= 1)) return false;
  const double turn = std::acos(std::clamp(last.t.dot(seg.normalized()), -1.0, 1.0));
  const double allowance = 0.5 * std::sqrt(L2) * std::sin(std::min(turn, M_PI / 2)) + tol;
  return (start.p - (last.p + tau * seg)).norm() <= allowance && start.t.dot(last.t) > 0.5;
}

// Ends `out` on the curve's start, reached from the point (p, t): the loop closed next to a
// singular point, where the tracer's own closure test does not look (closes_before).
void close_on_start(const Vec3& p, const Vec3& t, const CurvePoint& start, const std::string& why, BranchMarch* out) {
  out->length += arc_length_estimate(p, t, start.p, start.t);
  out->points.push_back(start);
  out->closed = true;
  out->event = stop(EventKind::kClosed, why);
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

// The state of one branch's walk across its passages through singular points.
struct Walk {
  BranchMarch out;
  CurvePoint from;               // where the next march starts
  bool unwatched_first = false;  // its first step is taken without the singular-point watch
  std::optional<Tracer> fine;    // short steps over the stretch of a near miss
  double fine_length = 0;        // the length of that stretch
  int left_node = -1;            // the singular point the current march left (registry index)
  std::size_t left_at = 0;       // and the index in out.points of the exit point it left from
};

// Whether the march that left a singular point along a half-branch met that same point again
// before it accepted a second point: its first step, long against the half-branch circle (a
// constant step of 0.9 from an exit point 0.007 from a ramphoid cusp), turned back towards the
// point. That is no arrival but a near miss, retaken with short steps.
bool back_at_the_point_left(SingularRegistry* registry, const SingularLocation& loc, const Walk& w) {
  if (!registry || w.left_node < 0 || w.out.points.size() > w.left_at + 2) return false;
  const SingularNode& n = registry->node(w.left_node);
  return (n.location.point - loc.point).norm() <= std::max(registry->merge_distance(), resolution_radius(n));
}

// What the caller of one step of the walk does next.
enum class Next { kMarch, kDone };

// One march of the walk from w->from until an event, appended to w->out (its points after the
// first, its length and event). Returns the index of w->from in w->out.points.
std::size_t march_passage(const Tracer& tracer, const MarchLimits& base, const CurvePoint* close_at, Walk* w,
                          TraceStats* stats) {
  MarchLimits limits = base;
  limits.watch_crossings = true;
  limits.skip_first_watch = w->unwatched_first;
  limits.close_at = close_at;
  limits.detect_closure = close_at != nullptr;
  limits.max_points = std::max<long>(2, base.max_points - static_cast<long>(w->out.points.size()) + 1);
  limits.max_length = std::max(0.0, base.max_length - w->out.length);
  if (w->fine) limits.max_length = std::min(limits.max_length, w->fine_length);
  MarchResult r = (w->fine ? *w->fine : tracer).march_until_event(w->from, Direction::kForward, limits, stats);
  const std::size_t begin = w->out.points.size() - 1;
  w->out.points.insert(w->out.points.end(), r.points.begin() + 1, r.points.end());
  w->out.length += r.length;
  w->out.event = r.event;
  w->out.closed = r.event.kind == EventKind::kClosed;
  w->unwatched_first = false;
  return begin;
}

// A near miss (the orientation reversed, or the rank ratio dipped, without a singular point
// there): the walk retakes the stretch from its last point with short steps (short_steps), or,
// when the options admit none that short, takes the step unwatched.
void retake_near_miss(const Tracer& tracer, Walk* w) {
  const Problem& P = tracer.problem();
  w->from = w->out.points.back();
  const double chord = (P.point(w->out.event.beyond) - w->from.p).norm();
  w->fine.reset();
  if (auto o = short_steps(tracer, 0.25 * chord)) w->fine.emplace(P, *o);
  w->fine_length = 2 * chord;
  w->unwatched_first = !w->fine;
}

// Where the walk goes after the singular point `loc` located at the end of its last march
// (started at index `begin`): closed at its start just before or after the point, closed through
// the node it left by, ended there (no continuing half-branch, or one traced before), or on along
// the half-branch continuing the arriving one (w->from becomes its exit point).
Next pass_singular_point(const Tracer& tracer, SingularRegistry* registry, SingularLocation loc, std::size_t begin,
                         const CurvePoint* close_at, int curve, int from_node, int from_half, Walk* w) {
  const double close_tolerance = 1e-9 * tracer.problem().scale();  // model units: rounding of a located point
  BranchMarch& out = w->out;
  trim_beyond(loc.point, begin, &out);
  // Only once the branch has left its start: a start placed half a step before a singular point
  // (regular_start) is the last accepted point when the first step already reaches the point.
  if (close_at && out.points.size() > 1 && closes_before(*close_at, out.points.back(), loc.point, close_tolerance)) {
    const CurvePoint last = out.points.back();
    close_on_start(last.p, last.t, *close_at, "closed at its start, passed just before a singular point", &out);
    return Next::kDone;
  }
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
    return Next::kDone;
  }
  if (k < 0 || !node.branches[static_cast<std::size_t>(k)].exit_ok) {
    out.event = stop(EventKind::kSingularSuspected, "ends at the " + what);
    return Next::kDone;
  }
  if (node.used[static_cast<std::size_t>(k)]) {
    out.event = stop(EventKind::kReachedTracedCurve, "goes on along a branch traced before, through the " + what);
    return Next::kDone;
  }
  registry->mark(n, k, curve);
  const HalfBranch& b = node.branches[static_cast<std::size_t>(k)];
  w->from = CurvePoint{b.exit_x, b.exit_point, b.direction};
  w->left_node = n;
  if (close_at && closes_before(*close_at, CurvePoint{loc.x, loc.point, b.tangent_3d}, w->from.p, close_tolerance)) {
    close_on_start(loc.point, b.tangent_3d, *close_at, "closed at its start, just after the " + what, &out);
    return Next::kDone;
  }
  out.length += arc_length_estimate(loc.point, b.tangent_3d, w->from.p, w->from.t);
  out.points.push_back(w->from);
  w->left_at = out.points.size() - 1;
  return Next::kMarch;
}

}  // namespace

BranchMarch march_branch(const Tracer& tracer, const CurvePoint& start, const CurvePoint* close_at,
                         SingularRegistry* registry, int curve, TraceStats* stats, int from_node, int from_half,
                         const MarchLimits* base_limits) {
  const MarchLimits base = base_limits ? *base_limits : tracer.limits();
  Walk w;
  w.out.points.push_back(start);
  w.from = start;
  w.left_node = from_node;
  for (int passage = 0;; ++passage) {
    const std::size_t begin = march_passage(tracer, base, close_at, &w, stats);
    const Event& e = w.out.event;
    if (w.fine && e.kind == EventKind::kBudget && w.out.length < base.max_length) {
      w.fine.reset();  // the stretch is passed: back to the options' steps
      w.from = w.out.points.back();
      continue;
    }
    if (e.kind != EventKind::kSingularSuspected || passage >= kMaxPassages) return std::move(w.out);
    SingularLocation loc;
    const bool located = locate_near(tracer, w.out.points.back(), e, &loc);
    if (!located || back_at_the_point_left(registry, loc, w)) {
      if (e.beyond.size() == 0) return std::move(w.out);  // stuck, and no singular point there
      retake_near_miss(tracer, &w);
      continue;
    }
    w.fine.reset();
    if (pass_singular_point(tracer, registry, loc, begin, close_at, curve, from_node, from_half, &w) == Next::kDone)
      return std::move(w.out);
  }
}

}  // namespace ssimarch
