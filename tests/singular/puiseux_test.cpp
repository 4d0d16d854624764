// Puiseux expansions of half-branches up to exponent 6 (issue 10 item 3; singular/puiseux.hpp)
// against closed-form branches: binomial series of sqrt(1 + X) and an explicit graph branch.
#include "ssimarch/singular/puiseux.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "singular/pairs.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/half_branches.hpp"

namespace ssimarch {
namespace {

using testing::germ;

// sqrt(1 + X) = sum binom(1/2, k) X^k: 1, 1/2, -1/8, 1/16, -5/128, 7/256, -21/1024.
constexpr double kSqrt1p[] = {1, 0.5, -0.125, 0.0625, -5.0 / 128, 7.0 / 256, -21.0 / 1024};

void expect_terms(const PuiseuxExpansion& e, const std::vector<PuiseuxTerm>& expected) {
  ASSERT_EQ(e.terms.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(e.terms[i].exponent, expected[i].exponent, 1e-12) << i;
    EXPECT_NEAR(e.terms[i].coefficient, expected[i].coefficient, 1e-9) << i;
  }
}

TEST(Puiseux, CuspWithCorrection) {
  // t^2 = s^3 + s^4: t = +-s^(3/2) sqrt(1 + s) = +-sum binom(1/2, k) s^(3/2 + k), exponents to 6.
  const LocalJet h = germ({{0, 2, 1}, {3, 0, -1}, {4, 0, -1}});
  for (const double sign : {1.0, -1.0}) {
    // The half-branch along +s; its normal rot90(+s) = +t, so W = t.
    const PuiseuxExpansion e = puiseux_expansion(h, Vec2(1, 0), sign * 0.9, 3, 2);
    EXPECT_EQ(e.denominator, 2);
    EXPECT_TRUE(e.complete);
    std::vector<PuiseuxTerm> expected;
    for (int k = 0; 1.5 + k <= 6; ++k) expected.push_back({1.5 + k, sign * kSqrt1p[k]});
    expect_terms(e, expected);
  }
}

// The cusp above in a model scaled by lambda (h a gap in model units: degree d times
// lambda^(1 - d)), expanded over its germ length: the terms are the unit ones in model units,
// b_e lambda^(1 - e), at every scale (issue 26).
TEST(Puiseux, TheSameBranchAtEveryScaleOverTheGermLength) {
  for (const double lambda : {1e-6, 1e6}) {
    SCOPED_TRACE(lambda);
    const LocalJet h =
        germ({{0, 2, 1 / lambda}, {3, 0, -1 / (lambda * lambda)}, {4, 0, -1 / (lambda * lambda * lambda)}});
    const Vec2 through(0.01 * lambda, 0.001 * lambda);
    const PuiseuxExpansion e = puiseux_expansion(h, Vec2(1, 0), 0.9 / std::sqrt(lambda), 3, 2, 6, &through, lambda);
    EXPECT_EQ(e.denominator, 2);
    EXPECT_TRUE(e.complete);
    ASSERT_EQ(e.terms.size(), 5u);
    for (std::size_t k = 0; k < e.terms.size(); ++k) {
      EXPECT_NEAR(e.terms[k].exponent, 1.5 + static_cast<double>(k), 1e-12);
      EXPECT_NEAR(e.terms[k].coefficient * std::pow(lambda, e.terms[k].exponent - 1), kSqrt1p[k], 1e-9) << k;
    }
  }
}

TEST(Puiseux, RamphoidCuspAndTacnode) {
  // t^2 = s^5: W = +-X^(5/2) only.  t^2 = s^4 + s^5: W = +-X^2 sqrt(1 + X) (tacnode, q = 1).
  expect_terms(puiseux_expansion(germ({{0, 2, 1}, {5, 0, -1}}), Vec2(1, 0), 1.1, 5, 2), {{2.5, 1.0}});
  const PuiseuxExpansion e = puiseux_expansion(germ({{0, 2, 1}, {4, 0, -1}, {5, 0, -1}}), Vec2(1, 0), -1.05, 2, 1);
  std::vector<PuiseuxTerm> expected;
  for (int k = 0; k <= 4; ++k) expected.push_back({2.0 + k, -kSqrt1p[k]});
  expect_terms(e, expected);
}

TEST(Puiseux, NodeBranchWithKnownCurvature) {
  // (t - s^2 - s^3)(t + s) = 0: the branch t = s^2 + s^3 (curvature 2 at the node) leaves along
  // +s with W = X^2 + X^3 and along -s (X = -s, W = -t) with W = -X^2 + X^3.
  const LocalJet h = germ({{0, 2, 1}, {1, 1, 1}, {2, 1, -1}, {3, 0, -1}, {3, 1, -1}, {4, 0, -1}});
  expect_terms(puiseux_expansion(h, Vec2(1, 0), 1.0, 2, 1), {{2, 1}, {3, 1}});
  expect_terms(puiseux_expansion(h, Vec2(-1, 0), -1.0, 2, 1), {{2, -1}, {3, 1}});
}

TEST(Puiseux, HalfBranchesOfTheCuspCarryTheExpansion) {
  // The same cusp through half_branches' own leading-term measurement (no surfaces needed for
  // the expansion; a graph pair supplies the frame).
  const Problem P = testing::graph_vs_plane_pi("v^2-u^3-u^4");
  VecX x(2);
  x << 0, 0;
  const LocalCurve c = local_curve(P, x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  const Classification k = classify(c.h);
  EXPECT_EQ(k.type, SingularType::kCusp);
  const auto hb = half_branches(P, c, k);
  ASSERT_EQ(hb.size(), 2u);
  for (const HalfBranch& b : hb) {
    ASSERT_GE(b.expansion.terms.size(), 5u);
    EXPECT_EQ(b.expansion.denominator, 2);
    const double sign = b.expansion.terms[0].coefficient > 0 ? 1.0 : -1.0;
    for (std::size_t i = 0; i < b.expansion.terms.size(); ++i) {
      EXPECT_NEAR(b.expansion.terms[i].exponent, 1.5 + static_cast<double>(i), 1e-12);
      // In the tangent-plane frame of the graph the gap is h = f / |grad g| with unit scaling.
      EXPECT_NEAR(b.expansion.terms[i].coefficient, sign * kSqrt1p[i], 1e-6) << i;
    }
  }
}

// The thesis' ramphoid cusp (Ex. 14/15, oracle "Ex 11"): f = u^4 + u^2 v^2 - 2u^2 v - u v^2 + v^2 =
// (v - u^2)^2 + u^2 v^2 - u v^2. Its two halves leave along +u and share the leading term u^2; they
// separate at u^(5/2): v = u^2 +- u^(5/2) + u^3 +- u^(7/2)/2 -+ 5u^(9/2)/8 - u^5 -+ 19u^(11/2)/16 - u^6
// + ... (sympy: v = sum c_j tau^j with u = tau^2 substituted into f and solved order by order).
const std::vector<std::tuple<int, int, double>> kRamphoid = {{4, 0, 1}, {2, 2, 1}, {2, 1, -2}, {1, 2, -1}, {0, 2, 1}};
std::vector<PuiseuxTerm> ramphoid_half(double sign) {
  return {{2, 1}, {2.5, sign}, {3, 1}, {3.5, sign * 0.5}, {4.5, -sign * 5.0 / 8}, {5, -1}, {5.5, -sign * 19.0 / 16}, {6, -1}};
}
double series_at(const std::vector<PuiseuxTerm>& terms, double X) {
  double w = 0;
  for (const PuiseuxTerm& t : terms) w += t.coefficient * std::pow(X, t.exponent);
  return w;
}

TEST(Puiseux, RamphoidCuspHalvesThatShareTheirLeadingTerm) {
  const LocalJet h = germ(kRamphoid);
  for (const double sign : {1.0, -1.0}) {
    const std::vector<PuiseuxTerm> expected = ramphoid_half(sign);
    const Vec2 through(0.01, series_at(expected, 0.01));
    const PuiseuxExpansion e = puiseux_expansion(h, Vec2(1, 0), 1.0, 2, 1, 6, &through);
    EXPECT_EQ(e.denominator, 2) << sign;
    EXPECT_TRUE(e.complete) << sign;
    expect_terms(e, expected);
  }
}

// Two branches t = s^2 +- s^k touching with contact order k (k = 3: an oscnode A5, k = 4: A7): on
// the +s side W = X^2 +- X^k; on the -s side (X = -s, W = -t) W = -X^2 +- (-1)^(k+1) X^k. Each
// half-branch is told apart from its twin only by its own point on the circle.
TEST(Puiseux, BranchesOfContactOrderThreeAndFourStayApart) {
  for (const int k : {3, 4}) {
    // (t - s^2 - s^k)(t - s^2 + s^k) = t^2 - 2 s^2 t + s^4 - s^(2k)
    const LocalJet h = germ({{0, 2, 1}, {2, 1, -2}, {4, 0, 1}, {2 * k, 0, -1}});
    for (const double side : {1.0, -1.0})
      for (const double eps : {1.0, -1.0}) {
        // t(s) = s^2 + eps s^k along X = side s, W = side t.
        const double a2 = side, ak = side * eps * std::pow(side, k);
        const std::vector<PuiseuxTerm> expected = {{2, a2}, {static_cast<double>(k), ak}};
        const Vec2 through(0.01, series_at(expected, 0.01));
        const PuiseuxExpansion e = puiseux_expansion(h, Vec2(side, 0), a2, 2, 1, 6, &through);
        EXPECT_TRUE(e.complete) << k << side << eps;
        expect_terms(e, expected);
      }
  }
}

// The same germs through half_branches: the halves are found on the circle (the contact-order-4
// pair crosses it 2e-6 rad apart, inside one sample), carry distinct expansions equal to the
// closed forms, and each continues along its own branch (a curve arriving on t = s^2 + s^k leaves
// on it, never on its twin).
TEST(Puiseux, HalfBranchesOfTouchingBranchesAreDistinctAndPairedByBranch) {
  for (const int k : {3, 4}) {
    // (append, not a literal + to_string: GCC 12's -Wrestrict false positive, PR 105329)
    const std::string K = std::to_string(k);
    const std::string f = std::string("(v-u^2-u^").append(K).append(")*(v-u^2+u^").append(K).append(")");
    const Problem P = testing::graph_vs_plane_pi(f);
    VecX x(2);
    x << 0, 0;
    const LocalCurve c = local_curve(P, x);
    ASSERT_EQ(c.status, LocalCurveStatus::kOk);
    const Classification kind = classify(c.h);
    EXPECT_EQ(kind.ak, std::string("A").append(std::to_string(2 * k - 1))) << k;
    EXPECT_EQ(kind.real_branches, 2) << k;
    const auto hb = half_branches(P, c, kind);
    ASSERT_EQ(hb.size(), 4u) << k;
    std::vector<double> branch_of(hb.size());
    for (std::size_t i = 0; i < hb.size(); ++i) {
      const HalfBranch& b = hb[i];
      ASSERT_EQ(b.expansion.terms.size(), 2u) << k << " " << i;
      // A point of the half-branch from its expansion, in (s, t) = (u, v): which branch it is.
      const double X = 0.1, W = series_at(b.expansion.terms, X);
      const Vec2 st = X * b.tangent + W * Vec2(-b.tangent[1], b.tangent[0]);
      branch_of[i] = (st[1] - st[0] * st[0]) / std::pow(st[0], k);
      EXPECT_NEAR(std::fabs(branch_of[i]), 1.0, 1e-9) << k << " " << i;
      EXPECT_NEAR(b.expansion.terms[0].exponent, 2.0, 1e-12);
      EXPECT_NEAR(b.expansion.terms[1].exponent, static_cast<double>(k), 1e-12);
    }
    for (std::size_t i = 0; i < hb.size(); ++i) {
      const std::size_t j = static_cast<std::size_t>(hb[i].continuation);
      ASSERT_LT(j, hb.size());
      EXPECT_NEAR(branch_of[i], branch_of[j], 1e-9) << k << " " << i;     // same branch
      EXPECT_LT(hb[i].tangent.dot(hb[j].tangent), -0.99) << k << " " << i;  // straight on
    }
  }
}

TEST(Puiseux, ThesisRamphoidCuspHalvesThroughHalfBranches) {
  const Problem P = testing::graph_vs_plane_pi("u^4+u^2*v^2-2*u^2*v-u*v^2+v^2");
  VecX x(2);
  x << 0, 0;
  const LocalCurve c = local_curve(P, x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  const Classification kind = classify(c.h);
  EXPECT_EQ(kind.type, SingularType::kRamphoidCusp);
  const auto hb = half_branches(P, c, kind);
  ASSERT_EQ(hb.size(), 2u);
  EXPECT_EQ(hb[0].continuation, 1);
  EXPECT_EQ(hb[1].continuation, 0);
  for (const HalfBranch& b : hb) {
    EXPECT_NEAR(b.tangent[0], 1.0, 1e-12);
    ASSERT_EQ(b.expansion.terms.size(), 8u);
    const double sign = b.expansion.terms[1].coefficient > 0 ? 1.0 : -1.0;
    const std::vector<PuiseuxTerm> expected = ramphoid_half(sign);
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_NEAR(b.expansion.terms[i].exponent, expected[i].exponent, 1e-12) << i;
      EXPECT_NEAR(b.expansion.terms[i].coefficient, expected[i].coefficient, 1e-6) << i;
    }
  }
  EXPECT_LT(hb[0].expansion.terms[1].coefficient * hb[1].expansion.terms[1].coefficient, 0);
}

TEST(Puiseux, ExponentFraction) {
  EXPECT_EQ(exponent_fraction(1.5), std::make_pair(3, 2));
  EXPECT_EQ(exponent_fraction(2.0), std::make_pair(2, 1));
  EXPECT_EQ(exponent_fraction(2.5), std::make_pair(5, 2));
  EXPECT_EQ(exponent_fraction(1.25), std::make_pair(5, 4));
  EXPECT_EQ(exponent_fraction(0.0), std::make_pair(2, 1));
}

}  // namespace
}  // namespace ssimarch
