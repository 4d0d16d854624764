#include "ssimarch/trace/trace_all.hpp"

#include "ssimarch/core/interrupt.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "ssimarch/march/arc_length.hpp"
#include "ssimarch/march/predictor.hpp"
#include "ssimarch/march/refined_arc_length.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"
#include "ssimarch/trace/branch_length_bound.hpp"
#include "ssimarch/trace/half_branch_guide.hpp"
#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/singular/analysis.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/start/start_points.hpp"
#include "ssimarch/start/start_tolerances.hpp"
#include "ssimarch/trace/tangency_hunt.hpp"
#include "ssimarch/trace/on_traced_curve.hpp"
#include "ssimarch/trace/through_singular.hpp"

namespace ssimarch {

namespace {

// The one place where marches become a curve: the backward half (if any; points reversed,
// tangents turned) followed by the forward half, which starts at the backward half's first
// point (its own first point is then dropped); a forward half that closed is the whole curve.
TracedCurve join(const BranchMarch* backward, BranchMarch forward) {
  TracedCurve curve;
  if (backward) {
    for (auto it = backward->points.rbegin(); it != backward->points.rend(); ++it)
      curve.points.push_back({it->x, it->p, -it->t});
    curve.length = backward->length;
    curve.start_end = to_termination(backward->event);
    curve.start_message = backward->event.message;
  }
  curve.points.insert(curve.points.end(), forward.points.begin() + (backward ? 1 : 0), forward.points.end());
  curve.length += forward.length;
  curve.closed = forward.closed;
  curve.end_end = to_termination(forward.event);
  curve.end_message = forward.event.message;
  return curve;
}

// One march from `start` along its tangent until an event: through the singular points it meets
// with a registry (march_branch), else the plain tracer, which stops next to them. `close_at`:
// the point whose return closes the curve (null: no closure test).
BranchMarch march_half(const Tracer& tracer, const CurvePoint& start, const CurvePoint* close_at,
                       SingularRegistry* registry, int index, TraceStats* stats, const MarchLimits& base) {
  if (registry) return march_branch(tracer, start, close_at, registry, index, stats, -1, -1, &base);
  MarchLimits limits = base;
  limits.detect_closure = close_at != nullptr;
  limits.close_at = close_at;
  MarchResult r = tracer.march_until_event(start, Direction::kForward, limits, stats);
  BranchMarch m;
  m.points = std::move(r.points);
  m.length = r.length;
  m.closed = r.event.kind == EventKind::kClosed;
  m.event = std::move(r.event);
  return m;
}

// The curve through the regular point `start`: forward until it closes or stops, then, unless
// it closed, backward from the start.
TracedCurve trace_branch_through(const Tracer& tracer, const CurvePoint& start, SingularRegistry* registry, int index,
                                 TraceStats* stats, const MarchLimits& base) {
  BranchMarch forward = march_half(tracer, start, &start, registry, index, stats, base);
  if (forward.closed) return join(nullptr, std::move(forward));
  const CurvePoint back{start.x, start.p, -start.t};
  // A forward half stopped away from a located singular point (a step that left the domain next
  // to a pole and could not land, a budget) may lie on a closed branch: the backward half then
  // comes round to the forward half's last point, arriving against its tangent. Stopping there
  // traces the loop once (issue 11: every branch exactly once) instead of running on past it.
  const CurvePoint& last = forward.points.back();
  const CurvePoint meet{last.x, last.p, -last.t};
  const bool may_meet = forward.end_node < 0 && forward.points.size() > 1;
  const BranchMarch backward = march_half(tracer, back, may_meet ? &meet : nullptr, registry, index, stats, base);
  if (!backward.closed) return join(&backward, std::move(forward));
  TracedCurve curve = join(&backward, std::move(forward));
  curve.closed = true;
  curve.start_end = curve.end_end = Termination::kClosedLoop;
  curve.start_message = curve.end_message = "";
  return curve;
}

// A half-branch whose exit point (a short step from the node, singular/half_branches.hpp) lies
// outside the domain leaves it before that point: the march from the node ends on the bound the
// chord node -> exit point crosses first (a node next to the domain's edge, OCCT bug32850). Empty
// when the exit point is inside, or no bound of the unknowns is crossed.
std::optional<BranchMarch> leave_before_exit(const Tracer& tracer, const SingularNode& node, const HalfBranch& b) {
  const Problem& P = tracer.problem();
  if (P.inside(b.exit_x)) return std::nullopt;
  const VecX& x0 = node.location.x;
  const VecX d = P.difference(x0, b.exit_x);
  int unknown = -1;
  double fraction = 2, value = 0;
  for (int i = 0; i < P.dim(); ++i) {
    const Interval& B = P.bounds()[static_cast<std::size_t>(i)];
    if (P.periods()[static_cast<std::size_t>(i)] > 0 || d[i] == 0) continue;
    for (double bound : {B.lo, B.hi}) {
      const double f = (bound - x0[i]) / d[i];
      if (f >= 0 && f <= 1 && f < fraction) fraction = f, unknown = i, value = bound;
    }
  }
  if (unknown < 0) return std::nullopt;
  const CorrectorOptions co{tracer.options().tolerance, tracer.options().max_corrector_iterations};
  const CorrectorResult r = solve_with_fixed_unknown(P, VecX(x0 + fraction * d), unknown, value, co);
  if (r.status != CorrectorStatus::kConverged || !P.inside(r.x, 1e-9 * (1 + std::fabs(value)))) return std::nullopt;
  BranchMarch m;
  m.points.push_back({r.x, P.point(r.x), b.direction});
  m.event = Event{EventKind::kDomainEdge, BudgetBound::kNone,
                  "reached the domain edge " + P.unknown_names()[static_cast<std::size_t>(unknown)] + " = " +
                      std::to_string(value) + " next to the " + std::string(to_string(node.kind.type)),
                  VecX{}};
  return m;
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
    std::optional<BranchMarch> edge = leave_before_exit(tracer, node, b);
    BranchMarch rest =
        edge ? std::move(*edge) : march_branch(tracer, exit_of(h), nullptr, registry, index, stats, n, h);
    m.points.insert(m.points.end(), rest.points.begin(), rest.points.end());
    m.length = arc_length_estimate(node.location.point, b.tangent_3d, rest.points.front().p, rest.points.front().t) +
               rest.length;
    m.event = rest.event;
    m.closed = rest.closed;
    return m;
  };
  registry->mark(n, k, index);
  BranchMarch forward = from_node(k);
  const int c = registry->node(n).branches[static_cast<std::size_t>(k)].continuation;
  if (forward.closed) return join(nullptr, std::move(forward));
  if (c >= 0 && !registry->node(n).used[static_cast<std::size_t>(c)] &&
      registry->node(n).branches[static_cast<std::size_t>(c)].exit_ok) {
    registry->mark(n, c, index);
    const BranchMarch backward = from_node(c);
    return join(&backward, std::move(forward));
  }
  TracedCurve curve = join(nullptr, std::move(forward));
  curve.start_end = Termination::kSingularPoint;
  curve.start_message = "starts at the " + std::string(to_string(registry->node(n).kind.type)) + " at " +
                        describe_point(registry->node(n).location.point);
  return curve;
}

// The start tangent's orientation fixed by the curve alone: its largest component positive (the
// sign of the jet's tangent follows the order of the equations, which swapping the surfaces
// changes; issue 11 item 4).
Vec3 canonical_direction(const Vec3& t) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(t[i]) > std::abs(t[k]) + 1e-12) k = i;
  return t[k] < 0 ? Vec3(-t) : t;
}

}  // namespace

