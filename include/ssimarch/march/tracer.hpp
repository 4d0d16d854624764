// The marching tracer: follows H(x) = 0 from start points with a predictor, a corrector and a
// step rule, until each end closes, leaves the domain, or stops at a singular point
// (spec/architecture.md; thesis ch. 4 for marching, spec/marching-directions.md).
//
// Properties:
//  (1) every accepted point is within options.tolerance (model units) of both surfaces;
//  (2) every loop is bounded (max_points, max_length, max corrector iterations, min_step),
//      and each end of a curve says why it stopped (Termination);
//  (3) a closed curve ends exactly on its first point and is traced once: the closure test runs
//      on every accepted chord (result.hpp, Termination::kClosedLoop);
//  (4) at a crossing of two branches (a node), the step crosses the node along the incoming
//      tangent and the corrector stays on the incoming branch: steps that turn the tangent by
//      more than max_turn_angle or move the point farther than max_correction_ratio * h from the
//      prediction are rejected and retried shorter.
#pragma once

#include <vector>

#include "ssimarch/march/options.hpp"
#include "ssimarch/march/problem.hpp"
#include "ssimarch/march/result.hpp"

namespace ssimarch {

class Tracer {
 public:
  /// Throws InputError when the options are invalid (TraceOptions::is_valid). Resolves the
  /// automatic (zero) step_length, min_step_length, min_step and deviation (options.hpp).
  Tracer(const Problem& problem, TraceOptions options);

  /// Traces every curve through the 3D points `starts` (each near the curve); with no start
  /// points, finds start points by sampling the domain (find_start_points) and traces a curve
  /// through each one not on a curve already traced.
  TraceResult trace(const std::vector<Vec3>& starts = {}) const;

  /// Traces the curve through the solution x0 in both directions.
  TracedCurve trace_from(const VecX& x0, TraceStats* stats) const;

  /// Solutions of H = 0 found by Newton from a grid of samples of the domain, at least half a
  /// step apart. Not a guarantee of finding every component (see the hunting issue).
  std::vector<VecX> find_start_points(TraceStats* stats) const;

  const TraceOptions& options() const { return options_; }
  const Problem& problem() const { return problem_; }

 private:
  struct Branch {
    std::vector<CurvePoint> points;
    Termination why = Termination::kMaxPoints;
    std::string message;
    double length = 0;
  };
  Branch march(const CurvePoint& start, bool detect_closure, TraceStats* stats) const;
  bool on_traced_curve(const Vec3& p, const std::vector<TracedCurve>& curves) const;

  const Problem& problem_;
  TraceOptions options_;  // with the automatic values resolved
  double spacing_ = 0;    // distance scale for telling curves and start points apart (model units)
};

/// Arc length between two points of a curve with unit tangents ta, tb: the length of the
/// circular arc with that chord and turning angle, c (phi/2) / sin(phi/2); exact on circles.
double arc_length_estimate(const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb);

}  // namespace ssimarch
