#include "ssimarch/march/predictor.hpp"

#include <algorithm>
#include <cmath>

namespace ssimarch {

namespace {

// Tangents u, v with |u x v| <= kParallelTolerance |u| |v| (about 1e-8 radians apart) are
// parallel for the circle constructions: the normal planes do not meet in a usable line.
constexpr double kParallelTolerance = 1e-8;
// Seed 000's b = 2 (P - Q).(S - R) counts as 0 when |b| <= kEquidistantTolerance 2 |P - Q| |S - R|
// (the line is then perpendicular to the chord to within 1e-10 radians: every point of it is
// equidistant from P and Q up to rounding).
constexpr double kEquidistantTolerance = 1e-10;
// At most this many Gauss-Newton foot-point iterations per surface in map_to_unknowns.
constexpr int kMapIterations = 8;
// kappa * scale below this: the curve is straight at this point (no normal, no torsion).
constexpr double kStraightCurvature = 1e-12;

using J2 = Jet<2, 1>;

struct SurfacePatch {
  Vec3 p;
  Eigen::Matrix<double, 3, 2> d;
};
SurfacePatch eval_patch(const Surface& s, const Vec2& uv) {
  Vec3T<J2> f = s.point(J2::variable(0, uv[0]), J2::variable(1, uv[1]));
  SurfacePatch r;
  for (int i = 0; i < 3; ++i) {
    r.p[i] = f[i].value();
    r.d(i, 0) = f[i].d(0);
    r.d(i, 1) = f[i].d(1);
  }
  return r;
}

// Foot of Q on a parametric surface by Gauss-Newton from uv (the first iteration is the
// first-order map through the pseudo-inverse of [S_u S_v]).
Vec2 foot_point(const Surface& s, Vec2 uv, const Vec3& Q, double stop, long* evaluations) {
  for (int it = 0; it < kMapIterations; ++it) {
    SurfacePatch f = eval_patch(s, uv);
    ++*evaluations;
    if (!f.p.allFinite() || !f.d.allFinite()) break;
    Vec2 du = f.d.completeOrthogonalDecomposition().solve(Q - f.p);
    if (!du.allFinite()) break;
    uv += du;
    if ((f.d * du).norm() <= stop) break;
  }
  return uv;
}

Prediction tangent_step(const Problem& problem, const MarchState& s, double h) {
  Prediction r;
  r.x = s.here.x[0] + h * s.here.x[1];
  r.point = problem.point(r.x);
  if (problem.kind() != PairKind::kImplicitImplicit) ++r.evaluations[0];
  r.arc = h;
  return r;
}

Prediction fallback_step(const Problem& problem, const MarchState& s, double h) {
  Prediction r = tangent_step(problem, s, h);
  r.fallback = true;
  return r;
}

Prediction from_point(const Problem& problem, const MarchState& s, const Vec3& Q, double arc) {
  Prediction r;
  r.point = Q;
  r.arc = arc;
  r.x = map_to_unknowns(problem, s.here.x[0], Q, s.map_tolerance, &r.evaluations);
  return r;
}

}  // namespace

CurveFrame curve_frame(const DynamicCurveJet& jet, double scale) {
  CurveFrame f;
  f.p = jet.alpha[0];
  f.t = jet.alpha[1];
  if (jet.order >= 2) f.alpha2 = 2.0 * jet.alpha[2];
  if (jet.order >= 3) f.alpha3 = 6.0 * jet.alpha[3];
  f.kappa = f.alpha2.norm();
  if (f.kappa * scale > kStraightCurvature) {
    f.has_normal = true;
    f.n = f.alpha2 / f.kappa;
    f.b = f.t.cross(f.n);
    f.kappa_prime = f.alpha3.dot(f.n);
    f.tau = f.alpha3.dot(f.b) / f.kappa;
  } else {
    f.n = f.b = Vec3::Zero();
    f.kappa_prime = f.alpha3.norm();  // |alpha'''| where the normal is undefined
  }
  return f;
}

VecX map_to_unknowns(const Problem& problem, const VecX& x0, const Vec3& Q, double stop, std::array<long, 2>* evaluations) {
  VecX x = x0;
  switch (problem.kind()) {
    case PairKind::kImplicitImplicit:
      x = Q;
      break;
    case PairKind::kParametricImplicit:
      x.head(2) = foot_point(problem.first(), x0.head(2), Q, stop, &(*evaluations)[0]);
      break;
    case PairKind::kParametricParametric:
      x.head(2) = foot_point(problem.first(), x0.head(2), Q, stop, &(*evaluations)[0]);
      x.tail(2) = foot_point(problem.second(), x0.tail(2), Q, stop, &(*evaluations)[1]);
      break;
  }
  return x;
}

// --- seed 000 ------------------------------------------------------------------------------------

Seed000Circle seed000_circle(const Vec3& P_in, const Vec3& Q_in, const Vec3& u, const Vec3& v, const Vec3& origin,
                             const double* previous_t, int previous_axis) {
  Seed000Circle c;
  const Vec3 P = P_in - origin, Q = Q_in - origin;
  const Vec3 d = u.cross(v);
  if (!(d.norm() > kParallelTolerance * u.norm() * v.norm())) {
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
  // Step 3: |r(t) - P| = |r(t) - Q|  <=>  t = a / b (spec/circular-step.md: R in a, not S).
  const double a = P.squaredNorm() - Q.squaredNorm() - 2 * (P - Q).dot(c.R);
  c.b = 2 * (P - Q).dot(c.S - c.R);
  if (std::fabs(c.b) > kEquidistantTolerance * 2 * (P - Q).norm() * (c.S - c.R).norm()) {
    c.line_parameter = a / c.b;
    c.how = Seed000Circle::Equidistant::kSolved;
  } else if (previous_t && previous_axis == k) {
    // The paper: "use t from the previous iteration".
    c.line_parameter = *previous_t;
    c.how = Seed000Circle::Equidistant::kReusedPrevious;
  } else {
    // No previous t (first step, or measured along another axis): Wu-Andrade's third plane
    // through P with normal u x v picks the point of the line in the plane of the arc.
    Eigen::Matrix3d A;
    A.row(0) = u.transpose();
    A.row(1) = v.transpose();
    A.row(2) = d.transpose();
    Vec3 X = A.partialPivLu().solve(Vec3(u.dot(P), v.dot(Q), d.dot(P)));
    if (!X.allFinite()) {
      c.status = CircleStatus::kNoEquidistantPoint;
      return c;
    }
    c.line_parameter = X[k];  // r(t) has coordinate k equal to t
    c.how = Seed000Circle::Equidistant::kThirdPlane;
  }
  const Vec3 C = c.R + c.line_parameter * (c.S - c.R);
  c.R += origin;
  c.S += origin;
  c.centre = C + origin;
  c.radius = (P - C).norm();
  c.status = std::isfinite(c.radius) ? CircleStatus::kOk : CircleStatus::kNoEquidistantPoint;
  return c;
}

Eigen::Matrix3d seed000_rotation(const Vec3& n) {
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

Vec3 seed000_arc_point(const Vec3& P, const Vec3& Q, const Vec3& C, double rho, double L) {
  const Vec3 n = (P - C).cross(Q - C);
  const Eigen::Matrix3d R = seed000_rotation(n);
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

bool wu_andrade_centre(const Vec3& P, const Vec3& Q, const Vec3& tP, const Vec3& tQ, Vec3* centre) {
  const Vec3 m = tP.cross(tQ);
  if (!(m.norm() > kParallelTolerance * tP.norm() * tQ.norm())) return false;
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

// --- predictors ----------------------------------------------------------------------------------

Prediction TangentPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  return tangent_step(problem, s, h);
}

Prediction CirclePredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  if (!s.has_previous) return fallback_step(problem, s, h);
  const Vec3 &P = s.previous_p, &Q = s.here.alpha[0], &u = s.previous_t, &v = s.here.alpha[1];
  const double* previous_t = s.circle_line_axis >= 0 ? &s.circle_line_parameter : nullptr;
  Seed000Circle c = seed000_circle(P, Q, u, v, Q, previous_t, s.circle_line_axis);
  if (c.status != CircleStatus::kOk) return fallback_step(problem, s, h);
  // Walk on the circle through Q (|Q - C| = |P - C| when C is equidistant; the fallbacks for
  // b = 0 may leave them different, and the arc must start at Q).
  const double rho = (Q - c.centre).norm();
  if (!((P - c.centre).cross(Q - c.centre).norm() > 0) || !(rho > 0)) return fallback_step(problem, s, h);
  Prediction r = from_point(problem, s, seed000_arc_point(P, Q, c.centre, rho, h), h);
  // For the paper's "reuse t": t is the centre's coordinate along `axis` measured from this
  // step's Q; reused at the next step (from its own Q) it keeps the centre at the same height
  // along that axis, which is exact for the planar arcs where b = 0 happens.
  r.circle_line_parameter = c.line_parameter;
  r.circle_line_axis = c.axis;
  return r;
}

Prediction WuAndradePredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  if (!s.has_previous) return fallback_step(problem, s, h);
  const Vec3 &P = s.previous_p, &Q = s.here.alpha[0], &tQ = s.here.alpha[1];
  Vec3 C;
  if (!wu_andrade_centre(P, Q, s.previous_t, tQ, &C)) return fallback_step(problem, s, h);
  const double R = (Q - C).norm();
  if (!(R > 0) || !std::isfinite(R)) return fallback_step(problem, s, h);
  const Vec3 e1 = (Q - C) / R;
  // tQ . (C - Q) = 0 by the second plane, so the unit tangent at Q already lies in the circle's
  // plane; the projection only removes rounding.
  const Vec3 e2 = (tQ - tQ.dot(e1) * e1).normalized();
  const double theta = wu_andrade_angle(h, R);
  return from_point(problem, s, C + R * (std::cos(theta) * e1 + std::sin(theta) * e2), R * theta);
}

Prediction ParabolaPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  CurveFrame f = curve_frame(s.here, problem.scale());
  // kappa n = alpha'' (defined, and zero, where the curve is straight).
  return from_point(problem, s, f.p + h * f.t + (0.5 * h * h) * f.alpha2, h);
}

Prediction PolynomialPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  CurveFrame f = curve_frame(s.here, problem.scale());
  const double h2 = h * h, h3 = h2 * h;
  Vec3 Q;
  if (f.has_normal) {
    // Thesis eq 2.7 in world coordinates (standard torsion: + kappa tau L^3/6 b).
    Q = f.p + (h - f.kappa * f.kappa * h3 / 6) * f.t + (f.kappa * h2 / 2 + f.kappa_prime * h3 / 6) * f.n +
        (f.kappa * f.tau * h3 / 6) * f.b;
  } else {
    // kappa = 0: the same cubic, P + L t + (L^3/6) alpha''' (n and b undefined).
    Q = f.p + h * f.t + (h3 / 6) * f.alpha3;
  }
  return from_point(problem, s, Q, h);
}

