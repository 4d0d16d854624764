#include <cmath>

#include "march_steps.hpp"

namespace ssimarch::internal {

// A closed curve must end exactly on its first point and be traced once (tracer.hpp, property
// 3): testing the start against every accepted chord, with the circular-arc sagitta of that
// chord as the allowance, catches the return however the steps fall.
bool closes_loop(const CurvePoint& start, const CurvePoint& cur, const Vec3& p1, const Vec3& t1, double slack) {
  const Vec3 seg = p1 - cur.p;
  const double tau = (start.p - cur.p).dot(seg) / seg.squaredNorm();
  if (!(tau >= 0 && tau <= 1)) return false;
  const double dist = (start.p - (cur.p + tau * seg)).norm();
  const double phi = angle_between(cur.t, t1);
  const double sagitta = 0.5 * seg.norm() * std::tan(phi / 4);
  return dist <= 2 * sagitta + slack && start.t.dot(cur.t) > 0.5;
}

}  // namespace ssimarch::internal