TracedCurve trace_curve_through(const Tracer& tracer, const VecX& x0, TraceStats* stats, SingularRegistry* registry,
                                int index, const std::vector<TracedCurve>* join_at, double join_radius) {
  const Problem& P = tracer.problem();
  TracedCurve curve;
  DynamicCurveJet j = curve_jet_dynamic(P, x0, 1);
  ++stats->jet_evaluations;
  stats->add_surface_evaluations(jet_evaluation_cost(P, 1));
  CurvePoint start{x0, P.point(x0), canonical_direction(j.tangent())};
  if (j.status != CurveJetStatus::kOk) {
    curve.points.push_back(start);
    curve.start_end = curve.end_end = Termination::kSingularPoint;
    curve.start_message = curve.end_message = "the start point " + describe_point(start.p) + " is a singular point";
    return curve;
  }
  ++stats->points;
  stats->record_iterations(1);
  MarchLimits base = tracer.limits();
  base.traced = join_at;
  base.traced_radius = join_radius;
  curve = trace_branch_through(tracer, start, registry, index, stats, base);
  for (auto& p : curve.points) p.x = P.wrap(p.x);
  return curve;
}

namespace {

// The tracer's options with max_length no more than the run-away bound (branch_length_bound.hpp);
// *bound: that bound when it is the binding one, else 0.
// The tracer with the run-away bound as its max_length; *bound is the bound when it is the
// binding limit (0 otherwise).
Tracer bounded_tracer(const Tracer& unbounded, double* bound) {
  Tracer t(unbounded);
  const double b = branch_length_bound(unbounded.problem(), kResolutionFraction * unbounded.spacing());
  *bound = b < unbounded.options().max_length ? b : 0;
  t.cap_max_length(b);
  return t;
}

// A curve end stopped by the run-away bound says so (it is a failure, not a result).
void explain_bound(double bound, TracedCurve* c) {
  if (bound <= 0) return;
  const std::string why =
      "reached the run-away bound: " + std::to_string(bound) +
      " model units, the longest branch the domain holds at the tracer's resolution (docs/topology.md)";
  if (c->start_end == Termination::kMaxLength) c->start_message = why;
  if (c->end_end == Termination::kMaxLength) c->end_message = why;
}

// An unfinished end of a traced curve: an open end that stopped away from the boundary and from
// located singular points (no step could be taken, or stuck next to a suspected singular point).
// A later trace that reaches it is the same branch: it stops there and continues that curve.
struct LooseEnd {
  int curve;
  bool at_start;
};

std::vector<LooseEnd> loose_ends(const std::vector<TracedCurve>& curves, const SingularRegistry& registry, double tol) {
  std::vector<LooseEnd> out;
  auto at_node = [&](const Vec3& p) {
    for (const SingularNode& n : registry.nodes())
      if ((n.location.point - p).norm() <= tol) return true;
    return false;
  };
  auto loose = [](Termination t) { return t == Termination::kStepUnderflow || t == Termination::kSingularPoint; };
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const TracedCurve& c = curves[i];
    if (c.closed || c.points.size() < 2) continue;
    if (loose(c.start_end) && !at_node(c.points.front().p)) out.push_back({static_cast<int>(i), true});
    if (loose(c.end_end) && !at_node(c.points.back().p)) out.push_back({static_cast<int>(i), false});
  }
  return out;
}

