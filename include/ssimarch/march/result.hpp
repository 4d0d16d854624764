// What a march returns: curves as polylines of points on both surfaces, why each end stopped,
// and the work it took. What a whole trace returns (start-point search, singular points) is
// owned by the stages that make it: start/start_search.hpp, trace/result.hpp.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

/// Why one end of a traced curve stopped. Each value states its exact condition.
enum class Termination {
  kClosedLoop,     // the curve came back to its start: the start lay on the last chord (within the
                   // chord's sagitta bound) with tangents agreeing; the last point is the first one
  kLeftDomain,     // a non-periodic unknown reached its bound; the last point lies on that bound
  kSingularPoint,  // no step of length >= min_step could be taken and the curve's Jacobian is
                   // (nearly) rank deficient there: the last point is next to a singular point
  kStepUnderflow,  // no step of length >= min_step could be taken at a regular point
  kMaxPoints,      // the curve reached options.max_points points
  kMaxLength,      // the traced length reached options.max_length
  kReachedTracedCurve,  // the end came within a given distance of a curve traced before
};
std::string_view to_string(Termination t);

/// A point of a traced curve.
struct CurvePoint {
  UnknownVec x;  // the unknowns of H (params: u,v[,p,q] or x,y,z), periodic ones wrapped into the domain
  Vec3 p;  // the 3D point
  Vec3 t;  // the unit tangent in the direction of travel
};

struct TracedCurve {
  std::vector<CurvePoint> points;
  bool closed = false;
  double length = 0;  // arc length (model units): the sum of segment_lengths where they are given
  // Per segment (points i -> i + 1; a closed curve's last point repeats its first), its length
  // (model units) to kSegmentLengthTolerance (march/refined_arc_length.hpp), as trace_all and the
  // face clip measured it; empty where the points are the only record (the circular-arc estimate
  // plus its shortfall, march/arc_length.hpp, stands in). Whoever changes `points` clears it.
  std::vector<double> segment_lengths;
  Termination start_end = Termination::kClosedLoop;  // why the start end stopped (open curves)
  Termination end_end = Termination::kClosedLoop;
  std::string start_message, end_message;  // details, e.g. the singular point's rank ratio
  // A curve of tangential contact: the surfaces touch all along it (every point singular;
  // traced by trace/tangential_contact.hpp, not marched).
  bool tangential_contact = false;
};

/// Work counters of a trace (the thesis' Tables 4.1-4.4 report the iteration histogram).
struct TraceStats {
  long points = 0;
  long rejected_steps = 0;
  std::array<long, 5> iterations{};  // points by corrector iterations: 1, 2, 3, 4, >= 5
  long linearizations = 0;           // first-order evaluations of both surfaces
  long jet_evaluations = 0;          // higher-order (Taylor) evaluations of H
  long corrector_failures = 0;
  // Calls of the first and of the second surface (Surface::point or Surface::value, any number
  // type: an evaluation with derivatives counts once), by the tracer, its predictor and corrector.
  std::array<long, 2> surface_evaluations{};
  long predictor_fallbacks = 0;      // predictions that fell back to the tangent step (docs/marching.md)
  double time_ms = 0;
  // Wall time is `time_ms` (milliseconds, steady clock), over the whole trace() call.

  void record_iterations(int n) { ++iterations[static_cast<std::size_t>(n <= 1 ? 0 : (n >= 5 ? 4 : n - 1))]; }
  void add_surface_evaluations(const std::array<long, 2>& e) {
    surface_evaluations[0] += e[0];
    surface_evaluations[1] += e[1];
  }
  TraceStats& operator+=(const TraceStats& o);
};

}  // namespace ssimarch
