#include "ssimarch/march/wu_andrade_circle.hpp"

#include <cmath>

namespace ssimarch {

bool wu_andrade_centre(const Vec3& P, const Vec3& Q, const Vec3& tP, const Vec3& tQ, Vec3* centre) {
  const Vec3 m = tP.cross(tQ);
  if (!(m.norm() > kParallelTangentsSine * tP.norm() * tQ.norm())) return false;
  Eigen::Matrix3d A;
  A.row(0) = tP.transpose();
  A.row(1) = tQ.transpose();
  A.row(2) = m.transpose();
  // Centred at Q: the three right-hand sides stay small, so no cancellation far from the origin.
  Vec3 X = A.partialPivLu().solve(Vec3(tP.dot(P - Q), 0.0, m.dot(P - Q)));
  if (!X.allFinite()) return false;
  *centre = X + Q;
  return true;
}

Prediction WuAndradeCirclePredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  if (!s.has_previous) return internal::fallback_step(problem, s, h);
  const Vec3 &P = s.previous_p, &Q = s.here.alpha[0], &tQ = s.here.alpha[1];
  Vec3 C;
  if (!wu_andrade_centre(P, Q, s.previous_t, tQ, &C)) return internal::fallback_step(problem, s, h);
  const double R = (Q - C).norm();
  if (!(R > 0) || !std::isfinite(R)) return internal::fallback_step(problem, s, h);
  const Vec3 e1 = (Q - C) / R;
  // tQ . (C - Q) = 0 by the second plane, so the unit tangent at Q already lies in the circle's
  // plane; the projection only removes rounding.
  const Vec3 e2 = (tQ - tQ.dot(e1) * e1).normalized();
  const double theta = wu_andrade_angle(h, R);
  return internal::prediction_at(problem, s, C + R * (std::cos(theta) * e1 + std::sin(theta) * e2), R * theta);
}

}  // namespace ssimarch