Prediction HelixPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  CurveFrame f = curve_frame(s.here, problem.scale());
  if (!f.has_normal) return from_point(problem, s, f.p + h * f.t, h);  // kappa = tau = 0: a line
  // Thesis eq 2.9 placed at P in the Frenet frame, with a = kappa/w^2, bh = tau_dC/w^2,
  // c = 1/w, w = sqrt(kappa^2 + tau^2), and the corrected last coefficient (a bh/c^2) L.
  const double tau_dC = -f.tau;
  const double w2 = f.kappa * f.kappa + f.tau * f.tau, w = std::sqrt(w2);
  const double a = f.kappa / w2, bh = tau_dC / w2, c = 1.0 / w;
  const double phi = h / c, sn = std::sin(phi);
  const double one_minus_cos = 2 * std::sin(phi / 2) * std::sin(phi / 2);
  const Vec3 Q = f.p + ((a * a / c) * sn + (bh * bh / (c * c)) * h) * f.t + (a * one_minus_cos) * f.n +
                 ((a * bh / c) * sn - (a * bh / (c * c)) * h) * f.b;
  return from_point(problem, s, Q, h);
}

Prediction TaylorPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  Prediction r;
  // Own order, even when the tracer's jet is longer (a step rule may need more terms).
  const int k_max = std::min(order, s.here.order);
  r.x = s.here.x[static_cast<std::size_t>(k_max)];
  for (int k = k_max - 1; k >= 0; --k) r.x = (r.x * h + s.here.x[static_cast<std::size_t>(k)]).eval();
  r.point = problem.point(r.x);
  if (problem.kind() != PairKind::kImplicitImplicit) ++r.evaluations[0];
  r.arc = h;
  return r;
}