// The last segment of each loose end, as curves for MarchLimits::traced.
std::vector<TracedCurve> stubs(const std::vector<TracedCurve>& curves, const std::vector<LooseEnd>& ends) {
  std::vector<TracedCurve> out;
  for (const LooseEnd& e : ends) {
    const auto& pts = curves[static_cast<std::size_t>(e.curve)].points;
    TracedCurve s;
    s.points =
        e.at_start ? std::vector<CurvePoint>{pts[0], pts[1]} : std::vector<CurvePoint>{pts[pts.size() - 2], pts.back()};
    out.push_back(std::move(s));
  }
  return out;
}

// The curve run the other way: points reversed, tangents turned, ends swapped.
TracedCurve reversed(TracedCurve c) {
  std::reverse(c.points.begin(), c.points.end());
  for (CurvePoint& p : c.points) p.t = -p.t;
  std::swap(c.start_end, c.end_end);
  std::swap(c.start_message, c.end_message);
  return c;
}

// Curve b continues curve *a at a's end (or start): b is oriented to run on from there and the
// two are joined by the segment between their touching points (shorter than the join radius).
void continue_curve(TracedCurve* a, bool at_a_start, TracedCurve b, bool b_touches_at_start) {
  if (at_a_start) {
    *a = reversed(std::move(*a));
    continue_curve(a, false, std::move(b), b_touches_at_start);
    *a = reversed(std::move(*a));
    return;
  }
  if (!b_touches_at_start) b = reversed(std::move(b));
  const CurvePoint& last = a->points.back();
  a->length += arc_length_estimate(last.p, last.t, b.points.front().p, b.points.front().t) + b.length;
  a->points.insert(a->points.end(), b.points.begin(), b.points.end());
  a->end_end = b.end_end;
  a->end_message = b.end_message;
}

