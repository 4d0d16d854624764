#include "collapsed_row_chart.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "local_charts.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/expansion_tolerances.hpp"
#include "ssimarch/singular/series.hpp"

namespace ssimarch {

namespace {

using namespace local_charts;
using series::Series;

// Samples of psi along a row (sign changes, then bisection). A row's roots are the directions of
// the surface's generators at P0 lying in the other surface's tangent plane: two for a cone or a
// pole met by a transversal surface, at most a few for any real pair; 256 separates roots 1/40
// of the row apart (a node whose branches cross at 1.4 degrees on a full circle of generators).
constexpr int kRowSamples = 256;

// A collapsed row of D: the parameter `across` (0 = u, 1 = v) is `value` on it, the other runs
// over the row.
struct Row {
  int across = 1;
  double value = 0;
  Vec3 point = Vec3::Zero();
};

Vec3 point_at(const Surface& S, double u, double v) {
  const Vec3T<double> p = S.point(u, v);
  return {p.x, p.y, p.z};
}

Vec2 on_row(const Row& r, double w, double c) { return r.across == 1 ? Vec2(w, c) : Vec2(c, w); }

const Interval& range(const Surface& D, int parameter) { return parameter == 0 ? D.domain().u : D.domain().v; }

// The collapsed row nearest (u, v): the derivative along the row vanishes there (Gauss-Newton on
// F_along(w, c) = 0 in c, a simple zero), and the whole row maps to one point.
std::optional<Row> collapsed_row(const Surface& D, const Vec2& uv, double scale) {
  const FirstOrder f = parametric_first_order(D, uv[0], uv[1]);
  Row row;
  row.across = f.du.norm() <= f.dv.norm() ? 1 : 0;
  const int along = 1 - row.across;
  const double w = uv[along];
  double c = uv[row.across];
  using J2 = Jet<2, 2>;
  J2::MultiIndex mixed{1, 1};
  for (int it = 0; it < 60; ++it) {  // quadratic convergence: a handful of passes
    const Vec2 p = on_row(row, w, c);
    const Vec3T<J2> F = D.point(J2::variable(0, p[0]), J2::variable(1, p[1]));
    Vec3 g = Vec3::Zero(), gc = Vec3::Zero();
    for (int k = 0; k < 3; ++k) g[k] = F[k].d(along), gc[k] = F[k].derivative(mixed);
    if (!(gc.squaredNorm() > 0)) return std::nullopt;
    const double step = g.dot(gc) / gc.squaredNorm();
    c -= step;
    if (!std::isfinite(c)) return std::nullopt;
    if (std::fabs(step) <= 1e-15 * (1 + std::fabs(c))) break;
  }
  const Interval& across = range(D, row.across);
  const double slack = 1e-9 * (1 + across.width());
  if (c < across.lo - slack || c > across.hi + slack) return std::nullopt;
  c = std::min(std::max(c, across.lo), across.hi);
  row.value = c;
  const Vec2 p0 = on_row(row, w, c);
  row.point = point_at(D, p0[0], p0[1]);
  const Interval& a = range(D, along);
  for (int i = 0; i <= 32; ++i) {
    const Vec2 p = on_row(row, a.lo + a.width() * i / 32, c);
    if ((point_at(D, p[0], p[1]) - row.point).norm() > kCollapsedRowRelative * scale) return std::nullopt;
  }
  return row;
}

// The other surface's chart at P0 and what a branch needs of it: the frame (in `c`), the 3D jets
// of the chart, and for a parametric one its parameters and first-order matrix M (s, t) = M (dp, dq).
struct OtherChart {
  bool parametric = false;
  Vec3T<LocalJet> point;
  double unit = 1;          // |grad g| (implicit)
  Vec2 pq = Vec2::Zero();   // (p0, q0) (parametric)
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
};

// The roots w of psi along the row: the generators at P0 along which branches of the curve leave
// it (sign changes of 256 samples, bisection to the last bit).
std::vector<double> row_roots(const Surface& D, const Row& row, const std::function<double(double)>& psi) {
  const int along = 1 - row.across;
  const Interval& a = range(D, along);
  std::vector<double> roots;
  double w0 = a.lo, f0 = psi(w0);
  for (int i = 1; i <= kRowSamples; ++i) {
    const double w1 = a.lo + a.width() * i / kRowSamples, f1 = psi(w1);
    if ((f0 < 0 && f1 >= 0) || (f0 >= 0 && f1 < 0)) {
      double lo = w0, hi = w1;
      const bool below = f0 < 0;
      while (true) {  // to the last bit
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        ((psi(mid) < 0) == below ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    w0 = w1, f0 = f1;
  }
  return roots;
}

// One branch of the curve through P0 in the chart: its unit tangent line direction d (angle in
// [0, pi)) and its offset Y = sum y_k X^k along rot90(d) at X along d.
struct BranchGerm {
  Vec2 d = Vec2::Zero();
  Series y;
};

// The chart's coordinates (s, t) and the height phi of D over the other surface along the common
// normal, as jets of order K in (W, C): D's parameters (w + W along the row, value + C across it).
template <int K>
void height_over_chart(const Problem& pr, int slot, const Vec3T<Jet<2, K>>& Dj, const LocalCurve& c,
                       const OtherChart& o, Jet<2, K>* s, Jet<2, K>* t, Jet<2, K>* phi) {
  using J = Jet<2, K>;
  auto along = [](const Vec3T<J>& v, const Vec3& e) { return v.x * e.x() + v.y * e.y() + v.z * e.z(); };
  const Surface& O = slot == 0 ? pr.second() : pr.first();
  const Vec3 P0 = c.origin;
  if (!o.parametric) {  // the implicit graph's (s, t) are the tangential components exactly
    *s = along(Dj, c.e1) - c.e1.dot(P0);
    *t = along(Dj, c.e2) - c.e2.dot(P0);
    *phi = O.value(Dj) / o.unit;
    return;
  }
  // (p, q) with (O(p, q) - D) . e_i = 0: the chord iteration of the parametric-parametric chart
  // (docs/math/singular_local_curve.md §1), one order per pass.
  const J t1 = along(Dj, c.e1) - c.e1.dot(P0), t2 = along(Dj, c.e2) - c.e2.dot(P0);
  const Eigen::Matrix2d Ai = o.M.inverse();
  J P(o.pq[0]), Q(o.pq[1]);
  for (int it = 0; it <= K; ++it) {
    const Vec3T<J> Oj = O.point(P, Q);
    J r1 = t1 - (along(Oj, c.e1) - c.e1.dot(P0)), r2 = t2 - (along(Oj, c.e2) - c.e2.dot(P0));
    r1[0] = r2[0] = 0.0;
    P += Ai(0, 0) * r1 + Ai(0, 1) * r2;
    Q += Ai(1, 0) * r1 + Ai(1, 1) * r2;
  }
  const Vec3T<J> Oj = O.point(P, Q);
  *phi = along(Dj, c.normal) - along(Oj, c.normal);
  const J dp = P - o.pq[0], dq = Q - o.pq[1];
  *s = o.M(0, 0) * dp + o.M(0, 1) * dq;
  *t = o.M(1, 0) * dp + o.M(1, 1) * dq;
}

// D at (w + W, value + C) as jets of order K.
template <int K>
Vec3T<Jet<2, K>> row_jet(const Surface& D, const Row& row, double w) {
  using J = Jet<2, K>;
  const J W = J::variable(0, w), C = J::variable(1, row.value);
  return row.across == 1 ? D.point(W, C) : D.point(C, W);
}

// The order m in C to which the height vanishes along the row (1 where D's generators at P0 leave
// O's tangent plane: a cone's apex; 2 on a smooth pole, where D's tangent plane is O's: a
// singular point of the curve), with psi_m(w), the coefficient of C^m, sampled along the row; 0
// where the first kMaxRowOrder all vanish.
constexpr int kMaxRowOrder = 3;
int row_order(const Problem& pr, int slot, const Surface& D, const Row& row, const LocalCurve& c, const OtherChart& o,
              std::function<double(double)>* psi) {
  using J = Jet<2, kMaxRowOrder>;
  auto coefficients = [&pr, slot, &D, row, c, o](double w, int m, double* size) {
    const Vec3T<J> Dj = row_jet<kMaxRowOrder>(D, row, w);
    J s, t, phi;
    height_over_chart<kMaxRowOrder>(pr, slot, Dj, c, o, &s, &t, &phi);
    const J::MultiIndex a{0, m};
    if (size) *size = Vec3(Dj.x.coef(a), Dj.y.coef(a), Dj.z.coef(a)).norm();
    return phi.coef(a);
  };
  const Interval& range_w = range(D, 1 - row.across);
  for (int m = 1; m <= kMaxRowOrder; ++m) {
    double largest = 0, scale = 0;
    for (int i = 0; i <= kRowSamples; ++i) {
      double size = 0;
      largest = std::max(largest, std::fabs(coefficients(range_w.lo + range_w.width() * i / kRowSamples, m, &size)));
      scale = std::max(scale, size);
    }
    if (largest > kRowOrderZero * scale) {
      *psi = [coefficients, m](double w) { return coefficients(w, m, nullptr); };
      return m;
    }
  }
  return 0;
}

// The branch leaving the row at w: phi vanishes on the whole row (C = 0), so phi = C phi~ and the
// branch is phi~(W, C) = 0 with phi~_W != 0 at a simple root: W(C) by the chord iteration on
// series, then (s, t)(C), and Y(X) by reverting X(C). Order kLocalOrder - 1 (phi~ loses one).
std::optional<BranchGerm> branch_at(const Problem& pr, int slot, const Row& row, int m, double w, const LocalCurve& c,
                                    const OtherChart& o) {
  const Surface& D = slot == 0 ? pr.first() : pr.second();
  const Vec3T<LocalJet> Dj = row_jet<kLocalOrder>(D, row, w);
  LocalJet s, t, phi;
  height_over_chart<kLocalOrder>(pr, slot, Dj, c, o, &s, &t, &phi);
  LocalJet rest(0.0);  // phi / C^m
  for (int d = 0; d + m <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) set_coef(rest, d - j, j, coef(phi, d - j, j + m));
  const double a = coef(rest, 1, 0), b = coef(rest, 0, 1);
  if (!(std::fabs(a) > kSimpleRowRootRatio * std::hypot(a, b))) return std::nullopt;
  const int K = kLocalOrder - m;
  Series Ws(static_cast<std::size_t>(K + 1), 0.0), Cs = Ws;
  Cs[1] = 1.0;
  for (int it = 0; it < K; ++it) {  // each pass fixes one more order of W(C)
    Series r = series::compose(rest, Ws, Cs, 1);
    r[0] = 0.0;  // w is the root to rounding
    for (std::size_t i = 0; i < Ws.size(); ++i) Ws[i] -= r[i] / a;
  }
  const Series ss = series::compose(s, Ws, Cs, 1), ts = series::compose(t, Ws, Cs, 1);
  Vec2 d(ss[1], ts[1]);
  if (!(d.norm() > 0) || !d.allFinite()) return std::nullopt;
  d.normalize();
  if (d[1] < 0 || (d[1] == 0 && d[0] < 0)) d = -d;
  Series X(ss.size(), 0.0), Y = X;
  for (std::size_t i = 1; i < ss.size(); ++i) X[i] = d[0] * ss[i] + d[1] * ts[i], Y[i] = -d[1] * ss[i] + d[0] * ts[i];
  BranchGerm g;
  g.d = d;
  g.y = series::substitute(Y, series::powers(series::revert(X)));
  return g;
}

// Whether two germs are one branch: the same tangent line and the same offsets on the circle of
// radius rho. A line along the chart's first axis may come out as d or -d (its angle rounds to
// either end of [0, pi): a loop through a NURBS sphere's pole met by an implicit cylinder, issue 27,
// was two germs and h their square, a "tangential contact"); in the flipped frame X -> -X, Y -> -Y
// the offsets are y_k -> (-1)^(k+1) y_k.
bool same_branch(const BranchGerm& a, const BranchGerm& b, double rho) {
  const double s = a.d.dot(b.d) >= 0 ? 1.0 : -1.0;
  if ((a.d - s * b.d).norm() > kSameBranchRelative) return false;
  double gap = 0;
  for (std::size_t k = 1; k < a.y.size(); ++k) {
    const double flip = s > 0 || k % 2 == 1 ? 1.0 : -1.0;
    gap += std::fabs(a.y[k] - flip * b.y[k]) * std::pow(rho, static_cast<double>(k));
  }
  return gap <= kSameBranchRelative * rho;
}

// The branch's equation Y - y(X) = 0 as a jet in (s, t).
LocalJet branch_equation(const BranchGerm& g) {
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  const LocalJet X = g.d[0] * S + g.d[1] * T;
  LocalJet l = -g.d[1] * S + g.d[0] * T, Xk = X;
  for (std::size_t k = 1; k < g.y.size(); ++k, Xk *= X) l -= g.y[k] * Xk;
  return l;
}

// A smooth pole in the other surface's tangent plane (m = 2) along which no branch leaves (psi_2
// keeps one sign: the meridians of D all curve away from O the same way, a sphere's pole resting
// on a plane): the height of D over O to second order, the quadratic form q(s, t) with
// q(d(w)) = psi_2(w) / |(s, t)_C(w)|^2 at every meridian w, (s, t)_C the chart direction in which
// the meridian leaves P0 (least squares over the row's samples). q definite makes P0 an isolated
// point of the intersection (docs/math/singular_local_curve.md §7); nullopt where q is not
// definite within kRowOrderZero of its size or does not fit the samples.
std::optional<LocalJet> definite_height(const Problem& pr, int slot, const Surface& D, const Row& row,
                                        const LocalCurve& c, const OtherChart& o) {
  using J = Jet<2, 2>;
  const Interval& range_w = range(D, 1 - row.across);
  Eigen::MatrixXd A(kRowSamples, 3);
  Eigen::VectorXd b(kRowSamples);
  const J::MultiIndex c1{0, 1}, c2{0, 2};
  for (int i = 0; i < kRowSamples; ++i) {
    const Vec3T<J> Dj = row_jet<2>(D, row, range_w.lo + range_w.width() * (i + 0.5) / kRowSamples);
    J s, t, phi;
    height_over_chart<2>(pr, slot, Dj, c, o, &s, &t, &phi);
    const Vec2 d(s.coef(c1), t.coef(c1));
    if (!(d.norm() > 0) || !d.allFinite()) return std::nullopt;
    const Vec2 u = d.normalized();
    A.row(i) << u[0] * u[0], u[0] * u[1], u[1] * u[1];
    b[i] = phi.coef(c2) / d.squaredNorm();
  }
  const Eigen::Vector3d q = A.colPivHouseholderQr().solve(b);
  const double size = q.cwiseAbs().maxCoeff();
  if (!(size > 0) || !q.allFinite() || (A * q - b).cwiseAbs().maxCoeff() > 1e-6 * size) return std::nullopt;
  if (!(4 * q[0] * q[2] - q[1] * q[1] > kRowOrderZero * size * size)) return std::nullopt;
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  return q[0] * S * S + q[1] * S * T + q[2] * T * T;
}

// The other surface's chart at P0 (regular there, P0 on it).
bool other_chart(const Problem& pr, int slot, const VecX& x, const Row& row, LocalCurve* c, OtherChart* o) {
  const Surface& O = slot == 0 ? pr.second() : pr.first();
  const double tol = 1e-10 * pr.scale();               // locate's gap tolerance (singular/locate.hpp)
  if (pr.kind() != PairKind::kParametricParametric) {  // the implicit graph of the other surface
    if (!implicit_graph(O, row.point, c, &o->point, &o->unit)) return false;
    if (o->unit < kSingularSurfaceGradientRatio * pr.scale() * implicit_hessian_norm(O, c->origin)) return false;
    return (c->origin - row.point).norm() <= tol;
  }
  o->parametric = true;
  const Eigen::Index k = slot == 0 ? 2 : 0;
  o->pq = refine_closest_parameters(O, row.point, Vec2(x[k], x[k + 1]));
  if ((point_at(O, o->pq[0], o->pq[1]) - row.point).norm() > tol) return false;
  if (chart_condition(O, o->pq[0], o->pq[1]) < kDegenerateChartRatio) return false;
  LocalCurve chart;
  if (!parametric_chart(O, o->pq[0], o->pq[1], &chart, &o->point)) return false;
  c->origin = chart.origin, c->normal = chart.normal, c->e1 = chart.e1, c->e2 = chart.e2;
  c->unknowns = chart.unknowns;  // (U, V) of the other surface, linear in (s, t)
  const FirstOrder f = parametric_first_order(O, o->pq[0], o->pq[1]);
  o->M << c->e1.dot(f.du), c->e1.dot(f.dv), c->e2.dot(f.du), c->e2.dot(f.dv);
  return true;
}

// The degenerate surface's parameters of a point P near P0 (LocalCurve::lift): the row's
// generator line through P (largest |(P - P0) . D_across(w)| / |D_across(w)|, signed towards the
// domain where the row is an edge: docs/math/poles.md eq. (4)) and the offset along it, refined
// as D's nearest point. A global nearest-point search from a grid can end on the row itself, or
// on the other nappe of a cone, for points this close to P0.
std::function<VecX(const Vec3&, VecX)> lift_from_row(const Surface& surface, const Row& row, Eigen::Index k) {
  auto D = std::make_shared<const Surface>(surface);
  return [D, row, k](const Vec3& P, VecX x) {
    const int along = 1 - row.across;
    const Interval& a = range(*D, along);
    const Interval& across = range(*D, row.across);
    const double side = row.value <= across.lo ? 1.0 : (row.value >= across.hi ? -1.0 : 0.0);
    double best = -1, w_best = a.lo, offset = 0;
    for (int i = 0; i <= kRowSamples; ++i) {
      const double w = a.lo + a.width() * i / kRowSamples;
      const Vec2 p = on_row(row, w, row.value);
      const FirstOrder f = parametric_first_order(*D, p[0], p[1]);
      const Vec3 g = row.across == 1 ? f.dv : f.du;
      if (!(g.squaredNorm() > 0)) continue;
      const double along_g = (P - row.point).dot(g) / g.norm();
      const double score = side == 0 ? std::fabs(along_g) : side * along_g;
      if (score > best) best = score, w_best = w, offset = (P - row.point).dot(g) / g.squaredNorm();
    }
    const Vec2 guess = on_row(row, w_best, row.value + offset);
    x.segment<2>(k) = refine_closest_parameters(*D, P, guess);
    return x;
  };
}

}  // namespace

LocalCurve collapsed_row_curve(const Problem& pr, const VecX& x, int slot) {
  LocalCurve c;
  c.kind = pr.kind();
  c.base = x;
  const Surface& D = slot == 0 ? pr.first() : pr.second();
  const Eigen::Index k = 2 * slot;
  const std::optional<Row> row = collapsed_row(D, Vec2(x[k], x[k + 1]), pr.scale());
  if (!row) return c;
  OtherChart o;
  if (!other_chart(pr, slot, x, *row, &c, &o)) return c;
  const std::vector<LocalJet> other_unknowns = c.unknowns;
  std::vector<BranchGerm> germs;
  const double rho = 1e-2 * pr.scale();
  std::function<double(double)> psi;
  const int m = row_order(pr, slot, D, *row, c, o, &psi);
  if (m == 0) return c;
  const std::vector<double> roots = row_roots(D, *row, psi);
  for (double w : roots) {
    const std::optional<BranchGerm> g = branch_at(pr, slot, *row, m, w, c, o);
    if (!g) return c;
    bool known = false;
    for (const BranchGerm& h : germs) known = known || same_branch(h, *g, rho);
    if (!known) germs.push_back(*g);
  }
  if (germs.empty()) {
    const std::optional<LocalJet> q = roots.empty() && m == 2 ? definite_height(pr, slot, D, *row, c, o) : std::nullopt;
    if (!q) return c;
    c.h = *q;
  } else {
    c.h = LocalJet(1.0);
    for (const BranchGerm& g : germs) c.h *= branch_equation(g);
    c.gap_degree = static_cast<int>(germs.size());
  }
  c.point = {o.point.x, o.point.y, o.point.z};
  // The unknowns: the degenerate surface's lifted by nearest points (its parameters are not
  // functions of the point at P0), the other's from its chart (parametric) or none.
  VecX base = x;
  const Vec2 on = on_row(*row, x[k + (row->across == 1 ? 0 : 1)], row->value);
  base.segment<2>(k) = on;
  c.unknowns.clear();
  for (Eigen::Index i = 0; i < base.size(); ++i) c.unknowns.emplace_back(base[i]);
  if (o.parametric) {
    const std::size_t j = slot == 0 ? 2 : 0;
    c.unknowns[j] = other_unknowns[0], c.unknowns[j + 1] = other_unknowns[1];
    base.segment<2>(static_cast<Eigen::Index>(j)) = o.pq;
  }
  c.base = base;
  c.lift = lift_from_row(D, *row, k);
  c.status = LocalCurveStatus::kOk;
  return c;
}

}  // namespace ssimarch
