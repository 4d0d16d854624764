#include "ssimarch/march/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "march_steps.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/march/closure_turning.hpp"
#include "ssimarch/march/corrector.hpp"
#include "ssimarch/march/model_size.hpp"
#include "ssimarch/march/option_ranges.hpp"
#include "ssimarch/march/pole_passage.hpp"
#include "ssimarch/march/predictor.hpp"
#include "ssimarch/march/resolved_options.hpp"
#include "ssimarch/march/step_control.hpp"
#include "ssimarch/march/step_tolerances.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch {

std::string_view to_string(EventKind kind) {
  switch (kind) {
    case EventKind::kClosed: return "closed";
    case EventKind::kDomainEdge: return "domain_edge";
    case EventKind::kSingularSuspected: return "singular_suspected";
    case EventKind::kReachedTracedCurve: return "reached_traced_curve";
    case EventKind::kBudget: return "budget";
    case EventKind::kStepUnderflow: return "step_underflow";
  }
  return "?";
}

Termination to_termination(const Event& e) {
  switch (e.kind) {
    case EventKind::kClosed: return Termination::kClosedLoop;
    case EventKind::kDomainEdge: return Termination::kLeftDomain;
    case EventKind::kSingularSuspected: return Termination::kSingularPoint;
    case EventKind::kReachedTracedCurve: return Termination::kReachedTracedCurve;
    case EventKind::kStepUnderflow: return Termination::kStepUnderflow;
    case EventKind::kBudget: break;
  }
  return e.bound == BudgetBound::kLength ? Termination::kMaxLength : Termination::kMaxPoints;
}

std::string describe_point(const Vec3& p) {
  std::ostringstream os;
  os.precision(10);
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}

double arc_length_estimate(const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb) {
  double c = (b - a).norm();
  double phi = internal::angle_between(ta, tb);
  if (phi < 1e-8) return c;
  return c * (phi / 2) / std::sin(phi / 2);
}

bool near_traced_curve(const Vec3& p, const std::vector<TracedCurve>& curves, double radius) {
  for (const auto& c : curves)
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      Vec3 a = c.points[i].p, seg = c.points[i + 1].p - a;
      double L2 = seg.squaredNorm();
      double tau = L2 > 0 ? std::clamp((p - a).dot(seg) / L2, 0.0, 1.0) : 0.0;
      if ((p - (a + tau * seg)).norm() <= radius) return true;
    }
  return false;
}

Tracer::Tracer(const Problem& problem, TraceOptions options)
    : Tracer(problem, resolve_trace_options(options, problem.scale())) {}

Tracer::Tracer(const Problem& problem, const ResolvedTraceOptions& resolved)
    : problem_(problem), options_(resolved.options), spacing_(resolved.spacing) {}

MarchLimits Tracer::limits() const {
  MarchLimits l;
  l.max_points = options_.max_points;
  l.max_length = options_.max_length;
  return l;
}

namespace {

// One march's strategies and state; step() tries one step, accept() takes it.
struct Marcher {
  Marcher(const Problem& problem, const TraceOptions& options, TraceStats* s) : P(problem), o(options), stats(s) {}
  const Problem& P;
  const TraceOptions& o;
  TraceStats* stats;
  AnyPredictor predictor = make_predictor(o);
  AnyCorrector corrector = make_corrector(o);
  AnyStepControl rule = make_step_control(o);
  int order = std::max(jet_order(predictor), std::visit([](const auto& s) { return s.jet_order(); }, rule));
  std::array<long, 2> jet_cost = jet_evaluation_cost(P, order);
  CorrectorOptions co{o.tolerance, o.max_corrector_iterations};
  MarchState state;
  CurvePoint cur;
  ClosureTurning turning;  // the index condition of loop closure (march/closure_turning.hpp)

  // The outcome of one try: a corrected point that passed every guard and the rule's own test,
  // or a rejection (with the rule's measurements when it got that far).
  struct Attempt {
    bool ok = false, measured = false;
    Prediction prediction;
    CorrectorResult corrected;
    Vec3 p1 = Vec3::Zero();
    DynamicCurveJet next;
    StepReport report;
    internal::MidpointProbe middle;
  };

  DynamicCurveJet jet_at(const UnknownVec& x, const Vec3* hint) {
    stats->jet_evaluations += order;
    stats->add_surface_evaluations(jet_cost);
    return curve_jet_dynamic(P, x, order, hint);
  }

