// The marching tracer: follows H(x) = 0 from a point of the curve in one direction with a
// predictor, a corrector and a step rule until an event (thesis ch. 4; docs/marching.md):
// the curve closed, reached the domain edge, came to a suspected singular point or to a curve
// traced before, exhausted a budget, or could take no step at a regular point. Whole-curve and
// whole-problem tracing live in the stages above: start points in start/, both directions,
// skipping traced curves and singular points in trace/, the curve network in network/.
//
// Properties:
//  (1) every accepted point is within options.tolerance (model units) of both surfaces;
//  (2) every loop is bounded (max_points, max_length, max corrector iterations, min_step),
//      and each march says why it stopped (Event);
//  (3) a closed curve ends exactly on its first point and is traced once: the closure test runs
//      on every accepted chord (loop_closure.cpp);
//  (4) at a crossing of two branches (a node), the step crosses the node along the incoming
//      tangent and the corrector stays on the incoming branch: steps that turn the tangent by
//      more than max_turn_angle or move the point farther than max_correction_ratio * h from the
//      prediction are rejected and retried shorter (step_guards.cpp).
#pragma once

#include <algorithm>

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/march/options.hpp"
#include "ssimarch/march/resolved_options.hpp"
#include "ssimarch/march/result.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// What stopped a march. Each value states its exact condition.
enum class EventKind {
  kClosed,              // the start lay on the last chord (within the chord's sagitta bound) with
                        // tangents agreeing; the last point is the start itself
  kDomainEdge,          // a non-periodic unknown reached its bound; the last point lies on it
  kSingularSuspected,   // no step >= min_step could be taken and the rank ratio of J_H or the
                        // sine of the angle between the normals is < kSuspectSingularRankRatio;
                        // or (MarchLimits::watch_crossings) the next step would have reversed the
                        // tangent orientation: Event::beyond holds that step's end
  kReachedTracedCurve,  // the last point is within MarchLimits::traced_radius of a traced curve
  kBudget,              // MarchLimits::max_points or max_length reached (Event::bound says which)
  kStepUnderflow,       // no step >= min_step could be taken at a regular point
};
std::string_view to_string(EventKind kind);

/// Which budget a kBudget event exhausted.
enum class BudgetBound { kNone, kPoints, kLength };

struct Event {
  EventKind kind = EventKind::kBudget;
  BudgetBound bound = BudgetBound::kNone;
  std::string message;  // details for people: the point, the rank ratio, the edge, ...
  UnknownVec beyond;          // kSingularSuspected by a reversed orientation: the end of the step not
                        // taken (a crossing lies between the last point and it); else empty
};
/// How a curve end reports the event (result.hpp).
Termination to_termination(const Event& event);

/// Along the start point's tangent, or against it.
enum class Direction { kForward, kBackward };

/// The bounds of one march.
struct MarchLimits {
  long max_points = 200000;  // points of this march, the start included
  double max_length = std::numeric_limits<double>::infinity();  // model units
  bool detect_closure = true;  // stop with kClosed on coming back to the start
  // Stop with kReachedTracedCurve once an accepted point is within traced_radius (model units)
  // of one of these curves' polylines; null: never.
  const std::vector<TracedCurve>* traced = nullptr;
  double traced_radius = 0;
  // Stop with kSingularSuspected before a step whose ends have opposite tangent orientations
  // (CurveJet::orientation): the step passed a crossing of branches (thesis ch. 5 §5.2.1).
  bool watch_crossings = false;
  bool skip_first_watch = false;  // the first step is not watched (a restart after a near miss)
  // The point whose return closes the curve (a march continuing a curve through a singular
  // point); null: the march's own start.
  const CurvePoint* close_at = nullptr;
};

struct MarchResult {
  std::vector<CurvePoint> points;  // the start first; tangents point along the direction of travel
  Event event;
  double length = 0;  // arc length (model units), circular-arc estimate per segment
};

class Tracer {
 public:
  /// Throws InputError when the options are invalid (TraceOptions::is_valid). Resolves the
  /// automatic (zero) step_length, min_step_length, min_step and deviation (options.hpp).
  Tracer(const Problem& problem, TraceOptions options);
  /// With options checked and resolved for this problem once (resolve_trace_options, as the
  /// pipeline does): used as they are, not checked again.
  Tracer(const Problem& problem, const ResolvedTraceOptions& resolved);

  /// Marches from `start` (a regular point of the curve with its unit tangent) in `direction`
  /// until an event; adds the work to *stats (the start itself is not counted as a point).
  MarchResult march_until_event(const CurvePoint& start, Direction direction, const MarchLimits& limits,
                                TraceStats* stats) const;

  /// The options' own limits: max_points, max_length, closure detection on, no traced curves.
  MarchLimits limits() const;
  const TraceOptions& options() const { return options_; }
  const Problem& problem() const { return problem_; }
  /// Distance scale for telling curves and start points apart (model units): the user's
  /// step_length, else the constant rule's automatic step (scale/100), whatever the rule.
  double spacing() const { return spacing_; }
  /// Lowers max_length (model units) keeping the resolved automatic values: constructing a new
  /// Tracer from options() would take the resolved step length as the user's and change spacing().
  void cap_max_length(double max_length) { options_.max_length = std::min(options_.max_length, max_length); }

 private:
  const Problem& problem_;
  TraceOptions options_;  // with the automatic values resolved
  double spacing_ = 0;
};

/// Arc length between two points of a curve with unit tangents ta, tb: the length of the
/// circular arc with that chord and turning angle, c (phi/2) / sin(phi/2); exact on circles.
double arc_length_estimate(const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb);

/// Whether p is within `radius` (model units) of one of the curves' polylines.
bool near_traced_curve(const Vec3& p, const std::vector<TracedCurve>& curves, double radius);

/// "(x, y, z)" with 10 significant digits, for messages.
std::string describe_point(const Vec3& p);

}  // namespace ssimarch