// The loose end nearest p.
const LooseEnd& nearest(const std::vector<TracedCurve>& curves, const std::vector<LooseEnd>& ends, const Vec3& p) {
  std::size_t best = 0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const auto& pts = curves[static_cast<std::size_t>(ends[i].curve)].points;
    const double di = ((ends[i].at_start ? pts.front().p : pts.back().p) - p).norm();
    if (di < d) d = di, best = i;
  }
  return ends[best];
}

// Adds the traced curve c to *curves, or, when one of its ends reached a loose end, continues
// that curve with it (closing it when c's other end reached the curve's other loose end).
// Curve indices recorded at singular nodes follow c into the curve it joined.
void add_or_join(TracedCurve c, const std::vector<LooseEnd>& ends, std::vector<TracedCurve>* curves,
                 SingularRegistry* registry) {
  const bool at_start = c.start_end == Termination::kReachedTracedCurve;
  if (ends.empty() || (!at_start && c.end_end != Termination::kReachedTracedCurve)) {
    curves->push_back(std::move(c));
    return;
  }
  const LooseEnd e = nearest(*curves, ends, at_start ? c.points.front().p : c.points.back().p);
  const bool other_reached = (at_start ? c.end_end : c.start_end) == Termination::kReachedTracedCurve;
  const Vec3 other = at_start ? c.points.back().p : c.points.front().p;
  TracedCurve& a = (*curves)[static_cast<std::size_t>(e.curve)];
  continue_curve(&a, e.at_start, std::move(c), at_start);
  if (other_reached) {
    const LooseEnd f = nearest(*curves, ends, other);
    if (f.curve == e.curve && f.at_start != e.at_start) {  // both ends of one curve: a loop
      a.length += arc_length_estimate(a.points.back().p, a.points.back().t, a.points.front().p, a.points.front().t);
      a.points.push_back(a.points.front());
      a.closed = true;
    }
  }
  const int added = static_cast<int>(curves->size());
  for (std::size_t n = 0; registry && n < registry->nodes().size(); ++n) {
    std::vector<int>& on = registry->node(static_cast<int>(n)).curves;
    std::replace(on.begin(), on.end(), added, e.curve);
    std::sort(on.begin(), on.end());
    on.erase(std::unique(on.begin(), on.end()), on.end());
  }
}

// Removes curve i; the registry's curve indices follow.
void erase_curve(std::size_t i, std::vector<TracedCurve>* curves, SingularRegistry* registry) {
  curves->erase(curves->begin() + static_cast<std::ptrdiff_t>(i));
  for (std::size_t n = 0; registry && n < registry->nodes().size(); ++n) {
    std::vector<int>& on = registry->node(static_cast<int>(n)).curves;
    on.erase(std::remove(on.begin(), on.end(), static_cast<int>(i)), on.end());
    for (int& k : on)
      if (k > static_cast<int>(i)) --k;
  }
}

bool on_a_traced_curve(const Tracer& tracer, const VecX& x, const std::vector<TracedCurve>& curves, double radius);

// Whether every point of the curve lies within `merge` of its first: a march that took no step.
bool one_point(const TracedCurve& t, double merge) {
  return !t.points.empty() && std::none_of(t.points.begin(), t.points.end(),
                                           [&](const CurvePoint& q) { return (q.p - t.points[0].p).norm() > merge; });
}

// A march from a regular start that took no step away from it: the branch is shorter than the
// step between two domain edges (a curve cutting a corner of the domain: stress seed 31 pair 75,
// an arc of 0.036 at a step of 0.29, came back as two "isolated" regular points, certified).
// Retaken with steps 16 times shorter until it leaves its start, down to 16 times the options'
// smallest step; a start whose jet fails (a singular point, an apex: no domain end) is left to the
// analysis.
TracedCurve retrace_short_branch(const Tracer& tracer, const VecX& x, double merge, TraceStats* stats, TracedCurve c) {
  // Only a march that left the domain at once: one that stopped at a singular point nearby is
  // the registry's to pass (the node's half-branches are traced from it).
  const auto left_at_once = [&](const TracedCurve& t) {
    return one_point(t, merge) && (t.start_end == Termination::kLeftDomain || t.end_end == Termination::kLeftDomain);
  };
  TraceOptions o = tracer.options();
  while (left_at_once(c)) {
    o.step_length /= 16;
    if (!(o.step_length > 16 * o.min_step)) break;
    o.min_step_length = std::min(o.min_step_length, 0.5 * o.step_length);
    std::string error;
    if (!o.is_valid(&error)) break;
    c = trace_curve_through(Tracer(tracer.problem(), o), x, stats, nullptr, 0, nullptr, 0.0);
  }
  return c;
}

