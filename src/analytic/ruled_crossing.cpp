// docs/math/closed_form_quadrics.md, "Crossing points from the closed form": the node of a ruled
// section at a double root of the discriminant, from the jets of its two branches.
#include "ssimarch/analytic/ruled_crossing.hpp"

#include <algorithm>
#include <cmath>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

// Jet order in u = theta - tau: the expansions run to exponent 6 (as singular/half_branches.cpp
// asks of singular/puiseux.hpp), and the reversion X -> s is exact to the jet's order.
constexpr int kOrder = 8;
constexpr int kExpansionOrder = 6;
// Expansion coefficients below this times max(1, |leading|) are left out, as singular/puiseux.cpp
// leaves out its zero coefficients.
constexpr double kZeroCoefficient = 1e-12;

using Series = Taylor<kOrder>;
using Wide = Taylor<kOrder + 2>;  // Delta to two more orders: Delta / u^2 loses two
using SeriesPoint = std::array<Series, 3>;

// The unit normal of s at p: its gradient's direction (as singular/local_curve.cpp's chart).
std::optional<Vec3> unit_normal(const Surface& s, const Vec3& p) {
  using J = Jet<3, 1>;
  const J f = s.value(Vec3T<J>(J::variable(0, p.x()), J::variable(1, p.y()), J::variable(2, p.z())));
  const Vec3 g(f.d(0), f.d(1), f.d(2));
  if (!g.allFinite() || !(g.norm() > 0)) return std::nullopt;
  return Vec3(g.normalized());
}

// f(s(X)) for series f (its constant term kept) and s with s(0) = 0: Horner with truncated products.
Series substitute(const Series& f, const Series& s) {
  Series r(f[kOrder]);
  for (int k = kOrder - 1; k >= 0; --k) r = r * s + f[k];
  return r;
}

// The (s, t) axes of singular/local_curve.cpp's implicit chart at a point with unit normal n:
// e1 the x axis projected onto the tangent plane (or, where n is along x, the unit axis least
// aligned with n crossed with n), e2 = n x e1. The half-branches' order and the sign of a line's
// canonical direction are taken in this frame, as the general classifier takes them.
void chart_axes(const Vec3& n, Vec3* e1, Vec3* e2) {
  const Vec3 hint = Vec3::UnitX();
  Vec3 a = hint - hint.dot(n) * n;
  if (a.norm() <= 1e-8) {
    int k = 0;
    n.cwiseAbs().minCoeff(&k);
    a = Vec3::Unit(k).cross(n);
  }
  *e1 = a.normalized();
  *e2 = n.cross(*e1);
}

// s(X) for the series X(s) = x1 s + x2 s^2 + ... (x1 != 0): the fixed point of
// s = (X - sum_{k>=2} x_k s^k) / x1, each pass adding one correct order.
Series revert(const Series& x) {
  const Series X = Series::variable(0, 0.0);
  Series higher = x;
  higher[0] = 0;
  higher[1] = 0;
  Series s = X / x[1];
  for (int pass = 1; pass < kOrder; ++pass) s = (X - substitute(higher, s)) / x[1];
  return s;
}

// The two branches' point jets in u = theta - tau: t+- = (-b +- S) / 2a, S = u sqrt(Delta / u^2).
// False where the root is not clearly of multiplicity 2 (Delta''/2 <= kRuledNodeSeparation x
// scale) or a jet is not finite.
bool branch_jets(const RuledCurves& rc, double tau, double scale, std::array<SeriesPoint, 2>* out) {
  const auto [aw, bw, cw] = rc.quadratic(Wide::variable(0, tau));
  const Wide disc = bw * bw - 4.0 * aw * cw;
  if (!(disc[2] > kRuledNodeSeparation * scale)) return false;
  Series e, a, b, c;
  for (int k = 0; k <= kOrder; ++k) e[k] = disc[k + 2], a[k] = aw[k], b[k] = bw[k], c[k] = cw[k];
  const Series root = sqrt(e);
  Series S;
  for (int k = 1; k <= kOrder; ++k) S[k] = root[k - 1];
  const Series theta = Series::variable(0, tau);
  for (int branch = 0; branch < 2; ++branch) {
    const Series t = (-b + (branch == 0 ? 1.0 : -1.0) * S) / (2.0 * a);
    const Vec3T<Series> p = rc.on_ruling(theta, t);
    (*out)[static_cast<std::size_t>(branch)] = {p.x, p.y, p.z};
    for (const Series& q : (*out)[static_cast<std::size_t>(branch)])
      if (!is_finite(q)) return false;
  }
  return true;
}