AnyPredictor make_predictor(const TraceOptions& options) {
  switch (options.predictor) {
    case PredictorKind::kTangent: return TangentPredictor{};
    case PredictorKind::kCircle: return CirclePredictor{};
    case PredictorKind::kCircleWuAndrade: return WuAndradePredictor{};
    case PredictorKind::kParabola: return ParabolaPredictor{};
    case PredictorKind::kPolynomial: return PolynomialPredictor{};
    case PredictorKind::kHelix: return HelixPredictor{};
    case PredictorKind::kTaylor: return TaylorPredictor{options.taylor_order};
  }
  return TangentPredictor{};
}

int jet_order(const AnyPredictor& p) {
  return std::visit([](const auto& x) { return x.jet_order(); }, p);
}

int contact_order(const AnyPredictor& p) {
  return std::visit(
      [](const auto& x) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, TaylorPredictor>)
          return x.order;
        else
          return std::decay_t<decltype(x)>::kContactOrder;
      },
      p);
}

Prediction predict(const AnyPredictor& p, const Problem& problem, const MarchState& s, double h) {
  return std::visit([&](const auto& x) { return x.predict(problem, s, h); }, p);
}

std::array<long, 2> jet_evaluation_cost(const Problem& problem, int order) {
  // curve_jet_n: raw_jacobians (residual + point), linearize (for rank_ratio), then per order
  // k = 2..K one Taylor residual + point. point() calls the first surface unless implicit-implicit.
  const long K = std::max(order, 1);
  if (problem.kind() == PairKind::kImplicitImplicit) return {K + 1, K + 1};
  return {2 * K + 1, K + 1};
}

std::array<long, 2> linearize_evaluation_cost(const Problem&) { return {1, 1}; }

}  // namespace ssimarch
