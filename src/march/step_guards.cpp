#include <cmath>
#include <limits>
#include <sstream>

#include "march_steps.hpp"
#include "ssimarch/march/predictor.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch::internal {

double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

bool chord_is_plausible(const CurvePoint& cur, const Vec3& p1, const Vec3& predicted, double arc, const TraceOptions& o) {
  const double chord = (p1 - cur.p).norm();
  return chord >= 0.25 * arc && chord <= 1.75 * arc && (p1 - predicted).norm() <= o.max_correction_ratio * arc &&
         (p1 - cur.p).dot(cur.t) > 0;
}

bool turn_is_plausible(const Vec3& t0, const Vec3& t1, const TraceOptions& o) {
  return angle_between(t0, t1) <= o.max_turn_angle;
}

MidpointProbe probe_midpoint(const Problem& problem, const UnknownVec& x0, const UnknownVec& dx0, const UnknownVec& x1,
                             const UnknownVec& dx1, double chord, TraceStats* stats) {
  // Hermite basis at t = 1/2 on [0, chord]: (x0 + x1)/2 + chord (dx0 - dx1)/8; the difference
  // keeps a periodic unknown's step short across its seam.
  const UnknownVec xm = x0 + 0.5 * problem.difference(x0, x1) + (chord / 8) * (dx0 - dx1);
  const Linearization L = problem.linearize(xm);
  ++stats->linearizations;
  stats->add_surface_evaluations(linearize_evaluation_cost(problem));
  MidpointProbe m;
  m.deviation = std::isfinite(L.distance) ? L.distance : std::numeric_limits<double>::infinity();
  m.rank_ratio = Problem::rank_ratio(L);
  return m;
}

Event stuck_event(const Problem& problem, const CurvePoint& cur, double rank_ratio, double min_step, TraceStats* stats) {
  const Linearization L = problem.linearize(cur.x);
  stats->add_surface_evaluations(linearize_evaluation_cost(problem));
  const double sin_theta = L.normal_first.cross(L.normal_second).norm();
  Event e;
  e.kind = rank_ratio < kSuspectSingularRankRatio || sin_theta < kSuspectSingularRankRatio ? EventKind::kSingularSuspected
                                                                                          : EventKind::kStepUnderflow;
  std::ostringstream os;
  os.precision(3);
  os << "no step >= " << min_step << " could be taken after " << describe_point(cur.p) << "; Jacobian rank ratio "
     << rank_ratio << ", sin(angle between normals) " << sin_theta;
  e.message = os.str();
  return e;
}

}  // namespace ssimarch::internal