// A "curve" whose points are all one point (a march that could take no step from its start: a
// cone's apex on a sphere's pole, OpenCASCADE bug21494_1) is a point where the surfaces meet and no
// branch leaves: an isolated point, reported once among the isolated points and not as a curve
// (issue 29: one representation of an isolated point). Its class is the analysis's where the local
// curve can be built, else `isolated` with no local data (a degenerate chart, an apex).
void points_are_not_curves(const Tracer& tracer, double merge, double radius, TraceStats* stats,
                           std::vector<TracedCurve>* curves, SingularRegistry* registry,
                           std::vector<SingularPointReport>* isolated) {
  const Problem& P = tracer.problem();
  for (std::size_t i = curves->size(); i-- > 0;) {
    const TracedCurve& c = (*curves)[i];
    if (c.tangential_contact || !one_point(c, merge)) continue;
    const CurvePoint at = c.points[0];
    TracedCurve short_branch = retrace_short_branch(tracer, VecX(at.x), merge, stats, c);
    erase_curve(i, curves, registry);
    if (on_a_traced_curve(tracer, VecX(at.x), *curves, radius)) continue;  // its branch was retraced already
    if (!one_point(short_branch, merge)) {                                 // trace_curve_through wrapped its unknowns
      curves->push_back(std::move(short_branch));
      continue;
    }
    const auto known = [&](const SingularPointReport& r) { return (r.p - at.p).norm() <= merge; };
    if (std::any_of(isolated->begin(), isolated->end(), known)) continue;
    SingularAnalysisOptions here;
    here.locate = false;
    here.half_branches = false;
    const SingularAnalysis a = analyse_singular_point(P, VecX(at.x), here);
    SingularPointReport r = a.analysed() ? make_report(a, false) : SingularPointReport{};
    r.x = at.x;
    r.p = at.p;
    if (!a.analysed() || r.type == SingularType::kRegular) r.type = SingularType::kIsolated;
    isolated->push_back(std::move(r));
  }
}

// An isolated point (a contact with no real branch) that a curve shorter than the resolution
// radius leaves and returns to: no branch arrives at an isolated point, so the curve is a loop
// around the contact within the tracer's resolution. The surfaces meet there to the tolerance
// (through_singular.cpp, locate_near) with parallel normals, and a loop's points are known only
// to tolerance / sin(angle between the normals), its own size (a sphere 1e-12 above a plane: a
// circle of radius 1.4e-6, points known to 7e-7): the contact point is the answer, as the closed
// form gives it for a gap within the tolerance (analytic/, contact_gap_tolerance). The curve goes
// and the point becomes an isolated point (out of the singular points); returns those points.
std::vector<Vec3> absorb_contact_loops(std::vector<TracedCurve>* curves, SingularRegistry* registry, double radius,
                                       double tol, std::vector<SingularPointReport>* isolated) {
  std::vector<Vec3> absorbed;
  for (std::size_t n = 0; n < registry->nodes().size(); ++n) {
    const SingularNode& node = registry->nodes()[n];
    if (node.kind.type != SingularType::kIsolated) continue;
    const Vec3 p = node.location.point;
    for (std::size_t i = curves->size(); i-- > 0;) {
      const TracedCurve& c = (*curves)[i];
      const bool on = std::find(node.curves.begin(), node.curves.end(), static_cast<int>(i)) != node.curves.end();
      if (!on || c.closed || c.length > radius || c.points.empty() || (c.points.front().p - p).norm() > tol ||
          (c.points.back().p - p).norm() > tol)
        continue;
      erase_curve(i, curves, registry);
      if (std::find(absorbed.begin(), absorbed.end(), p) == absorbed.end()) {
        absorbed.push_back(p);
        isolated->push_back(make_report(node, false));
      }
    }
  }
  return absorbed;
}

