#include "ssimarch/march/osculating_circle_step.hpp"

#include <cmath>

namespace ssimarch {

namespace {
// Seed 000's b = 2 (P - Q).(S - R) counts as 0 when |b| <= kEquidistantTolerance 2 |P - Q| |S - R|
// (the line is then perpendicular to the chord to within 1e-10 radians: every point of it is
// equidistant from P and Q up to rounding).
constexpr double kEquidistantTolerance = 1e-10;

// b = 0 and no previous t on the same axis: Wu-Andrade's third plane through P with normal
// u x v picks the point of the line in the plane of the arc. False when it has none.
bool third_plane_point(const Vec3& P, const Vec3& Q, const Vec3& u, const Vec3& v, const Vec3& d, int k, double* t) {
  Eigen::Matrix3d A;
  A.row(0) = u.transpose();
  A.row(1) = v.transpose();
  A.row(2) = d.transpose();
  Vec3 X = A.partialPivLu().solve(Vec3(u.dot(P), v.dot(Q), d.dot(P)));
  if (!X.allFinite()) return false;
  *t = X[k];  // r(t) has coordinate k equal to t
  return true;
}
}  // namespace

// Seed 000 §3, steps 1-4 (the formulas are in the header).
OsculatingCircle osculating_circle(const Vec3& P_in, const Vec3& Q_in, const Vec3& u, const Vec3& v, const Vec3& origin,
                                   const double* previous_t, int previous_axis) {
  OsculatingCircle c;
  const Vec3 P = P_in - origin, Q = Q_in - origin;
  const Vec3 d = u.cross(v);
  if (!(d.norm() > kParallelTangentsSine * u.norm() * v.norm())) {
    c.status = CircleStatus::kParallelTangents;
    return c;
  }
  // Step 2: the line of the planes u.X = u.P and v.X = v.Q, through the points with coordinate
  // `axis` = 0 and 1; the axis with the largest |(u x v)_k| keeps the 2x2 solve well conditioned.
  int k = 0;
  d.cwiseAbs().maxCoeff(&k);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  Eigen::Matrix2d M;
  M << u[i], u[j], v[i], v[j];
  auto line_point = [&](double value) {
    Eigen::Vector2d rhs(u.dot(P) - u[k] * value, v.dot(Q) - v[k] * value);
    Eigen::Vector2d sol = M.partialPivLu().solve(rhs);
    Vec3 X;
    X[k] = value;
    X[i] = sol[0];
    X[j] = sol[1];
    return X;
  };
  c.axis = k;
  c.R = line_point(0.0);
  c.S = line_point(1.0);
  // Step 3: |r(t) - P| = |r(t) - Q|  <=>  t = a / b (with R in a, not the paper's S).
  const double a = P.squaredNorm() - Q.squaredNorm() - 2 * (P - Q).dot(c.R);
  c.b = 2 * (P - Q).dot(c.S - c.R);
  if (std::fabs(c.b) > kEquidistantTolerance * 2 * (P - Q).norm() * (c.S - c.R).norm()) {
    c.line_parameter = a / c.b;
    c.how = OsculatingCircle::Equidistant::kSolved;
  } else if (previous_t && previous_axis == k) {
    // The paper: "use t from the previous iteration".
    c.line_parameter = *previous_t;
    c.how = OsculatingCircle::Equidistant::kReusedPrevious;
  } else if (third_plane_point(P, Q, u, v, d, k, &c.line_parameter)) {
    c.how = OsculatingCircle::Equidistant::kThirdPlane;
  } else {
    c.status = CircleStatus::kNoEquidistantPoint;
    return c;
  }
  const Vec3 C = c.R + c.line_parameter * (c.S - c.R);
  c.R += origin;
  c.S += origin;
  c.centre = C + origin;
  c.radius = (P - C).norm();
  c.status = std::isfinite(c.radius) ? CircleStatus::kOk : CircleStatus::kNoEquidistantPoint;
  return c;
}

Eigen::Matrix3d osculating_circle_rotation(const Vec3& n) {
  const double n1 = n[0], n2 = n[1], n3 = n[2];
  const double lambda = std::hypot(n2, n3), V = n.norm();
  Eigen::Matrix3d R;
  if (lambda <= 1e-14 * V) {
    const double s = n1 >= 0 ? 1.0 : -1.0;
    R << 0, 0, s, 0, 1, 0, -s, 0, 0;
    return R;
  }
  R << lambda / V, 0, n1 / V,                          //
      -n1 * n2 / (lambda * V), n3 / lambda, n2 / V,    //
      -n1 * n3 / (lambda * V), -n2 / lambda, n3 / V;
  return R;
}

Vec3 osculating_circle_arc_point(const Vec3& P, const Vec3& Q, const Vec3& C, double rho, double L) {
  const Vec3 n = (P - C).cross(Q - C);
  const Eigen::Matrix3d R = osculating_circle_rotation(n);
  // Row-vector convention of the paper: X' = (X - C) [R].
  const Eigen::RowVector3d Pr = (P - C).transpose() * R, Qr = (Q - C).transpose() * R;
  const double alpha = std::atan2(Pr[1], Pr[0]), beta = std::atan2(Qr[1], Qr[0]);
  const double theta = L / rho;
  // n = (P - C) x (Q - C) goes to +k, so P' -> Q' is counter-clockwise; sin(beta - alpha) > 0
  // is the paper's "alpha < beta" without its failure when the angles wrap around +-pi.
  const bool ccw = std::sin(beta - alpha) > 0;
  const double angle = ccw ? beta + theta : beta - theta;
  const Eigen::RowVector3d A(rho * std::cos(angle), rho * std::sin(angle), 0.0);
  return (A * R.transpose()).transpose() + C;
}

Prediction OsculatingCirclePredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  if (!s.has_previous) return internal::fallback_step(problem, s, h);
  const Vec3 &P = s.previous_p, &Q = s.here.alpha[0], &u = s.previous_t, &v = s.here.alpha[1];
  const double* previous_t = s.circle_line_axis >= 0 ? &s.circle_line_parameter : nullptr;
  OsculatingCircle c = osculating_circle(P, Q, u, v, Q, previous_t, s.circle_line_axis);
  if (c.status != CircleStatus::kOk) return internal::fallback_step(problem, s, h);
  // Walk on the circle through Q (|Q - C| = |P - C| when C is equidistant; the fallbacks for
  // b = 0 may leave them different, and the arc must start at Q).
  const double rho = (Q - c.centre).norm();
  if (!((P - c.centre).cross(Q - c.centre).norm() > 0) || !(rho > 0)) return internal::fallback_step(problem, s, h);
  Prediction r = internal::prediction_at(problem, s, osculating_circle_arc_point(P, Q, c.centre, rho, h), h);
  // For the paper's "reuse t": t is the centre's coordinate along `axis` measured from this
  // step's Q; reused at the next step (from its own Q) it keeps the centre at the same height
  // along that axis, which is exact for the planar arcs where b = 0 happens.
  r.circle_line_parameter = c.line_parameter;
  r.circle_line_axis = c.axis;
  return r;
}

}  // namespace ssimarch
