#include "ssimarch/singular/local_curve.hpp"

#include <cmath>

namespace ssimarch {

namespace {

using J1 = Jet<2, 1>;
using J3 = Jet<3, 1>;

LocalJet dot_jet(const Vec3T<LocalJet>& a, const Vec3& e) { return a.x * e.x() + a.y * e.y() + a.z * e.z(); }

struct FirstOrder {
  Vec3 p, du, dv;
};
FirstOrder parametric_first_order(const Surface& s, double u, double v) {
  Vec3T<J1> f = s.point(J1::variable(0, u), J1::variable(1, v));
  FirstOrder r;
  for (int i = 0; i < 3; ++i) r.p[i] = f[i].value(), r.du[i] = f[i].d(0), r.dv[i] = f[i].d(1);
  return r;
}
Vec3 implicit_gradient(const Surface& s, const Vec3& p, double* value) {
  J3 f = s.value(Vec3T<J3>(J3::variable(0, p.x()), J3::variable(1, p.y()), J3::variable(2, p.z())));
  if (value) *value = f.value();
  return {f.d(0), f.d(1), f.d(2)};
}

// Orthonormal tangent frame (e1, e2) with e1 x e2 = n, e1 along `hint` where it is not parallel to n.
void frame_from_normal(const Vec3& n, const Vec3& hint, Vec3* e1, Vec3* e2) {
  Vec3 a = hint - hint.dot(n) * n;
  if (a.norm() <= 1e-8 * hint.norm() || hint.norm() == 0) {
    int k = 0;
    n.cwiseAbs().minCoeff(&k);
    a = Vec3::Unit(k).cross(n);
  }
  *e1 = a.normalized();
  *e2 = n.cross(*e1);
}

bool finite(const LocalCurve& c) {
  if (!is_finite(c.h)) return false;
  for (const auto& u : c.unknowns)
    if (!is_finite(u)) return false;
  return true;
}

// The first surface F over its tangent plane: (u, v) linear in (s, t).
bool parametric_chart(const Surface& F, double u0, double v0, LocalCurve* c, Vec3T<LocalJet>* Fj) {
  FirstOrder f = parametric_first_order(F, u0, v0);
  Vec3 n = f.du.cross(f.dv);
  if (!(n.norm() > 0) || !n.allFinite()) return false;
  c->normal = n.normalized();
  c->origin = f.p;
  frame_from_normal(c->normal, f.du, &c->e1, &c->e2);
  Eigen::Matrix2d M;
  M << c->e1.dot(f.du), c->e1.dot(f.dv), c->e2.dot(f.du), c->e2.dot(f.dv);
  const Eigen::Matrix2d Mi = M.inverse();
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  LocalJet U = u0 + Mi(0, 0) * S + Mi(0, 1) * T, V = v0 + Mi(1, 0) * S + Mi(1, 1) * T;
  *Fj = F.point(U, V);
  c->unknowns = {U, V};
  return true;
}

void parametric_implicit(const Problem& pr, const VecX& x, LocalCurve* c) {
  Vec3T<LocalJet> Fj;
  if (!parametric_chart(pr.first(), x[0], x[1], c, &Fj)) return;
  const Vec3 grad = implicit_gradient(pr.second(), c->origin, nullptr);
  if (!(grad.norm() > 0)) return;
  c->h = pr.second().value(Fj) / grad.norm();
  c->point = {Fj.x, Fj.y, Fj.z};
  c->status = LocalCurveStatus::kOk;
}

// (p, q) with (G(p,q) - P0) . e_i = 0: G over the tangent plane of F at P0 (Newton, 2 x 2).
bool project_second(const Surface& G, const LocalCurve& c, double* p, double* q, Eigen::Matrix2d* A) {
  for (int it = 0; it < 60; ++it) {
    FirstOrder g = parametric_first_order(G, *p, *q);
    (*A) << c.e1.dot(g.du), c.e1.dot(g.dv), c.e2.dot(g.du), c.e2.dot(g.dv);
    if (!(std::fabs(A->determinant()) > 0) || !A->allFinite()) return false;
    Vec2 r(c.e1.dot(g.p - c.origin), c.e2.dot(g.p - c.origin));
    Vec2 step = A->inverse() * r;
    *p -= step[0];
    *q -= step[1];
    if (step.norm() <= 1e-15 * (1 + std::hypot(*p, *q))) break;
  }
  FirstOrder g = parametric_first_order(G, *p, *q);
  (*A) << c.e1.dot(g.du), c.e1.dot(g.dv), c.e2.dot(g.du), c.e2.dot(g.dv);
  return std::isfinite(*p) && std::isfinite(*q) && std::fabs(A->determinant()) > 0;
}

void parametric_parametric(const Problem& pr, const VecX& x, LocalCurve* c) {
  Vec3T<LocalJet> Fj;
  if (!parametric_chart(pr.first(), x[0], x[1], c, &Fj)) return;
  double p0 = x[2], q0 = x[3];
  Eigen::Matrix2d A;
  if (!project_second(pr.second(), *c, &p0, &q0, &A)) return;
  const Eigen::Matrix2d Ai = A.inverse();
  const LocalJet t1 = dot_jet(Fj, c->e1) - c->e1.dot(c->origin), t2 = dot_jet(Fj, c->e2) - c->e2.dot(c->origin);
  LocalJet P(p0), Q(q0);
  // Each pass of this chord iteration fixes one more order of (p, q)(s, t) (implicit function theorem).
  for (int it = 0; it <= kLocalOrder; ++it) {
    Vec3T<LocalJet> Gj = pr.second().point(P, Q);
    LocalJet r1 = t1 - (dot_jet(Gj, c->e1) - c->e1.dot(c->origin));
    LocalJet r2 = t2 - (dot_jet(Gj, c->e2) - c->e2.dot(c->origin));
    r1[0] = r2[0] = 0.0;  // (p0, q0) is already the solution at (0, 0)
    P += Ai(0, 0) * r1 + Ai(0, 1) * r2;
    Q += Ai(1, 0) * r1 + Ai(1, 1) * r2;
  }
  Vec3T<LocalJet> Gj = pr.second().point(P, Q);
  c->h = dot_jet(Fj, c->normal) - dot_jet(Gj, c->normal);
  c->unknowns.push_back(P);
  c->unknowns.push_back(Q);
  c->point = {Fj.x, Fj.y, Fj.z};
  c->base = VecX(4);
  c->base << x[0], x[1], p0, q0;
  c->status = LocalCurveStatus::kOk;
}

// Ratio |grad f| / |grad g| (dimensionless; model-unit implicit forms) below which an implicit
// surface counts as singular at a point of an implicit-implicit pair (a cone's apex, where its
// gradient vanishes and it has no tangent plane): the local curve is then built over the other
// surface's tangent plane. (To join problem/singular_tolerances.hpp.)
constexpr double kSingularSurfaceGradientRatio = 1e-3;

// The surface `chart` over its tangent plane at the point of it nearest x (Newton along its
// gradient), h = the surface `other` over that chart.
void implicit_chart(const Surface& chart, const Surface& other, const VecX& x, LocalCurve* c) {
  Vec3 P0(x[0], x[1], x[2]);
  double f = 0;
  Vec3 grad;
  for (int it = 0; it < 60; ++it) {  // onto f = 0 along grad f
    grad = implicit_gradient(chart, P0, &f);
    if (!(grad.squaredNorm() > 0)) return;
    Vec3 step = grad * (f / grad.squaredNorm());
    P0 -= step;
    if (step.norm() <= 1e-16 * (1 + P0.norm())) break;
  }
  grad = implicit_gradient(chart, P0, &f);
  if (!(grad.norm() > 0)) return;
  c->origin = P0;
  c->normal = grad.normalized();
  frame_from_normal(c->normal, Vec3::UnitX(), &c->e1, &c->e2);
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  LocalJet W(0.0);
  Vec3T<LocalJet> Pj;
  for (int it = 0; it <= kLocalOrder + 1; ++it) {
    Pj = from_frame(P0, c->e1, c->e2, c->normal, S, T, W);
    W -= chart.value(Pj) / grad.norm();
  }
  Pj = from_frame(P0, c->e1, c->e2, c->normal, S, T, W);
  // h in model units: `other` divided by its gradient's length, or by the chart's where `other`
  // is singular at P0 (its gradient vanishes there: a cone's apex).
  const double gg = implicit_gradient(other, P0, nullptr).norm();
  const double unit = gg >= kSingularSurfaceGradientRatio * grad.norm() ? gg : grad.norm();
  c->h = other.value(Pj) / unit;
  c->unknowns = {Pj.x, Pj.y, Pj.z};
  c->point = {Pj.x, Pj.y, Pj.z};
  c->base = P0;
  c->status = LocalCurveStatus::kOk;
}

void implicit_implicit(const Problem& pr, const VecX& x, LocalCurve* c) {
  const Vec3 p(x[0], x[1], x[2]);
  const double gf = implicit_gradient(pr.first(), p, nullptr).norm();
  const double gg = implicit_gradient(pr.second(), p, nullptr).norm();
  // The first surface singular at x (a cone's apex: grad f = 0, no tangent plane): the chart on
  // the second, whose h then has the intersection's singular point there.
  const bool first_singular = gf < kSingularSurfaceGradientRatio * gg;
  implicit_chart(first_singular ? pr.second() : pr.first(), first_singular ? pr.first() : pr.second(), x, c);
}

}  // namespace

VecX LocalCurve::unknowns_at(const Vec2& st) const {
  VecX r(static_cast<Eigen::Index>(unknowns.size()));
  for (std::size_t i = 0; i < unknowns.size(); ++i) r[static_cast<Eigen::Index>(i)] = evaluate(unknowns[i], st).value;
  return r;
}

MatX LocalCurve::unknowns_jacobian() const {
  MatX J(static_cast<Eigen::Index>(unknowns.size()), 2);
  for (std::size_t i = 0; i < unknowns.size(); ++i) {
    J(static_cast<Eigen::Index>(i), 0) = unknowns[i].d(0);
    J(static_cast<Eigen::Index>(i), 1) = unknowns[i].d(1);
  }
  return J;
}

LocalCurve local_curve(const Problem& problem, const VecX& x) {
  LocalCurve c;
  c.kind = problem.kind();
  c.base = x;
  switch (problem.kind()) {
    case PairKind::kParametricImplicit: parametric_implicit(problem, x, &c); break;
    case PairKind::kParametricParametric: parametric_parametric(problem, x, &c); break;
    case PairKind::kImplicitImplicit: implicit_implicit(problem, x, &c); break;
  }
  if (c.status == LocalCurveStatus::kOk && !finite(c)) c.status = LocalCurveStatus::kNonFinite;
  return c;
}

}  // namespace ssimarch