// Curves traced before a singular point next to them was known can be a stub of a branch traced
// later through that point (a start on the domain edge 1e-3 from a node, whose march could not
// get past it: OCCT bug32850): a curve shorter than the resolution radius, through no singular
// point, with every point within that radius of a longer curve is that curve's duplicate and goes
// (each branch once, issue 11 item 2); the registry's curve indices follow.
void drop_stubs(std::vector<TracedCurve>* curves, SingularRegistry* registry, double radius) {
  for (std::size_t i = curves->size(); i-- > 0;) {
    const TracedCurve& c = (*curves)[i];
    if (c.length > radius || c.tangential_contact) continue;
    bool through_node = false;  // a branch piece leaving a singular point is never a stub
    for (std::size_t n = 0; registry && n < registry->nodes().size(); ++n) {
      const std::vector<int>& on = registry->nodes()[n].curves;
      through_node = through_node || std::find(on.begin(), on.end(), static_cast<int>(i)) != on.end();
    }
    if (through_node) continue;
    std::vector<TracedCurve> others;
    for (std::size_t j = 0; j < curves->size(); ++j)
      if (j != i && (*curves)[j].length > c.length) others.push_back((*curves)[j]);
    const bool covered = std::all_of(c.points.begin(), c.points.end(),
                                     [&](const CurvePoint& p) { return near_traced_curve(p.p, others, radius); });
    if (!covered || others.empty()) continue;
    erase_curve(i, curves, registry);
  }
}

// A start that regular_start left on a singular point (no point within half a step of it is
// regular enough: at short steps the rank ratio there stays below kSuspectSingularRankRatio)
// stands for the point's half-branches. Registered, the point's half-branches are traced by
// trace_all's node loop, each once, and a loop through the point closes there on the half-branch
// it left by; a trace from the start itself would leave and come back through the point along
// used half-branches and stop there as an open curve (issue 11: every branch exactly once). False
// (nothing registered) when x is regular, or no singular point with a half-branch to leave by
// is located within singular_start_radius of it (model units, start/start_tolerances.hpp;
// a point of a curve of tangential contact, an isolated point), or x is on a pole.
// The singular point located from a start x, with its local curve and class: none when x is
// regular (J_H's rank ratio), or the location fails or leaves the domain, or the local curve
// cannot be built. Located once for both uses below (a node to trace from, an isolated point).
struct StartSingularity {
  SingularAnalysis analysis;  // without half-branches: the type decides whether they are needed
  double distance = 0;        // from point(x), model units
};
// How far apart two points of the curve at the linearisation L, each within `tolerance` of both surfaces, may be
// across the curve: tolerance / sin(theta), theta the angle between the normals (at most the
// problem's scale: a point where the normals are parallel is known to no better).
double position_accuracy(const Problem& P, const Linearization& L, double tolerance) {
  const double sine = L.normal_first.cross(L.normal_second).norm();
  return std::min(tolerance / std::max(sine, tolerance / P.scale()), P.scale());
}

std::optional<StartSingularity> singularity_at_start(const Problem& P, const VecX& x) {
  if (!(Problem::rank_ratio(P.linearize(x)) < kSuspectSingularRankRatio)) return std::nullopt;
  SingularAnalysisOptions options;
  options.half_branches = false;
  StartSingularity s{analyse_singular_point(P, x, options)};
  const SingularLocation& loc = s.analysis.location;
  if (loc.status != LocateStatus::kConverged || !P.inside(loc.x, 1e-9) || !s.analysis.analysed()) return std::nullopt;
  s.distance = (loc.point - P.point(x)).norm();
  return s;
}

bool register_singular_start(const Tracer& tracer, const VecX& x, const StartSingularity& s,
                             const std::vector<Pole>& poles, SingularRegistry* registry) {
  const Problem& P = tracer.problem();
  // A start on a pole (no tangent in its parameters) is the pole's, handled after the others.
  if (pole_at(poles, x, 1e-9) || s.distance > singular_start_radius(tracer.options().tolerance, P.scale()))
    return false;
  // Points on or across a curve of tangential contact are traced by trace_contact_from.
  const SingularType type = s.analysis.kind.type;
  if (type == SingularType::kRegular || type == SingularType::kTangentialContact ||
      type == SingularType::kTangentLineCrossing)
    return false;
  const std::vector<HalfBranch> branches = half_branches(P, s.analysis.curve, s.analysis.kind);
  if (std::none_of(branches.begin(), branches.end(), [](const HalfBranch& b) { return b.exit_ok; })) return false;
  registry->add(s.analysis.location);
  return true;
}