  Attempt step() {
    Attempt a;
    const double h = std::visit([](const auto& s) { return s.step(); }, rule);
    a.prediction = predict(predictor, P, state, h);
    stats->add_surface_evaluations(a.prediction.evaluations);
    if (a.prediction.fallback) ++stats->predictor_fallbacks;
    const double arc = a.prediction.arc > 0 ? a.prediction.arc : h;
    a.prediction.arc = arc;
    a.corrected = correct(corrector, P, a.prediction.x, co);
    stats->linearizations += a.corrected.linearizations;
    stats->add_surface_evaluations(a.corrected.evaluations);
    if (a.corrected.status != CorrectorStatus::kConverged) {
      ++stats->corrector_failures;
      return a;
    }
    a.p1 = a.corrected.point;  // from the corrector's last linearisation
    if (!a.p1.allFinite()) {
      a.p1 = P.point(a.corrected.x);
      if (P.kind() != PairKind::kImplicitImplicit) ++stats->surface_evaluations[0];
    }
    if (!internal::chord_is_plausible(cur, a.p1, a.prediction.point, arc, o)) return a;
    a.next = jet_at(a.corrected.x, &cur.t);
    if (a.next.status != CurveJetStatus::kOk || !internal::turn_is_plausible(cur.t, a.next.tangent(), o)) return a;
    // The step's middle: off the curve when the step left its arc (kMidpointDeviationRatio);
    // its rank ratio feeds the watch for singular points the chord passes (watch_event).
    const double chord = (a.p1 - cur.p).norm();
    a.middle = internal::probe_midpoint(P, cur.x, state.here.x[1], a.corrected.x, a.next.x[1], chord, stats);
    if (!(a.middle.deviation <= kMidpointDeviationRatio * chord)) return a;
    a.report = make_step_report(cur.p, cur.t, a.p1, a.next.tangent(), a.prediction.point, arc, a.corrected.iterations);
    a.measured = true;
    a.ok = std::visit([&](const auto& s) { return s.acceptable(a.report); }, rule);
    return a;
  }

  // False when the rule gives up (h < min_step).
  bool reject(const Attempt& a) {
    ++stats->rejected_steps;
    return std::visit([&](auto& s) { return s.rejected(a.measured ? &a.report : nullptr); }, rule);
  }

  void accept(Attempt& a, MarchResult* r) {
    stats->record_iterations(a.corrected.iterations);
    ++stats->points;
    r->length += arc_length_estimate(cur.p, cur.t, a.p1, a.next.tangent());
    // An unwatched step across a crossing of branches (the orientation reverses) leaves the
    // arc simple no more, and its index unknown.
    if (a.next.orientation != state.here.orientation) turning.lose();
    const UnknownVec d = P.difference(cur.x, a.corrected.x);
    turning.step(Vec2(a.next.x[1][0], a.next.x[1][1]), Vec2(d[0], d[1]));
    state.has_previous = true;
    state.previous_x = cur.x;
    state.previous_p = cur.p;
    state.previous_t = cur.t;
    state.circle_line_parameter = a.prediction.circle_line_parameter;
    state.circle_line_axis = a.prediction.circle_line_axis;
    cur = CurvePoint{a.corrected.x, a.p1, a.next.tangent()};
    state.here = std::move(a.next);
    r->points.push_back(cur);
    const CurveGeometry frame = frenet_from_jet(state.here, P.scale());
    std::visit([&](auto& s) { s.accepted(a.report, frame); }, rule);
  }

