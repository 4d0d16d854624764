#include "ssimarch/singular/half_branches.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

std::vector<Vec2> circle_crossings(const LocalJet& h, double r, int samples) {
  auto value = [&](double a) { return evaluate(h, Vec2(r * std::cos(a), r * std::sin(a))).value; };
  std::vector<Vec2> out;
  const double step = 2 * M_PI / samples;
  double a0 = 0, f0 = value(0);
  for (int i = 1; i <= samples; ++i) {
    const double a1 = i * step, f1 = value(a1);
    if ((f0 < 0 && f1 >= 0) || (f0 >= 0 && f1 < 0)) {
      double lo = a0, hi = a1, flo = f0;
      for (int it = 0; it < 60; ++it) {  // bisection to the last bit of the angle
        const double mid = 0.5 * (lo + hi), fm = value(mid);
        if ((fm < 0) == (flo < 0))
          lo = mid, flo = fm;
        else
          hi = mid;
      }
      const double a = 0.5 * (lo + hi);
      out.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    a0 = a1, f0 = f1;
  }
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

// Leading term c X^gamma of the offset w from the line at distance X along it, from the crossing
// p and the point of the same half-branch at 0.8 X (Newton in w across the line, started from
// the quadratic prediction 0.64 w, which lies well inside the basin of the same half-branch).
void offset_term(const LocalJet& h, const Vec2& p, const Vec2& normal, const Vec2& d, HalfBranch* b) {
  const double X1 = p.dot(d), w1 = p.dot(normal);
  b->offset_coefficient = w1 / (X1 * X1);
  b->offset_exponent = 0;
  if (std::fabs(w1) <= 1e-9 * X1) return;
  const double X2 = 0.8 * X1;
  double w2 = 0.64 * w1;
  for (int it = 0; it < 50; ++it) {
    LocalValue v = evaluate(h, X2 * d + w2 * normal);
    const double dw = v.value / v.gradient.dot(normal);
    if (!std::isfinite(dw)) return;
    w2 -= dw;
    if (std::fabs(dw) <= 1e-16 * std::fabs(w2)) break;
  }
  if (w2 == 0 || (w2 > 0) != (w1 > 0)) return;
  double gamma = std::log(w1 / w2) / std::log(X1 / X2);
  // Puiseux exponents are rationals p/q with q <= the multiplicity: snap to the nearest one with
  // q <= 4 when the estimate is within its O(X^2) error.
  double best = 1;
  for (int q = 1; q <= 4; ++q) {
    const double snapped = std::round(gamma * q) / q;
    if (std::fabs(snapped - gamma) < std::fabs(best - gamma)) best = snapped;
  }
  if (std::fabs(best - gamma) <= 0.02) gamma = best;
  b->offset_exponent = gamma;
  b->offset_coefficient = w1 / std::pow(X1, gamma);
}

// Pairs half-branches on each tangent line (see the header): opposite sides by matching offsets,
// then same-side leftovers (cusp-like branches).
void pair_half_branches(const Classification& kind, std::vector<HalfBranch>* hb) {
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

void exit_point(const Problem& problem, const LocalCurve& curve, const Vec2& p, const HalfBranchOptions& options,
                HalfBranch* b) {
  VecX x = curve.unknowns_at(p);
  const double tol = options.newton_tolerance * std::max(1.0, problem.scale());
  if (!onto_curve(problem, &x, tol)) return;
  b->exit_x = problem.wrap(x);
  b->exit_point = problem.point(b->exit_x);
  const Vec3 hint = b->exit_point - curve.origin;
  CurveJet<1> jet = curve_jet<1>(problem, b->exit_x, &hint);
  if (jet.status != CurveJetStatus::kOk || jet.rank_ratio < options.min_rank_ratio) return;
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
  if (contact) {  // a curve of contact is a double zero of h: no sign change, take its line
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
    offset_term(curve.h, p, Vec2(-d[1], d[0]), b.tangent, &b);
    b.tangent_3d = curve.direction_3d(b.tangent);
    // The expansion in the half-branch's own frame: rot90(tangent) = +-rot90(d).
    const auto [num, den] = exponent_fraction(b.offset_exponent);
    const double leading = (b.tangent.dot(d) > 0 ? 1.0 : -1.0) * b.offset_coefficient;
    b.expansion = puiseux_expansion(curve.h, b.tangent, leading, num, den);
    b.normal_3d = curve.direction_3d(Vec2(-b.tangent[1], b.tangent[0]));
    b.param_tangent = dx * b.tangent;
    exit_point(problem, curve, p, options, &b);
    out.push_back(b);
  }
  pair_half_branches(kind, &out);
  return out;
}

}  // namespace

std::vector<HalfBranch> half_branches(const Problem& problem, const LocalCurve& curve, const Classification& kind,
                                      const HalfBranchOptions& options) {
  if (kind.type == SingularType::kRegular || kind.type == SingularType::kIsolated) return {};
  // Near a point of high multiplicity the curve is nearly singular (|grad h| ~ r^(m-1)): widen
  // the circle until every exit point is regular enough to march from.
  std::vector<HalfBranch> out;
  for (int k = 0; k < 4; ++k) {
    out = half_branches_at(problem, curve, kind, options, options.epsilon * std::pow(2.0, k));
    if (std::all_of(out.begin(), out.end(), [](const HalfBranch& b) { return b.exit_ok; })) break;
  }
  return out;
}

}  // namespace ssimarch
