#include "ssimarch/singular/classify.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ssimarch {

std::string_view to_string(SingularType t) {
  switch (t) {
    case SingularType::kRegular: return "regular";
    case SingularType::kNode: return "node";
    case SingularType::kIsolated: return "isolated";
    case SingularType::kCusp: return "cusp";
    case SingularType::kTacnode: return "tacnode";
    case SingularType::kRamphoidCusp: return "ramphoid_cusp";
    case SingularType::kOscnode: return "oscnode";
    case SingularType::kHigherDoublePoint: return "higher_double_point";
    case SingularType::kTriplePoint: return "triple_point";
    case SingularType::kQuadruplePoint: return "quadruple_point";
    case SingularType::kMultiplePoint: return "multiple_point";
    case SingularType::kTangentLineCrossing: return "tangent_line_crossing";
    case SingularType::kTangentialContact: return "tangential_contact";
  }
  return "?";
}

int milnor_number(const LocalJet& h, double rank_tolerance, std::vector<int>* rows) {
  const std::array<LocalJet, 2> g = {partial(h, 0), partial(h, 1)};
  auto quotient_dim = [&](int N) {
    // Columns: monomials s^i t^j of degree < N; rows: s^a t^b g truncated to degree < N.
    const int cols = N * (N + 1) / 2;
    MatX A = MatX::Zero(2 * cols, cols);
    int r = 0;
    for (const LocalJet& gen : g)
      for (int da = 0; da < N; ++da)
        for (int b = 0; b <= da; ++b, ++r) {
          for (int d = 0; d + da < N; ++d)
            for (int j = 0; j <= d; ++j) {
              const int D = d + da, J = j + b;
              A(r, D * (D + 1) / 2 + J) += coef(gen, d - j, j);
            }
        }
    Eigen::JacobiSVD<MatX> svd(A);
    const auto& sv = svd.singularValues();
    int rank = 0;
    for (Eigen::Index i = 0; i < sv.size(); ++i)
      if (sv[i] > rank_tolerance * std::max(1e-300, sv[0])) ++rank;
    return cols - rank;
  };
  if (rows) rows->clear();
  int prev = quotient_dim(1);
  if (rows) rows->push_back(prev);
  // g is exact to degree kLocalOrder - 1, so J + M^N is known for N <= kLocalOrder.
  for (int N = 1; N < kLocalOrder; ++N) {
    const int next = quotient_dim(N + 1);
    if (rows) rows->push_back(next);
    if (next == prev) return prev;  // M^N in J + M^(N+1), hence M^N in J (Nakayama)
    prev = next;
  }
  return -1;
}