  // Continues from p, a point just past a pole, in the new chart: no previous point carries
  // over (its parameters belong to the other side of the pole).
  bool restart(const CurvePoint& p) {
    turning.lose();  // the turning in one chart says nothing in the other
    DynamicCurveJet j = jet_at(p.x, &p.t);
    if (j.status != CurveJetStatus::kOk) return false;
    state = MarchState{};
    state.map_tolerance = o.tolerance;
    state.here = std::move(j);
    cur = p;
    ++stats->points;
    return true;
  }
};

// The pole the march is passing: the step's corrected point lies beyond a degenerate edge, or
// (no step possible) the pole point is within two steps ahead of cur.
const Pole* pole_ahead(const Problem& P, const std::vector<Pole>& poles, const CurvePoint& cur,
                       const Marcher::Attempt* a, double reach) {
  if (poles.empty()) return nullptr;
  if (a && a->corrected.status == CorrectorStatus::kConverged && !P.inside(a->corrected.x))
    return internal::crossed_pole(P, poles, cur, a->corrected.x);
  if (a) return nullptr;
  for (const Pole& pole : poles)
    if ((pole.point - cur.p).norm() <= reach && (pole.point - cur.p).dot(cur.t) > 0) return &pole;
  return nullptr;
}

Event budget_event(BudgetBound bound, const std::string& message) {
  Event e;
  e.kind = EventKind::kBudget;
  e.bound = bound;
  e.message = message;
  return e;
}

// The watch on a step from cur (jet `here`) to the attempt's point (MarchLimits::watch_crossings):
// kSingularSuspected with Event::beyond = the attempt's point when the tangent orientation reverses
// (a crossing of branches passed), the rank ratio of J_H has a local minimum below
// kWatchRankRatio at cur, by more than kRankMinimumMargin (a tacnode passed near), or it dips in the middle of the step
// below kRankDipRatio times its smaller end value (a singular point the chord passes without a reversal: a triple point
// along a branch, or a long step past a quadruple point); kBudget (no event) otherwise.
Event watch_event(const CurvePoint& cur, double previous_rank, double previous_middle, const DynamicCurveJet& here,
                  const Marcher::Attempt& a) {
  const double r1 = here.rank_ratio, r2 = a.next.rank_ratio, rm = a.middle.rank_ratio;
  if (a.next.orientation != here.orientation)
    return Event{EventKind::kSingularSuspected, BudgetBound::kNone,
                 "the tangent orientation reverses between " + describe_point(cur.p) + " and " + describe_point(a.p1) +
                     ": a crossing of branches lies between",
                 a.corrected.x};
  if (const double below = 1 - kRankMinimumMargin;
      r1 < kWatchRankRatio && r1 < below * previous_rank && r1 < below * r2)
    return Event{EventKind::kSingularSuspected, BudgetBound::kNone,
                 "the rank ratio of the Jacobian has a local minimum " + std::to_string(r1) + " at " + describe_point(cur.p),
                 a.corrected.x};
  if (rm < kRankDipRatio * std::min(r1, r2))
    return Event{EventKind::kSingularSuspected, BudgetBound::kNone,
                 "the rank ratio of the Jacobian dips to " + std::to_string(rm) + " between " + describe_point(cur.p) +
                     " and " + describe_point(a.p1) + ": a singular point lies near the chord",
                 a.corrected.x};
  // The same dip with cur at its bottom, against the middles of the steps on either side: the
  // march came within a fraction of a step of a singular point that neither chord passes by
  // its middle (a long step ending next to the triple point of the three-petal rose).
  if (r1 < kRankDipRatio * std::min(previous_middle, rm))
    return Event{EventKind::kSingularSuspected, BudgetBound::kNone,
                 "the rank ratio of the Jacobian dips to " + std::to_string(r1) + " at " + describe_point(cur.p) +
                     " between the middles of its steps: a singular point lies next to it",
                 a.corrected.x};
  return Event{};
}

// The march passes `pole` (march/pole_passage.hpp): appends the pole point where the curve goes
// through it and the first point beyond, and restarts there. True when the march ends here: it
// closed (on either chord) or no continuation past the pole exists (the curve ends at it);
// *no_passage when the curve neither passes through the pole nor has a point beyond it (the
// caller may retry a shorter step on this side).
bool pass_pole_step(const Problem& P, const Pole& pole, double h, const CurvePoint& target, double slack,
                    bool may_close, Marcher* m, MarchResult* r, TraceStats* stats, bool* no_passage) {
  const double distance = std::max((pole.point - m->cur.p).norm(), 0.25 * h);
  const PolePassage pp = pass_pole(P, pole, m->cur, distance, m->co);
  auto end = [&](EventKind kind, const std::string& message) {
    r->event = Event{kind, BudgetBound::kNone, message, UnknownVec{}};
    return true;
  };
  auto close_on = [&](const CurvePoint& a, const Vec3& p1, const Vec3& t1) {
    if (!may_close || !internal::closes_loop(target, a, p1, t1, slack)) return false;
    r->length += arc_length_estimate(a.p, a.t, target.p, target.t);
    r->points.push_back(target);
    return end(EventKind::kClosed, "closed loop");
  };
  const CurvePoint& from = pp.through ? pp.at_pole : m->cur;
  if (pp.through) {
    if (close_on(m->cur, pole.point, pp.at_pole.t)) return true;
    r->length += arc_length_estimate(m->cur.p, m->cur.t, pole.point, pp.at_pole.t);
    r->points.push_back(pp.at_pole);
    ++stats->points;
    if (!pp.ok) return end(EventKind::kDomainEdge, "reached the pole " + describe_point(pole.point) + ", where the curve ends: " + pp.message);
  } else if (!pp.ok) {
    *no_passage = true;
    return end(EventKind::kStepUnderflow, "passing near the pole: " + pp.message);
  }
  if (close_on(from, pp.beyond.p, pp.beyond.t)) return true;
  r->length += arc_length_estimate(from.p, from.t, pp.beyond.p, pp.beyond.t);
  r->points.push_back(pp.beyond);
  if (!m->restart(pp.beyond)) return end(EventKind::kSingularSuspected, "no tangent past the pole at " + describe_point(pp.beyond.p));
  return false;
}

// Why a march cannot leave its start: the curve is singular there, or the start lies on a domain
// edge and the curve leaves the domain through it.
std::optional<Event> start_event(const Problem& P, const CurvePoint& start, const DynamicCurveJet& here) {
  if (here.status != CurveJetStatus::kOk)
    return Event{EventKind::kSingularSuspected, BudgetBound::kNone,
                 "the start point " + describe_point(start.p) + " is a singular point of the curve", UnknownVec{}};
  if (const int i = internal::bound_left_at(P, start.x, here.x[1]); i >= 0)
    return Event{
        EventKind::kDomainEdge, BudgetBound::kNone,
        "starts on the domain edge " + P.unknown_names()[static_cast<std::size_t>(i)] + " and leaves the domain there",
        UnknownVec{}};
  return std::nullopt;
}

// The closure allowance: rounding of the model's coordinates, plus the corrector tolerance
// magnified by the conditioning of the point across the curve, 1/sin(theta) between the
// normals (a near-tangential loop's points are known only to tolerance/sin(theta)). The
// projection and tangent tests of closes_loop keep a generous allowance from closing early,
// so a loop of any size relative to the step closes once (docs/marching.md, "Closure").
double closure_slack(const Problem& P, const TraceOptions& o, const CurvePoint& start, TraceStats* stats) {
  const Linearization L0 = P.linearize(start.x);
  stats->add_surface_evaluations(linearize_evaluation_cost(P));
  const double sin0 = L0.normal_first.cross(L0.normal_second).norm();
  return 1e-8 * P.scale() + 10 * o.tolerance * (1 + 1 / std::max(sin0, 1e-8));
}

// A step that meets a pole, passed by pass_pole_step: true when the march ends there. A step
// that neither passes through the pole nor finds a curve point beyond it goes on: a loop round
// the pole smaller than the step (stress seed 12 pair 2649) is followed by shorter steps on this
// side of it, until the step rule gives up.
bool pole_step_ends(const Problem& P, const Pole& pole, double h, const CurvePoint& target, double slack,
                    bool may_close, bool step_crossed_pole, const Marcher::Attempt& a, Marcher* m, MarchResult* r,
                    TraceStats* stats) {
  bool no_passage = false;
  if (!pass_pole_step(P, pole, h, target, slack, may_close, m, r, stats, &no_passage)) return false;
  if (!(no_passage && step_crossed_pole && m->reject(a))) return true;
  r->event = Event{};
  return false;
}

// The march's own budget (points, length) spent: the event that ends it.
std::optional<Event> budget_reached(const MarchResult& r, const MarchLimits& limits) {
  if (static_cast<long>(r.points.size()) >= limits.max_points)
    return budget_event(BudgetBound::kPoints, "reached max_points = " + std::to_string(limits.max_points));
  if (r.length >= limits.max_length) return budget_event(BudgetBound::kLength, "reached max_length");
  return std::nullopt;
}

// The index condition (closure_turning.hpp) applies to a loop this march traces whole, in a
// parameter plane: from the start back to it in the same direction; otherwise none is kept.
ClosureTurning closure_turning(const Problem& P, const CurvePoint& start, const CurvePoint& target,
                               const DynamicCurveJet& here) {
  if (P.kind() == PairKind::kImplicitImplicit || (target.p - start.p).norm() != 0 || !(target.t.dot(start.t) > 0))
    return ClosureTurning{};
  const auto& T = P.periods();
  return ClosureTurning(Vec2(here.x[1][0], here.x[1][1]), Vec2(T[0], T[1]));
}

// The loop closes at `target`: its last chord and the closed event.
void close_at(const CurvePoint& target, const CurvePoint& from, MarchResult* r) {
  r->length += arc_length_estimate(from.p, from.t, target.p, target.t);
  r->points.push_back(target);
  r->event = Event{EventKind::kClosed, BudgetBound::kNone, "closed loop", UnknownVec{}};
}

}  // namespace