// A start on an isolated point of the curve (the certified search adds the point of every box it
// decided around one, start/isolated_box.hpp) is that point: it is reported in `isolated` (once)
// and nothing is traced from it. False when no isolated point where the surfaces meet within
// contact_gap_tolerance is located within half a step of it.
bool isolated_start(const Tracer& tracer, const StartSingularity& s, double merge,
                    std::vector<SingularPointReport>* isolated) {
  const Problem& P = tracer.problem();
  // A gap above the corrector's tolerance is no contact: a loop of the curve surrounds the point
  // (a sphere 1e-10 above a plane, tests NearContact.*), traced from x.
  if (s.distance > 0.5 * tracer.options().step_length ||
      s.analysis.location.gap > contact_gap_tolerance(tracer.options().tolerance, P.scale()) ||
      s.analysis.kind.type != SingularType::kIsolated)
    return false;
  for (const SingularPointReport& r : *isolated)
    if ((r.p - s.analysis.location.point).norm() <= merge) return true;
  isolated->push_back(make_report(s.analysis, false));
  return true;
}

}  // namespace

namespace {

// The start points in the order they are traced. Regular start points first: a start that had to
// be moved off a singular point lies within a step of it, where closing the loop again is delicate
// (thesis ch. 6: start away from singular points); such starts are usually on curves traced by then
// and skipped. A start left on a pole (no regular point next to it: the curve through the pole is a
// curve of tangential contact, or ends there) comes last: the curves through the pole are traced by
// then. A start the search put on a singular point is moved next to it as a matter of course: only a
// start the user gave is worth a warning (`warnings` null otherwise; issue 29: 26 warnings on
// correct results).
std::vector<VecX> ordered_starts(const Tracer& tracer, const std::vector<VecX>& seeds, const std::vector<Pole>& poles,
                                 std::vector<std::string>* warnings) {
  std::vector<VecX> regular, moved, at_pole;
  for (const VecX& seed : seeds) {
    VecX x = regular_start(tracer, seed, warnings);
    const bool was_moved = (x - seed).norm() != 0;
    (was_moved ? moved : pole_at(poles, x, 1e-9) ? at_pole : regular).push_back(std::move(x));
  }
  regular.insert(regular.end(), moved.begin(), moved.end());
  regular.insert(regular.end(), at_pole.begin(), at_pole.end());
  return regular;
}

// Whether the start x lies on a curve traced before, by the geometry, not by a distance tied to the
// step (issue 26). The points of a curve are known to the tolerance along the normals but to
// tolerance / sin(theta) across the curve in the common tangent plane (theta: the angle between the
// surfaces' normals), so near a tangency two points of one curve may be that far apart. Next to a
// singular point (a suspect rank ratio) the branches through it come within the resolution radius
// of each other and are one component, traced from the point's half-branches: there the chord
// decides.
bool on_a_traced_curve(const Tracer& tracer, const VecX& x, const std::vector<TracedCurve>& curves, double radius) {
  const Problem& P = tracer.problem();
  const Linearization L = P.linearize(x);
  if (Problem::rank_ratio(L) < kSuspectSingularRankRatio) return near_traced_curve(L.point, curves, radius);
  return on_traced_curve(L.point, curves, radius, position_accuracy(P, L, tracer.options().tolerance));
}

// Every half-branch leaving a singular point that no curve followed yet is traced once (nodes may
// be added meanwhile, so the registry is read anew each pass).
void trace_unused_half_branches(const Tracer& tracer, SingularRegistry* registry, TraceResult* result) {
  for (std::size_t n = 0; n < registry->nodes().size(); ++n)
    for (std::size_t k = 0; k < registry->nodes()[n].branches.size(); ++k) {
      if (registry->nodes()[n].used[k] || !registry->nodes()[n].branches[k].exit_ok) continue;
      const int index = static_cast<int>(result->curves.size());
      TracedCurve c =
          trace_from_half_branch(tracer, registry, static_cast<int>(n), static_cast<int>(k), index, &result->stats);
      for (auto& p : c.points) p.x = tracer.problem().wrap(p.x);
      result->curves.push_back(std::move(c));
    }
}

}  // namespace