SplittingLemma splitting_lemma(const LocalJet& h) {
  SplittingLemma r;
  Eigen::Matrix2d H;
  H << 2 * coef(h, 2, 0), coef(h, 1, 1), coef(h, 1, 1), 2 * coef(h, 0, 2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(H);
  const int big = std::fabs(es.eigenvalues()[1]) >= std::fabs(es.eigenvalues()[0]) ? 1 : 0;
  r.axes.col(0) = es.eigenvectors().col(big);
  r.axes.col(1) = es.eigenvectors().col(1 - big);
  const SplittingLemma e = eliminate_first_variable(linear_substitution(h, r.axes));
  r.lambda = e.lambda;
  r.x_of_y = e.x_of_y;
  r.phi = e.phi;
  return r;
}

SplittingLemma eliminate_first_variable(const LocalJet& g) {
  SplittingLemma r;
  r.lambda = 2 * coef(g, 2, 0);
  const LocalJet gx = partial(g, 0);
  using T = Taylor<kLocalOrder>;
  const T Y = T::variable(0, 0.0);
  T X(0.0);
  // Chord iteration X <- X - g_X(X, Y)/lambda gains one order per pass (implicit function theorem).
  for (int it = 0; it <= kLocalOrder; ++it) X -= compose<2, 1, kLocalOrder>(gx, std::array<T, 2>{X, Y}) / r.lambda;
  r.x_of_y = X;
  r.phi = compose<2, 1, kLocalOrder>(g, std::array<T, 2>{X, Y});
  return r;
}

namespace {

// "A3", "D5", ...: snprintf, because GCC 12 warns falsely (-Wrestrict) on family('A', k).
std::string family(char letter, int k) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%c%d", letter, k);
  return buf;
}

void classify_double_point(const LocalJet& h, double tol, Classification* c) {
  const double a = coef(h, 2, 0), b = coef(h, 1, 1), d = coef(h, 0, 2);
  const double disc = b * b - 4 * a * d, norm2 = a * a + b * b + d * d;
  if (std::fabs(disc) > tol * norm2) {  // A1 (Prop 5.3): two real lines or none
    c->corank = 0;
    c->ak = "A1";
    c->ak_index = 1;
    c->real_branches = disc > 0 ? 2 : 0;
    c->type = disc > 0 ? SingularType::kNode : SingularType::kIsolated;
    c->crossing = disc > 0;
    c->real_form = -disc;
    return;
  }
  c->corank = 1;
  const SplittingLemma s = splitting_lemma(h);
  c->tangent_cone = {{s.axes.col(1) * (s.axes(1, 1) < 0 ? -1.0 : 1.0), 2}};
  c->complex_lines = 0;
  const double floor = tol * germ_scale(h);
  int k = 0;
  for (int deg = 3; deg <= kLocalOrder && k == 0; ++deg)
    if (std::fabs(s.phi[deg]) > floor) k = deg - 1;
  if (k == 0) {  // phi = 0 to the jet's order: h = lambda/2 (X - X(Y))^2 u, a double curve
    c->type = SingularType::kTangentialContact;
    c->milnor = -1;
    c->real_branches = 1;
    return;
  }
  c->ak_index = k;
  c->ak = family('A', k);
  c->real_form = s.phi[k + 1] * s.lambda;
  if (k % 2 == 0) {
    c->real_branches = 1;
    c->type = k == 2 ? SingularType::kCusp : (k == 4 ? SingularType::kRamphoidCusp : SingularType::kHigherDoublePoint);
    return;
  }
  c->real_branches = c->real_form < 0 ? 2 : 0;
  // Branches X = +-sqrt(-c/lambda) Y^((k+1)/2) cross iff (k+1)/2 is odd (docs/math/singular_local_curve.md §3).
  c->crossing = c->real_branches == 2 && ((k + 1) / 2) % 2 == 1;
  if (c->real_branches == 0)
    c->type = SingularType::kIsolated;
  else
    c->type = k == 3 ? SingularType::kTacnode : (k == 5 ? SingularType::kOscnode : SingularType::kHigherDoublePoint);
}

void classify_multiple_point(int distinct_roots, Classification* c) {
  const int m = c->multiplicity;
  c->corank = 2;
  int real_lines = static_cast<int>(c->tangent_cone.size());
  c->crossing = real_lines >= 2;
  if (c->milnor < 0) {  // non-isolated singular set: a squared factor
    c->type = real_lines >= 2 ? SingularType::kTangentLineCrossing : SingularType::kTangentialContact;
    return;
  }
  const bool ordinary = distinct_roots == m;
  if (ordinary) c->real_branches = real_lines;
  if (m == 3) {
    c->type = SingularType::kTriplePoint;
    if (distinct_roots == 3)
      c->ak = "D4";
    else if (distinct_roots == 2)
      c->ak = family('D', c->milnor);
    else if (c->milnor >= 6 && c->milnor <= 8)
      c->ak = family('E', c->milnor);
  } else if (m == 4) {
    c->type = SingularType::kQuadruplePoint;
    if (ordinary) c->ak = "X9";
  } else {
    c->type = SingularType::kMultiplePoint;
  }
}

}  // namespace

Classification classify(const LocalJet& h_in, const ClassifyOptions& options) {
  Classification c;
  LocalJet h = in_germ_units(h_in, options.length);
  h[0] = 0.0;
  h = clean(h, options.zero_tolerance);
  if (h[1] != 0.0 || h[2] != 0.0) {
    c.multiplicity = 1;
    c.milnor = 0;
    c.real_branches = 1;
    Vec2 grad(h[1], h[2]);
    c.tangent_cone = {{Vec2(-grad[1], grad[0]).normalized(), 1}};
    return c;
  }
  int m = 0;
  for (int d = 2; d <= kLocalOrder && m == 0; ++d)
    for (int j = 0; j <= d; ++j)
      if (coef(h, d - j, j) != 0.0) m = d;
  if (m == 0) {  // h vanishes to the jet's order: the surfaces coincide near the point
    c.type = SingularType::kTangentialContact;
    c.multiplicity = kLocalOrder + 1;
    return c;
  }
  c.multiplicity = m;
  c.milnor = milnor_number(h);
  int distinct = 0;
  c.tangent_cone = binary_form_roots(homogeneous_part(h, m), &c.complex_lines, &distinct);
  if (m == 2) {
    classify_double_point(h, options.zero_tolerance, &c);
    if (c.milnor < 0 && c.type != SingularType::kTangentialContact) c.milnor = c.ak_index;
  } else {
    classify_multiple_point(distinct, &c);
  }
  return c;
}

}  // namespace ssimarch
