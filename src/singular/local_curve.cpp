#include "ssimarch/singular/local_curve.hpp"

#include <cmath>
#include <memory>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "collapsed_row_chart.hpp"
#include "local_charts.hpp"

namespace ssimarch {

namespace {

using namespace local_charts;


bool finite(const LocalCurve& c) {
  if (!is_finite(c.h)) return false;
  for (const auto& u : c.unknowns)
    if (!is_finite(u)) return false;
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

// The surface `chart` over its tangent plane at the point of it nearest x, h = the surface
// `other` over that chart.
void implicit_chart(const Surface& chart, const Surface& other, const VecX& x, LocalCurve* c) {
  Vec3T<LocalJet> Pj;
  double grad = 0;
  if (!implicit_graph(chart, Vec3(x[0], x[1], x[2]), c, &Pj, &grad)) return;
  const Vec3 P0 = c->origin;
  // h in model units: `other` divided by its gradient's length, or by the chart's where `other`
  // is singular at P0 (its gradient vanishes there: a cone's apex).
  const double gg = implicit_gradient(other, P0, nullptr).norm();
  const double unit = gg >= kSingularSurfaceGradientRatio * grad ? gg : grad;
  c->h = other.value(Pj) / unit;
  c->unknowns = {Pj.x, Pj.y, Pj.z};
  c->point = {Pj.x, Pj.y, Pj.z};
  c->base = P0;
  c->status = LocalCurveStatus::kOk;
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

namespace {

LocalCurve curve_over_a_chart(const Problem& problem, const VecX& x) {
  LocalCurve c;
  c.kind = problem.kind();
  c.base = x;
  const bool pp = problem.kind() == PairKind::kParametricParametric;
  const bool deg0 = problem.kind() != PairKind::kImplicitImplicit && degenerate_at(problem, x, 0);
  const bool deg1 = pp && degenerate_at(problem, x, 1);
  // A degenerate surface without an implicit form (an expression or a patch): on a collapsed row
  // of it that lies on the other surface, the chart of collapsed_row_chart.hpp; elsewhere its own
  // chart stays (still a chart away from the degenerate point itself).
  if (deg0 != deg1 && !(deg0 ? problem.first() : problem.second()).is_implicit()) {
    c = collapsed_row_curve(problem, x, deg0 ? 0 : 1);
    if (c.status == LocalCurveStatus::kOk) {
      if (!finite(c)) c.status = LocalCurveStatus::kNonFinite;
      return c;
    }
    c = LocalCurve{};
    c.kind = problem.kind();
    c.base = x;
  }
  const bool d0 = deg0 && problem.first().is_implicit();
  const bool d1 = deg1 && problem.second().is_implicit();
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

}  // namespace

LocalCurve local_curve(const Problem& problem, const VecX& x) {
  LocalCurve c = curve_over_a_chart(problem, x);
  const double cap = kGermLengthRatio * problem.scale();
  c.germ_length = germ_length(c.h, cap, c.gap_degree);
  if (!(c.germ_length > 0)) c.germ_length = cap;  // a coefficient overflowed: h is not finite (status says so)
  return c;
}

}  // namespace ssimarch
