// Puiseux expansions of half-branches up to exponent 6 (issue 10 item 3; singular/puiseux.hpp)
// against closed-form branches: binomial series of sqrt(1 + X) and an explicit graph branch.
#include "ssimarch/singular/puiseux.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(Puiseux, ExponentFraction) {
  EXPECT_EQ(exponent_fraction(1.5), std::make_pair(3, 2));
  EXPECT_EQ(exponent_fraction(2.0), std::make_pair(2, 1));
  EXPECT_EQ(exponent_fraction(2.5), std::make_pair(5, 2));
  EXPECT_EQ(exponent_fraction(1.25), std::make_pair(5, 4));
  EXPECT_EQ(exponent_fraction(0.0), std::make_pair(2, 1));
}

}  // namespace
}  // namespace ssimarch