Vec3 coefficient(const SeriesPoint& p, int k) { return {p[0][k], p[1][k], p[2][k]}; }

// The half-branch leaving along u = dir * s, s >= 0, in the report's form: unit tangent T, the
// expansion W(X) of the offset along n x T (X along T), its leading term in the same frame, the
// half-branch's own (singular/half_branches.cpp: w = c X^gamma along rot90(tangent)).
SingularPointReport::HalfBranch half_branch(const SeriesPoint& p, double dir, const Vec3& n) {
  SingularPointReport::HalfBranch h;
  Series X, W;
  const Vec3 v = dir * coefficient(p, 1);
  h.tangent = v.normalized();
  h.normal = n.cross(h.tangent);
  double power = dir;
  for (int k = 1; k <= kOrder; ++k, power *= dir) {
    const Vec3 q = power * coefficient(p, k);
    X[k] = q.dot(h.tangent);
    W[k] = k >= 2 ? q.dot(h.normal) : 0.0;
  }
  const Series w = substitute(W, revert(X));
  for (int j = 2; j <= kExpansionOrder; ++j)
    if (std::fabs(w[j]) > kZeroCoefficient * std::max(1.0, std::fabs(w[2]))) h.expansion.push_back({double(j), w[j]});
  if (!h.expansion.empty()) {
    h.exponent = h.expansion.front().exponent;
    h.coefficient = h.expansion.front().coefficient;
  } else {
    h.coefficient = w[2];  // straight to rounding: exponent 0, as the general code
  }
  h.param_tangent = VecX(h.tangent);
  return h;
}

}  // namespace

std::optional<SingularPointReport> ruled_node(const Problem& problem, const RuledCurves& curves, double theta,
                                              double scale) {
  if (problem.kind() != PairKind::kImplicitImplicit) return std::nullopt;
  std::array<SeriesPoint, 2> branches;
  if (!branch_jets(curves, theta, scale, &branches)) return std::nullopt;
  SingularPointReport r;
  r.p = coefficient(branches[0], 0);
  r.x = problem.wrap(VecX(r.p));
  r.type = SingularType::kNode;
  r.ak = "A1";
  r.multiplicity = 2;
  r.milnor = 1;
  const auto n = unit_normal(problem.first(), r.p);
  if (!n) return std::nullopt;
  Vec3 e1, e2;
  chart_axes(*n, &e1, &e2);
  // Half-branches in the general code's order (increasing angle in the (e1, e2) frame from e1),
  // each continued straight across the node by the other half of its branch.
  struct Entry {
    double angle;
    int branch;
    SingularPointReport::HalfBranch half;
  };
  std::vector<Entry> entries;
  for (int b = 0; b < 2; ++b) {
    const Vec3 v = coefficient(branches[static_cast<std::size_t>(b)], 1);
    if (!(v.norm() > 0)) return std::nullopt;
    for (double dir : {1.0, -1.0}) {
      Entry e{0, b, half_branch(branches[static_cast<std::size_t>(b)], dir, *n)};
      e.angle = std::atan2(e.half.tangent.dot(e2), e.half.tangent.dot(e1));
      if (e.angle < 0) e.angle += 2 * M_PI;
      entries.push_back(std::move(e));
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.angle < b.angle; });
  for (std::size_t i = 0; i < entries.size(); ++i) {
    for (std::size_t j = 0; j < entries.size(); ++j)
      if (j != i && entries[j].branch == entries[i].branch) entries[i].half.continuation = static_cast<int>(j);
    r.half_branches.push_back(entries[i].half);
  }
  return r;
}

}  // namespace ssimarch
