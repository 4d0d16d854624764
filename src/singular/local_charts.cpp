#include "local_charts.hpp"

#include <cmath>
#include <memory>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch::local_charts {

using J1 = Jet<2, 1>;
using J3 = Jet<3, 1>;

LocalJet dot_jet(const Vec3T<LocalJet>& a, const Vec3& e) { return a.x * e.x() + a.y * e.y() + a.z * e.z(); }

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

// How far a parametric chart is from degenerate: |F_u x F_v| / (|F_u|^2 + |F_v|^2), in [0, 1/2].
double chart_condition(const Surface& s, double u, double v) {
  // The derivatives per the whole width of each parameter's range, so that the ratio does not
  // depend on the parameters' units: a cylinder of radius 1000 in (angle, height) has
  // |F_u| / |F_v| = 1000 and read as degenerate as the apex of a cone (issue 26).
  auto width = [](const Interval& r) { return std::isfinite(r.width()) && r.width() > 0 ? r.width() : 1.0; };
  const FirstOrder f = parametric_first_order(s, u, v);
  const Vec3 du = width(s.domain().u) * f.du, dv = width(s.domain().v) * f.dv;
  const double d = du.squaredNorm() + dv.squaredNorm();
  return d > 0 ? du.cross(dv).norm() / d : 0.0;
}

// The unit dividing an implicit surface's value into model units over a parametric chart: its
// gradient's length, floored where the surface is singular (a cone's apex) by
// kSingularSurfaceGradientRatio times |Hess g| and the problem's scale (same zero set).
double implicit_unit(const Surface& g, const Vec3& p, double scale) {
  const double grad = implicit_gradient(g, p, nullptr).norm();
  if (grad >= kSingularSurfaceGradientRatio * scale * implicit_hessian_norm(g, p)) return grad;
  return std::max(grad, kSingularSurfaceGradientRatio * scale * implicit_hessian_norm(g, p));
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

// The surface `chart` over its tangent plane at its point nearest P0 (Newton along its gradient):
// origin, frame and P(s, t) = P0 + s e1 + t e2 + w(s, t) N (w by the chord iteration on f = 0).
bool implicit_graph(const Surface& chart, Vec3 P0, LocalCurve* c, Vec3T<LocalJet>* Pj, double* gradient) {
  double f = 0;
  Vec3 grad;
  for (int it = 0; it < 60; ++it) {  // onto f = 0 along grad f
    grad = implicit_gradient(chart, P0, &f);
    if (!(grad.squaredNorm() > 0)) return false;
    Vec3 step = grad * (f / grad.squaredNorm());
    P0 -= step;
    if (step.norm() <= 1e-16 * (1 + P0.norm())) break;
  }
  grad = implicit_gradient(chart, P0, &f);
  if (!(grad.norm() > 0)) return false;
  c->origin = P0;
  c->normal = grad.normalized();
  frame_from_normal(c->normal, Vec3::UnitX(), &c->e1, &c->e2);
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  LocalJet W(0.0);
  for (int it = 0; it <= kLocalOrder + 1; ++it) {
    *Pj = from_frame(P0, c->e1, c->e2, c->normal, S, T, W);
    W -= chart.value(*Pj) / grad.norm();
  }
  *Pj = from_frame(P0, c->e1, c->e2, c->normal, S, T, W);
  *gradient = grad.norm();
  return true;
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

}  // namespace ssimarch::local_charts
