#include "ssimarch/singular/half_branches.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/singular/tangent_plane_expansion.hpp"

namespace ssimarch {

namespace {

// The angle in (lo, hi) where h changes sign (bisection to the last bit), h(lo) of sign `below`.
double bisect_angle(const std::function<double(double)>& value, double lo, double hi, bool below) {
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    if ((value(mid) < 0) == below)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

// The angle in [lo, hi] where sigma h is least (golden section): two crossings closer together
// than the sampling (branches sharing their leading terms, a tacnode of contact order 3 or 4)
// leave no sign change between samples, only a dip of |h| towards zero there.
double least_angle(const std::function<double(double)>& value, double lo, double hi, double sigma) {
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
  double fa = sigma * value(a), fb = sigma * value(b);
  for (int it = 0; it < 80; ++it) {
    if (fa <= fb)
      hi = b, b = a, fb = fa, a = hi - g * (hi - lo), fa = sigma * value(a);
    else
      lo = a, a = b, fa = fb, b = lo + g * (hi - lo), fb = sigma * value(b);
  }
  return fa <= fb ? a : b;
}

}  // namespace

std::vector<Vec2> circle_crossings(const LocalJet& h, double r, int samples) {
  const std::function<double(double)> value = [&](double a) { return evaluate(h, Vec2(r * std::cos(a), r * std::sin(a))).value; };
  const double step = 2 * M_PI / samples;
  std::vector<double> f(static_cast<std::size_t>(samples) + 1);
  for (int i = 0; i <= samples; ++i) f[static_cast<std::size_t>(i)] = value(i * step);
  std::vector<double> angles;
  auto at = [&](int i) { return f[static_cast<std::size_t>((i % samples + samples) % samples)]; };
  for (int i = 1; i <= samples; ++i) {
    const double f0 = at(i - 1), f1 = at(i);
    if ((f0 < 0 && f1 >= 0) || (f0 >= 0 && f1 < 0)) {
      angles.push_back(bisect_angle(value, (i - 1) * step, i * step, f0 < 0));
      continue;
    }
    // A dip of |h| at sample i with no sign change on either side: look for a hidden pair.
    const double fi = at(i), fn = at(i + 1);
    if (!(std::fabs(fi) < std::fabs(f0) && std::fabs(fi) <= std::fabs(fn)) || (fi < 0) != (fn < 0) || fi == 0) continue;
    const double sigma = fi > 0 ? 1.0 : -1.0;
    const double m = least_angle(value, (i - 1) * step, (i + 1) * step, sigma);
    if (!(sigma * value(m) < 0)) continue;
    angles.push_back(bisect_angle(value, (i - 1) * step, m, sigma < 0));
    angles.push_back(bisect_angle(value, m, (i + 1) * step, sigma > 0));
  }
  std::sort(angles.begin(), angles.end());
  std::vector<Vec2> out;
  for (double a : angles) out.emplace_back(r * std::cos(a), r * std::sin(a));
  return out;
}

namespace {

// Gauss-Newton with minimum-norm steps onto H = 0 (Allgower & Georg ch. 3).
bool onto_curve(const Problem& problem, VecX* x, double tolerance) {
  for (int it = 0; it < 30; ++it) {
    Linearization L = problem.linearize(*x);
    if (!L.h.allFinite() || !L.jacobian.allFinite()) return false;
    if (L.h.norm() <= tolerance) return true;
    Eigen::CompleteOrthogonalDecomposition<MatX> cod(L.jacobian);
    *x -= cod.solve(L.h);
  }
  return problem.linearize(*x).h.norm() <= tolerance;
}

int nearest_line(const Classification& kind, const Vec2& p, Vec2* signed_direction) {
  int best = -1;
  double best_cos = -1;
  for (std::size_t i = 0; i < kind.tangent_cone.size(); ++i) {
    const Vec2& d = kind.tangent_cone[i].direction;
    const double c = std::fabs(d.dot(p)) / p.norm();
    if (c > best_cos) best_cos = c, best = static_cast<int>(i), *signed_direction = d.dot(p) >= 0 ? d : Vec2(-d);
  }
  return best;
}

// The point of the half-branch through the crossing p = X1 d + w1 n at 0.8 X1 along the line (Newton
// in w across the line, started from the quadratic prediction 0.64 w1, well inside the basin of
// the same half-branch); w2 = 0 where it fails.
Vec2 inner_point(const LocalJet& h, const Vec2& p, const Vec2& normal, const Vec2& d) {
  const double X2 = 0.8 * p.dot(d);
  double w2 = 0.64 * p.dot(normal);
  for (int it = 0; it < 50; ++it) {
    LocalValue v = evaluate(h, X2 * d + w2 * normal);
    const double dw = v.value / v.gradient.dot(normal);
    if (!std::isfinite(dw)) return X2 * d;
    w2 -= dw;
    if (std::fabs(dw) <= 1e-16 * std::fabs(w2)) break;
  }
  return X2 * d + w2 * normal;
}

// Leading term c X^gamma of an offset w from two points (X1, w1), (X2, w2) of a half-branch
// (X2 = 0.8 X1): gamma = 0 and c = w1 / X1^2 where the offset is below resolution.
void leading_term(double X1, double w1, double X2, double w2, double* c, double* gamma) {
  *c = w1 / (X1 * X1);
  *gamma = 0;
  if (std::fabs(w1) <= 1e-9 * X1 || w2 == 0 || (w2 > 0) != (w1 > 0)) return;
  double g = std::log(w1 / w2) / std::log(X1 / X2);
  // Puiseux exponents are rationals p/q with q <= the multiplicity: snap to the nearest one with
  // q <= 4 when the estimate is within its O(X^2) error.
  double best = 1;
  for (int q = 1; q <= 4; ++q) {
    const double snapped = std::round(g * q) / q;
    if (std::fabs(snapped - g) < std::fabs(best - g)) best = snapped;
  }
  if (std::fabs(best - g) <= 0.02) g = best;
  *gamma = g;
  *c = w1 / std::pow(X1, g);
}

// The leading term of the offset from the line d in the chart, from the crossing p and the
// point of the same half-branch at 0.8 X (its sign w.r.t. `normal`); `inner` receives that point.
void offset_term(const LocalJet& h, const Vec2& p, const Vec2& normal, const Vec2& d, HalfBranch* b, Vec2* inner) {
  const double X1 = p.dot(d), w1 = p.dot(normal);
  *inner = inner_point(h, p, normal, d);
  double w2 = inner->dot(normal);
  if (std::fabs(w1) <= 1e-9 * X1) w2 = 0;
  leading_term(X1, w1, inner->dot(d), w2, &b->offset_coefficient, &b->offset_exponent);
}

// The same two points of the half-branch mapped to 3D by the chart's jet, measured over the
// tangent plane: X along tangent_3d, W along normal_3d (the frame of the reported expansion).
void tangent_plane_term(const LocalCurve& curve, const Vec2& p, const Vec2& inner, HalfBranch* b) {
  const Vec3 q1 = curve.point_at(p) - curve.origin, q2 = curve.point_at(inner) - curve.origin;
  leading_term(q1.dot(b->tangent_3d), q1.dot(b->normal_3d), q2.dot(b->tangent_3d), q2.dot(b->normal_3d),
               &b->leading_coefficient, &b->leading_exponent);
}

// How far half-branch B is from continuing A analytically through the point, from their Puiseux
// expansions W = sum b_e X^e in their own frames (tangent, rot90(tangent)), weighted by r^e (the
// size of each term on the circle of radius r). One analytic branch w(x) = sum a_j x^j of the
// line's frame gives, on opposite sides, b_j^B = (-1)^(j+1) b_j^A (X = -x and the normal turns
// with the tangent); two halves of a cusp-like branch W = sum b_j tau^j, X = tau^q on the same side
// are tau -> -tau, b^B = (-1)^j b^A with j = q e. This separates branches that share leading
// terms (a tacnode whose branches differ first at X^3, a ramphoid cusp's halves at X^(5/2)).
double continuation_mismatch(const HalfBranch& A, const HalfBranch& B, double r) {
  const bool same_side = A.tangent.dot(B.tangent) > 0;
  const int q = std::max(A.chart_expansion.denominator, B.chart_expansion.denominator);
  auto coefficient = [](const HalfBranch& h, double e) {
    for (const PuiseuxTerm& t : h.chart_expansion.terms)
      if (std::fabs(t.exponent - e) <= 1e-9) return t.coefficient;
    return 0.0;
  };
  std::vector<double> exponents;
  for (const HalfBranch* h : {&A, &B})
    for (const PuiseuxTerm& t : h->chart_expansion.terms) exponents.push_back(t.exponent);
  double cost = 0;
  for (double e : exponents) {
    const double j = e * q;
    const bool integral = std::fabs(e - std::round(e)) <= 1e-9;
    double sign = 0;
    if (same_side) sign = (std::lround(j) % 2 == 0) ? 1.0 : -1.0;
    else if (integral) sign = (std::lround(e) % 2 == 0) ? -1.0 : 1.0;
    else return 1e300;  // a fractional exponent does not continue across the point
    cost += std::fabs(coefficient(B, e) - sign * coefficient(A, e)) * std::pow(r, e);
  }
  return cost;
}

// Pairs half-branches on each tangent line (see the header): opposite sides by matching offsets,
// then same-side leftovers (cusp-like branches).
void pair_half_branches(const Classification& kind, double radius, std::vector<HalfBranch>* hb) {
  int branch = 0;
  auto join = [&](int a, int b) {
    (*hb)[static_cast<std::size_t>(a)].continuation = b;
    (*hb)[static_cast<std::size_t>(b)].continuation = a;
    (*hb)[static_cast<std::size_t>(a)].branch = (*hb)[static_cast<std::size_t>(b)].branch = branch++;
  };
  for (std::size_t l = 0; l < kind.tangent_cone.size(); ++l) {
    const Vec2& d = kind.tangent_cone[l].direction;
    std::vector<int> plus, minus;
    for (std::size_t i = 0; i < hb->size(); ++i)
      if ((*hb)[i].line == static_cast<int>(l)) ((*hb)[i].tangent.dot(d) > 0 ? plus : minus).push_back(static_cast<int>(i));
    auto cost = [&](int a, int b) {
      const HalfBranch &A = (*hb)[static_cast<std::size_t>(a)], &B = (*hb)[static_cast<std::size_t>(b)];
      if (!A.chart_expansion.terms.empty() || !B.chart_expansion.terms.empty()) return continuation_mismatch(A, B, radius);
      const int ga = static_cast<int>(std::lround(A.offset_exponent)), gb = static_cast<int>(std::lround(B.offset_exponent));
      if (ga != gb && A.offset_exponent != 0 && B.offset_exponent != 0) return 1e300;
      const double sign = (ga % 2 == 0) ? 1.0 : -1.0;
      return std::fabs(A.offset_coefficient - sign * B.offset_coefficient);
    };
    // Few half-branches per line: try every assignment of the smaller side into the larger.
    std::vector<int>& small = plus.size() <= minus.size() ? plus : minus;
    std::vector<int>& large = plus.size() <= minus.size() ? minus : plus;
    std::vector<int> perm = large, best_perm = large;
    std::sort(perm.begin(), perm.end());
    double best = std::numeric_limits<double>::infinity();
    do {
      double c = 0;
      for (std::size_t i = 0; i < small.size(); ++i) c += cost(small[i], perm[i]);
      if (c < best) best = c, best_perm = perm;
    } while (std::next_permutation(perm.begin(), perm.end()));
    for (std::size_t i = 0; i < small.size(); ++i) join(small[i], best_perm[i]);
    std::vector<int> rest(best_perm.begin() + static_cast<std::ptrdiff_t>(small.size()), best_perm.end());
    for (std::size_t i = 0; i + 1 < rest.size(); i += 2) join(rest[i], rest[i + 1]);
  }
}

// How regular a point of the curve is: the sine of the angle between the surfaces' normals, which
// does not depend on the units of the parameters (the Jacobian's rank ratio of a torus in angles
// and a plane in lengths at scale 1e6 mixes columns of 1e6 and 1, and read the exits of
// Villarceau's nodes as singular); the rank ratio where a normal is undefined.
double regularity(const Problem& problem, const VecX& x, double rank_ratio) {
  const Linearization L = problem.linearize(x);
  if (!(L.normal_first.squaredNorm() > 0 && L.normal_second.squaredNorm() > 0)) return rank_ratio;
  return L.normal_first.cross(L.normal_second).norm();
}

void exit_point(const Problem& problem, const LocalCurve& curve, const Vec2& p, const HalfBranchOptions& options,
                HalfBranch* b) {
  VecX x = curve.unknowns_at(p);
  const double tol = options.newton_tolerance * problem.scale();
  if (!onto_curve(problem, &x, tol)) return;
  b->exit_x = problem.wrap(x);
  b->exit_point = problem.point(b->exit_x);
  const Vec3 hint = b->exit_point - curve.origin;
  CurveJet<1> jet = curve_jet<1>(problem, b->exit_x, &hint);
  if (jet.status != CurveJetStatus::kOk || regularity(problem, b->exit_x, jet.rank_ratio) < options.min_rank_ratio)
    return;
  b->direction = jet.alpha[1];
  b->direction_x = jet.x[1];
  b->exit_ok = true;
}

}  // namespace

namespace {

std::vector<HalfBranch> half_branches_at(const Problem& problem, const LocalCurve& curve, const Classification& kind,
                                         const HalfBranchOptions& options, double r) {
  std::vector<HalfBranch> out;
  std::vector<Vec2> points = circle_crossings(curve.h, r, options.samples);
  const bool contact = kind.type == SingularType::kTangentialContact || kind.type == SingularType::kTangentLineCrossing;
  if (contact) {
    // A curve of contact is a double zero of h: no sign change, take its line. The sign changes
    // that rounding makes of that double zero (h ~ 1e-16 on both sides of it) are not half-branches
    // of their own: without this the parametric form of the tori of bug23163_1 listed a crossing
    // with three half-branches along one direction of its contact curve.
    Vec2 tangent;
    std::erase_if(points, [&](const Vec2& p) {
      const int line = nearest_line(kind, p, &tangent);
      return line >= 0 && kind.tangent_cone[static_cast<std::size_t>(line)].multiplicity % 2 == 0;
    });
    for (const auto& line : kind.tangent_cone)
      if (line.multiplicity % 2 == 0)
        for (double sgn : {1.0, -1.0}) points.push_back(sgn * r * line.direction);
  }
  const MatX dx = curve.unknowns_jacobian();
  for (const Vec2& p : points) {
    HalfBranch b;
    b.line = nearest_line(kind, p, &b.tangent);
    if (b.line < 0) continue;
    const Vec2& d = kind.tangent_cone[static_cast<std::size_t>(b.line)].direction;
    Vec2 inner;
    offset_term(curve.h, p, Vec2(-d[1], d[0]), b.tangent, &b, &inner);
    b.tangent_3d = curve.direction_3d(b.tangent);
    // The expansion in the half-branch's own frame: rot90(tangent) = +-rot90(d); reported over
    // the tangent plane (tangent_plane_expansion.hpp).
    const auto [num, den] = exponent_fraction(b.offset_exponent);
    const double leading = (b.tangent.dot(d) > 0 ? 1.0 : -1.0) * b.offset_coefficient;
    const Vec2 through(p.dot(b.tangent), p.dot(Vec2(-b.tangent[1], b.tangent[0])));
    b.chart_expansion = puiseux_expansion(curve.h, b.tangent, leading, num, den, 6, &through, curve.germ_length);
    b.normal_3d = curve.direction_3d(Vec2(-b.tangent[1], b.tangent[0]));
    b.expansion = tangent_plane_expansion(curve, b.tangent, b.chart_expansion);
    tangent_plane_term(curve, p, inner, &b);
    if (curve.lifted()) {
      // A degenerate parametrisation (local_curve.hpp): the half-branch's parameters along it by a
      // chord, and none where the implicit form's branch leaves the parametric patch (the other
      // nappe of a cone whose range ends at its apex): its nearest parameters are then far off.
      const VecX x1 = curve.unknowns_at(p), xh = curve.unknowns_at(0.5 * p);
      if ((problem.point(x1) - curve.point_at(p)).norm() > 0.5 * r) continue;
      b.param_tangent = problem.difference(xh, x1) / (0.5 * r);
    } else {
      b.param_tangent = dx * b.tangent;
    }
    exit_point(problem, curve, p, options, &b);
    out.push_back(b);
  }
  pair_half_branches(kind, r, &out);
  return out;
}

}  // namespace

std::vector<HalfBranch> half_branches(const Problem& problem, const LocalCurve& curve, const Classification& kind,
                                      const HalfBranchOptions& options) {
  // A regular point of the curve has no half-branches, except where a parametrisation of the pair
  // is degenerate (a lifted chart: the pole of a B-spline sphere, where J_H loses rank though the
  // curve is smooth): the walk that stopped there passes it along its two halves (issue 27).
  if (kind.type == SingularType::kIsolated || (kind.type == SingularType::kRegular && !curve.lifted())) return {};
  // Near a point of high multiplicity the curve is nearly singular (|grad h| ~ r^(m-1)): widen
  // the circle until every exit point is regular enough to march from.
  std::vector<HalfBranch> out;
  for (int k = 0; k < 4; ++k) {
    out = half_branches_at(problem, curve, kind, options, options.epsilon * curve.germ_length * std::pow(2.0, k));
    if (std::all_of(out.begin(), out.end(), [](const HalfBranch& b) { return b.exit_ok; })) break;
  }
  return out;
}

}  // namespace ssimarch