MarchResult Tracer::march_until_event(const CurvePoint& start_point, Direction direction, const MarchLimits& limits,
                                      TraceStats* stats) const {
  const CurvePoint start =
      direction == Direction::kForward ? start_point : CurvePoint{start_point.x, start_point.p, -start_point.t};
  MarchResult r;
  r.points.push_back(start);
  Marcher m(problem_, options_, stats);
  m.state.map_tolerance = options_.tolerance;
  m.state.here = m.jet_at(start.x, &start.t);
  m.cur = start;
  if (std::optional<Event> e = start_event(problem_, start, m.state.here)) {
    r.event = std::move(*e);
    return r;
  }
  std::visit([&](auto& s) { s.start(frenet_from_jet(m.state.here, problem_.scale())); }, m.rule);
  const double sagitta_slack = closure_slack(problem_, options_, start, stats);
  const CurvePoint& target = limits.close_at ? *limits.close_at : start;
  // A target other than the start may lie on the very first chord (just past a singular point).
  const std::size_t first_closing = (target.p - start.p).norm() > 0 ? 1 : 3;
  m.turning = closure_turning(problem_, start, target, m.state.here);
  bool watch = limits.watch_crossings && !limits.skip_first_watch;
  double previous_rank = 0;  // rank ratio at the point before m.cur (0: none, no minimum at the start)
  double previous_middle = 0;  // rank ratio at the middle of the step that reached m.cur (0: none)
  const std::vector<Pole> poles = problem_poles(problem_);
  auto may_close = [&] { return limits.detect_closure && r.points.size() >= first_closing; };
  while (true) {
    if (std::optional<Event> e = budget_reached(r, limits)) {
      r.event = std::move(*e);
      return r;
    }
    Marcher::Attempt a = m.step();
    const double h = std::visit([](const auto& s) { return s.step(); }, m.rule);
    const Pole* pole = pole_ahead(problem_, poles, m.cur, &a, 0);
    const bool step_crossed_pole = pole != nullptr;
    if (!pole && !a.ok && !m.reject(a)) {
      pole = pole_ahead(problem_, poles, m.cur, nullptr, 2 * options_.step_length);
      if (!pole) {
        r.event = internal::stuck_event(problem_, m.cur, m.state.here.rank_ratio, options_.min_step, stats);
        return r;
      }
    }
    if (pole) {
      if (pole_step_ends(problem_, *pole, h, target, sagitta_slack, may_close(), step_crossed_pole, a, &m, &r, stats))
        return r;
      continue;
    }
    if (!a.ok) continue;
    if (!problem_.inside(a.corrected.x)) {
      r.event = internal::land_on_domain_edge(problem_, m.cur, a.corrected.x, m.co, stats, &r);
      return r;
    }
    // The watch before the closure test: a closing step that also crosses a singular point
    // passes that point first (a start moved half a step off a node lies beyond it), and the
    // caller must register the passage, or the node's half-branches stay unused and are traced
    // again (issue 11: every branch exactly once). The caller closes the loop at the located
    // point when the target lies before it (trace/through_singular.cpp, closes_before).
    if (Event e = watch ? watch_event(m.cur, previous_rank, previous_middle, m.state.here, a) : Event{};
        e.kind == EventKind::kSingularSuspected) {
      r.event = std::move(e);
      return r;
    }
    // Proximity and first order (closes_loop), then the index condition (closure_turning.hpp):
    // a strand passing by the start after a partial turn is not the loop closing.
    if (may_close() && internal::closes_loop(target, m.cur, a.p1, a.next.tangent(), sagitta_slack) &&
        m.turning.admits_closure()) {
      close_at(target, m.cur, &r);
      return r;
    }
    watch = limits.watch_crossings;
    previous_rank = m.state.here.rank_ratio;
    previous_middle = a.middle.rank_ratio;
    m.accept(a, &r);
    if (limits.traced && near_traced_curve(m.cur.p, *limits.traced, limits.traced_radius)) {
      r.event = Event{EventKind::kReachedTracedCurve, BudgetBound::kNone,
                      "reached a traced curve at " + describe_point(m.cur.p), UnknownVec{}};
      return r;
    }
  }
}

}  // namespace ssimarch
