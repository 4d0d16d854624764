#include "ssimarch/porosity/polynomial_roots.hpp"

#include <gtest/gtest.h>

#include <random>

namespace ssimarch {
namespace {

// Expand (x - r0)(x - r1)... into ascending coefficients.
std::vector<double> from_roots(const std::vector<double>& roots, double lead) {
  std::vector<double> c{lead};
  for (double r : roots) {
    std::vector<double> n(c.size() + 1, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      n[i + 1] += c[i];
      n[i] -= r * c[i];
    }
    c = n;
  }
  return c;
}

TEST(porosity_PolynomialRoots, RandomSimpleRoots) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-3, 3);
  for (int deg = 1; deg <= 4; ++deg) {
    for (int k = 0; k < 500; ++k) {
      std::vector<double> r(deg);
      for (auto& v : r) v = U(rng);
      std::sort(r.begin(), r.end());
      bool separated = true;
      for (int i = 1; i < deg; ++i) separated &= r[i] - r[i - 1] > 1e-3;
      if (!separated) continue;
      const auto c = from_roots(r, 0.5 + std::abs(U(rng)));
      const auto got = real_roots(c.data(), deg, 1e-12);
      ASSERT_EQ(got.count, deg);
      for (int i = 0; i < deg; ++i) EXPECT_NEAR(got.x[i], r[i], 1e-9);
    }
  }
}

TEST(porosity_PolynomialRoots, DoubleRootIsReportedTwice) {
  // (x - 1)^2 (x + 2)(x - 3) and (x^2 + 1)(x - 0.5)^2: a tangency counts twice, a complex pair not at all.
  auto c = from_roots({1, 1, -2, 3}, 1.0);
  auto got = real_roots(c.data(), 4, 1e-12);
  ASSERT_EQ(got.count, 4);
  EXPECT_NEAR(got.x[1], 1.0, 1e-7);
  EXPECT_NEAR(got.x[2], 1.0, 1e-7);
  const double q[5] = {0.25, -1.0, 1.25, -1.0, 1.0};  // (x^2+1)(x^2 - x + 0.25)
  got = real_roots(q, 4, 1e-12);
  ASSERT_EQ(got.count, 2);
  EXPECT_NEAR(got.x[0], 0.5, 1e-7);
  // Perturbed so that the pair becomes complex with a tiny imaginary part: still a double root.
  const double q2[5] = {0.25 + 1e-17, -1.0, 1.25, -1.0, 1.0};
  EXPECT_EQ(real_roots(q2, 4, 1e-12).count, 2);
  // No real roots.
  const double none[5] = {1, 0, 2, 0, 1};
  EXPECT_EQ(real_roots(none, 4, 1e-12).count, 0);
}

TEST(porosity_PolynomialRoots, LongDouble) {
  const long double c[3] = {2.0L, -3.0L, 1.0L};
  const auto got = real_roots(c, 2, 1e-15L);
  ASSERT_EQ(got.count, 2);
  EXPECT_NEAR(static_cast<double>(got.x[0]), 1.0, 1e-15);
  EXPECT_NEAR(static_cast<double>(got.x[1]), 2.0, 1e-15);
}

}  // namespace
}  // namespace ssimarch
