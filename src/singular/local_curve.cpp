#include "ssimarch/singular/local_curve.hpp"

#include <cmath>
#include <memory>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

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

// |Hess f(p)| (Frobenius), the scale of f where its gradient vanishes.
double implicit_hessian_norm(const Surface& s, const Vec3& p) {
  using J32 = Jet<3, 2>;
  const J32 f = s.value(Vec3T<J32>(J32::variable(0, p.x()), J32::variable(1, p.y()), J32::variable(2, p.z())));
  double n2 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      J32::MultiIndex a{0, 0, 0};
      ++a[static_cast<std::size_t>(i)];
      ++a[static_cast<std::size_t>(j)];
      n2 += f.derivative(a) * f.derivative(a);
    }
  return std::sqrt(n2);
}

// How far a parametric chart is from degenerate: |F_u x F_v| / (|F_u|^2 + |F_v|^2), in [0, 1/2].
double chart_condition(const Surface& s, double u, double v);

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

double chart_condition(const Surface& s, double u, double v) {
  const FirstOrder f = parametric_first_order(s, u, v);
  const double d = f.du.squaredNorm() + f.dv.squaredNorm();
  return d > 0 ? f.du.cross(f.dv).norm() / d : 0.0;
}

// The unit dividing an implicit surface's value into model units over a parametric chart: its
// gradient's length, floored where the surface is singular (a cone's apex) by
// kSingularSurfaceGradientRatio times |Hess g| and the problem's scale (same zero set).
double implicit_unit(const Surface& g, const Vec3& p, double scale) {
  const double grad = implicit_gradient(g, p, nullptr).norm();
  if (grad >= kSingularSurfaceGradientRatio * scale * implicit_hessian_norm(g, p)) return grad;
  return std::max(grad, kSingularSurfaceGradientRatio * scale * implicit_hessian_norm(g, p));
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
  const double unit = implicit_unit(pr.second(), c->origin, pr.scale());
  if (!(unit > 0)) return;
  c->h = pr.second().value(Fj) / unit;
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

// The nearest parameters of a degenerate parametric surface of the pair, replacing the constant
// jets of its unknowns (first, first + 1) at a point of the local curve: near a cone's apex or a
// sphere's pole the parameters are not smooth functions of the point, so they are not jets.
std::function<VecX(const Vec3&, VecX)> lift_parameters(const Problem& pr, bool first, bool second) {
  auto F = first ? std::make_shared<const Surface>(pr.first()) : nullptr;
  auto G = second ? std::make_shared<const Surface>(pr.second()) : nullptr;
  return [F, G](const Vec3& P, VecX x) {
    int slot = 0;
    for (const auto& S : {F, G}) {
      if (S) {
        if (const auto uv = closest_parameters(*S, P)) x.segment<2>(2 * slot) = *uv;
      }
      ++slot;
    }
    return x;
  };
}

// A parametric chart of the pair degenerate at x (a cone's apex, a sphere's pole: F_u x F_v = 0,
// docs/math/singular_local_curve.md §6): the intersection near the point is the same set in 3D,
// so h is built over a chart that is regular there, with the degenerate surface's implicit form
// as the equation. The chart: the other surface's parameters when it is parametric and regular,
// otherwise the implicit form (of the two) whose gradient is larger at the point (the smooth one
// when the other is singular there, as a cone's apex on a sphere's pole).
void degenerate_chart(const Problem& pr, const VecX& x, bool first_degenerate, bool second_degenerate, LocalCurve* c) {
  const Surface &F = pr.first(), &G = pr.second();
  if ((first_degenerate && !F.is_implicit()) || (second_degenerate && !G.is_implicit())) return;
  const bool pp = pr.kind() == PairKind::kParametricParametric;
  c->unknowns.clear();
  for (Eigen::Index i = 0; i < x.size(); ++i) c->unknowns.emplace_back(x[i]);
  const FirstOrder f = parametric_first_order(F, x[0], x[1]);
  if (pp && first_degenerate != second_degenerate) {  // the regular one's parameters are the chart
    const int chart = first_degenerate ? 1 : 0;
    const Surface &C = chart == 0 ? F : G, &D = chart == 0 ? G : F;
    Vec3T<LocalJet> Cj;
    const std::size_t k = static_cast<std::size_t>(2 * chart);
    if (!parametric_chart(C, x[static_cast<Eigen::Index>(k)], x[static_cast<Eigen::Index>(k) + 1], c, &Cj)) return;
    const double unit = implicit_unit(D, c->origin, pr.scale());
    if (!(unit > 0)) return;
    const std::vector<LocalJet> uv = c->unknowns;  // parametric_chart set the chart's (U, V) only
    c->unknowns.clear();
    for (Eigen::Index i = 0; i < x.size(); ++i) c->unknowns.emplace_back(x[i]);
    c->unknowns[k] = uv[0], c->unknowns[k + 1] = uv[1];
    c->h = D.value(Cj) / unit;
    c->point = {Cj.x, Cj.y, Cj.z};
  } else {  // implicit charts: the degenerate parametric surface(s) by their implicit forms
    const Vec3 P0 = f.p;
    const double gf = implicit_gradient(F, P0, nullptr).norm(), gg = implicit_gradient(G, P0, nullptr).norm();
    const bool on_first = gf >= gg;
    LocalCurve chart;
    implicit_chart(on_first ? F : G, on_first ? G : F, P0, &chart);
    if (chart.status != LocalCurveStatus::kOk) return;
    c->origin = chart.origin, c->normal = chart.normal, c->e1 = chart.e1, c->e2 = chart.e2;
    c->h = chart.h;
    c->point = chart.point;
  }
  c->base = x;
  c->lift = lift_parameters(pr, first_degenerate, pp && second_degenerate);
  c->status = LocalCurveStatus::kOk;
}

// Whether the first (0) or second (1) surface of the pair has a degenerate parametric chart at x.
bool degenerate_at(const Problem& pr, const VecX& x, int slot) {
  if (slot == 1 && pr.kind() != PairKind::kParametricParametric) return false;
  const Surface& s = slot == 0 ? pr.first() : pr.second();
  const Eigen::Index k = 2 * slot;
  return chart_condition(s, x[k], x[k + 1]) < kDegenerateChartRatio;
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
  if (lift) r = lift(point_at(st), r);
  return r;
}

Vec3 LocalCurve::point_at(const Vec2& st) const {
  return {evaluate(point[0], st).value, evaluate(point[1], st).value, evaluate(point[2], st).value};
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
  // A degenerate chart of a surface without an implicit form (an expression or a patch) stays:
  // it is still a chart away from the degenerate point itself.
  const bool d0 = problem.kind() != PairKind::kImplicitImplicit && problem.first().is_implicit() && degenerate_at(problem, x, 0);
  const bool d1 = problem.kind() == PairKind::kParametricParametric && problem.second().is_implicit() && degenerate_at(problem, x, 1);
  if (d0 || d1) {
    degenerate_chart(problem, x, d0, d1, &c);
    if (c.status == LocalCurveStatus::kOk && !finite(c)) c.status = LocalCurveStatus::kNonFinite;
    return c;
  }
  switch (problem.kind()) {
    case PairKind::kParametricImplicit: parametric_implicit(problem, x, &c); break;
    case PairKind::kParametricParametric: parametric_parametric(problem, x, &c); break;
    case PairKind::kImplicitImplicit: implicit_implicit(problem, x, &c); break;
  }
  if (c.status == LocalCurveStatus::kOk && !finite(c)) c.status = LocalCurveStatus::kNonFinite;
  return c;
}

}  // namespace ssimarch