TraceResult trace_all(const Tracer& unbounded, const std::vector<Vec3>& starts, const TraceAllOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const Problem& P = unbounded.problem();
  TraceResult result;
  if (P.disjoint()) {  // no intersection is a result (issue 11 item 6)
    result.start_search.method = StartSearchMethod::kDisjointBoxes;
    result.start_search.certified = true;
    result.start_search.note = "no intersection: the boxes of the two surfaces do not overlap";
    result.warnings.push_back(result.start_search.note);
    return result;
  }
  double bound = 0;
  const Tracer tracer = bounded_tracer(unbounded, &bound);
  if (!starts.empty()) result.start_search.method = StartSearchMethod::kGiven;
  std::vector<VecX> seeds =
      starts.empty() ? automatic_start_points(tracer, &result.stats, &result.start_search)
                     : start_points_near(tracer, starts, &result.stats, &result.warnings, &result.failed_starts);
  const double registry_merge = kSingularMergeDistance * P.scale();
  SingularRegistry registry(P, registry_merge);
  const double registry_tol = kOnSingularPointDistance * P.scale();
  SingularRegistry* reg = options.through_singular_points ? &registry : nullptr;
  const double radius = kResolutionFraction * tracer.spacing();
  const std::vector<Pole> poles = problem_poles(P);
  for (const VecX& x : ordered_starts(tracer, seeds, poles, starts.empty() ? nullptr : &result.warnings)) {
    throw_if_interrupted();  // Ctrl-C between curves (core/interrupt.hpp)
    if (on_a_traced_curve(tracer, x, result.curves, radius)) continue;
    if (reg && trace_contact_from(tracer, x, &result.curves, reg)) continue;  // a curve of tangential contact
    if (reg) {
      if (const std::optional<StartSingularity> s = singularity_at_start(P, x)) {
        if (register_singular_start(tracer, x, *s, poles, reg)) continue;  // traced from the node below
        if (options.hunt_isolated_points && isolated_start(tracer, *s, registry_merge, &result.isolated_points))
          continue;
      }
    }
    const std::vector<LooseEnd> ends = loose_ends(result.curves, registry, registry_tol);
    const std::vector<TracedCurve> stub = stubs(result.curves, ends);
    TracedCurve c = trace_curve_through(tracer, x, &result.stats, reg, static_cast<int>(result.curves.size()),
                                        ends.empty() ? nullptr : &stub, radius);
    add_or_join(std::move(c), ends, &result.curves, reg);
  }
  if (reg && options.hunt_isolated_points)
    hunt_tangencies(tracer, result.start_search, reg, &result.curves, &result.isolated_points);
  if (reg) attach_crossings(reg, &result.curves, radius);
  if (reg) trace_unused_half_branches(tracer, reg, &result);
  drop_stubs(&result.curves, reg, radius);
  const std::vector<Vec3> contacts =
      reg ? absorb_contact_loops(&result.curves, reg, radius, registry_tol, &result.isolated_points)
          : std::vector<Vec3>{};
  points_are_not_curves(tracer, registry_merge, radius, &result.stats, &result.curves, reg, &result.isolated_points);
  for (TracedCurve& c : result.curves) explain_bound(bound, &c);
  // The circular-arc estimates summed while marching fall short where the curvature varies and
  // do not resolve cusps and tight turns (docs/marching.md, "Length."): each finished curve is
  // measured once more from its points, bisected on the curve where they do not suffice.
  const CorrectorOptions length_corrector{tracer.options().tolerance, tracer.options().max_corrector_iterations};
  const CurveGuide guide = half_branch_guide(registry.nodes());
  for (TracedCurve& c : result.curves) {
    if (c.tangential_contact) {
      c.length += arc_length_shortfall(c.points, c.closed);
      continue;
    }
    c.segment_lengths = segment_lengths(P, c.points, c.closed, length_corrector, guide);
    c.length = 0;
    for (double l : c.segment_lengths) c.length += l;
  }
  if (reg) result.singular_points = registry.reports();
  // A regular point is no singular point of the curve: the registry holds one only where a
  // parametrisation is degenerate on the curve (a B-spline sphere's pole), for the walk to pass.
  std::erase_if(result.singular_points, [&](const SingularPointReport& r) {
    return r.type == SingularType::kRegular || std::find(contacts.begin(), contacts.end(), r.p) != contacts.end();
  });
  result.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

TraceResult trace_all(const Problem& problem, const TraceOptions& options, const std::vector<Vec3>& starts,
                      const TraceAllOptions& all) {
  return trace_all(Tracer(problem, options), starts, all);
}

}  // namespace ssimarch
