// Trigonometric polynomials (analytic/trig_polynomial.hpp) against direct evaluation and roots
// known in closed form; the closed loops' trapezoidal lengths (analytic/ruled_section.hpp)
// against Gauss-Legendre quadrature and the ellipse perimeter by the complete elliptic integral.
#include "ssimarch/core/contract.hpp"
#include "ssimarch/analytic/trig_polynomial.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "ssimarch/analytic/quadric_form.hpp"
#include "ssimarch/analytic/ruled_section.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

TrigPolynomial random_trig(std::mt19937* rng, int degree) {
  std::uniform_real_distribution<double> u(-1, 1);
  TrigPolynomial f;
  f.constant = u(*rng);
  for (int m = 0; m < degree; ++m) {
    f.cos_coeff[static_cast<std::size_t>(m)] = u(*rng);
    f.sin_coeff[static_cast<std::size_t>(m)] = u(*rng);
  }
  return f;
}

// f(theta) term by term with the library's sine and cosine of m theta.
double direct(const TrigPolynomial& f, double theta) {
  double s = f.constant;
  for (int m = 1; m <= TrigPolynomial::kMaxDegree; ++m)
    s += f.cos_coeff[static_cast<std::size_t>(m - 1)] * std::cos(m * theta) + f.sin_coeff[static_cast<std::size_t>(m - 1)] * std::sin(m * theta);
  return s;
}

// (cos(theta - m) - cos(w)): the roots m +- w, a trigonometric polynomial of degree 1.
TrigPolynomial roots_pair(double m, double w) {
  TrigPolynomial f;
  f.constant = -std::cos(w);
  f.cos_coeff[0] = std::cos(m);
  f.sin_coeff[0] = std::sin(m);
  return f;
}

double wrap(double t) { return t - 2 * kPi * std::floor(t / (2 * kPi)); }

// The distance on the circle.
double angular_gap(double a, double b) {
  const double d = std::fabs(wrap(a) - wrap(b));
  return std::min(d, 2 * kPi - d);
}

TEST(TrigPolynomial, ValuesProductsAndDerivativesAsEvaluatedDirectly) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const TrigPolynomial f = random_trig(&rng, 2), g = random_trig(&rng, 2);
    const TrigPolynomial h = f * g, d = f.derivative();
    for (double t : {-2.0, 0.0, 0.3, 1.7, 3.1, 5.9}) {
      EXPECT_NEAR(f(t), direct(f, t), 1e-14);
      EXPECT_NEAR(h(t), direct(f, t) * direct(g, t), 1e-13);
      // f' term by term.
      double df = 0;
      for (int m = 1; m <= 2; ++m)
        df += m * (-f.cos_coeff[static_cast<std::size_t>(m - 1)] * std::sin(m * t) + f.sin_coeff[static_cast<std::size_t>(m - 1)] * std::cos(m * t));
      EXPECT_NEAR(d(t), df, 1e-14);
    }
  }
  EXPECT_THROW(random_trig(&rng, 3) * random_trig(&rng, 2), ContractViolation);
}

TEST(TrigPolynomial, BilinearFormAsEvaluatedDirectly) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::array<Eigen::Vector4d, 3> a, b;
  for (auto* v : {&a, &b})
    for (Eigen::Vector4d& x : *v) x = {u(rng), u(rng), u(rng), u(rng)};
  Eigen::Matrix4d q;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) q(i, j) = u(rng);
  q = (q + q.transpose()).eval();
  const TrigPolynomial f = bilinear_form(a, q, b);
  for (double t : {0.0, 0.5, 2.0, 4.0, 6.0}) {
    const Eigen::Vector4d A = a[0] + std::cos(t) * a[1] + std::sin(t) * a[2], B = b[0] + std::cos(t) * b[1] + std::sin(t) * b[2];
    EXPECT_NEAR(f(t), A.dot(q * B), 1e-14 * (1 + std::fabs(A.dot(q * B))));
  }
}

TEST(TrigPolynomial, SignChangesAreTheRootsGivenInClosedForm) {
  // Products of (cos(theta - m) - cos w) have the roots m +- w; random ones of degree 1 to 4.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0, 2 * kPi), half(0.05, kPi - 0.05);
  for (int trial = 0; trial < 200; ++trial) {
    const int degree = 1 + trial % 4;
    TrigPolynomial f;
    f.constant = 1;
    std::vector<double> expected;
    for (int k = 0; k < degree; ++k) {
      const double m = angle(rng), w = half(rng);
      f = f * roots_pair(m, w);
      expected.push_back(wrap(m + w));
      expected.push_back(wrap(m - w));
    }
    std::sort(expected.begin(), expected.end());
    // Roots closer than the cluster gap are seen as one (an even change): only separated ones.
    bool separated = true;
    for (std::size_t i = 0; i < expected.size(); ++i)
      separated = separated && angular_gap(expected[i], expected[(i + 1) % expected.size()]) > 1e-3;
    if (!separated) continue;
    const std::vector<double> found = trig_sign_changes(f);
    ASSERT_EQ(found.size(), expected.size()) << "trial " << trial;
    // The product's coefficients carry rounding of ~eps times their scale, which moves a simple
    // root r by that over |f'(r)|: a hundred such roundings allowed.
    double scale = std::fabs(f.constant);
    for (int m = 0; m < TrigPolynomial::kMaxDegree; ++m)
      scale += std::fabs(f.cos_coeff[static_cast<std::size_t>(m)]) + std::fabs(f.sin_coeff[static_cast<std::size_t>(m)]);
    const TrigPolynomial df = f.derivative();
    for (std::size_t i = 0; i < found.size(); ++i)
      EXPECT_LT(angular_gap(found[i], expected[i]), 100 * 2.2e-16 * scale / std::fabs(df(expected[i])) + 1e-15) << "trial " << trial;
  }
}

TEST(TrigPolynomial, DoubleRootsAreNoSignChangeAndTripleRootsAre) {
  // (cos(theta - 1) - cos 0.5) (1 - cos(theta - 4)): roots 0.5, 1.5 and a double root at 4
  // where f touches 0 without changing sign.
  TrigPolynomial touch;
  touch.constant = 1;
  touch.cos_coeff[0] = -std::cos(4.0);
  touch.sin_coeff[0] = -std::sin(4.0);
  const std::vector<double> found = trig_sign_changes(roots_pair(1, 0.5) * touch);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0], 0.5, 1e-13);
  EXPECT_NEAR(found[1], 1.5, 1e-13);
  // sin^3(theta - 2) = (3 sin(theta - 2) - sin(3 (theta - 2))) / 4: triple roots at 2 and 2 + pi,
  // where rounding decides the sign within |u| ~ (1e-16)^(1/3).
  TrigPolynomial s1;
  s1.cos_coeff[0] = -std::sin(2.0);
  s1.sin_coeff[0] = std::cos(2.0);
  const std::vector<double> triple = trig_sign_changes(s1 * s1 * s1);
  ASSERT_EQ(triple.size(), 2u);
  EXPECT_NEAR(triple[0], 2, 1e-5);
  EXPECT_NEAR(triple[1], 2 + kPi, 1e-5);
  // A constant and a positive polynomial have none.
  TrigPolynomial positive;
  positive.constant = 2;
  positive.cos_coeff[1] = 1;
  EXPECT_TRUE(trig_sign_changes(positive).empty());
  EXPECT_TRUE(trig_sign_changes(TrigPolynomial{}).empty());
}

TEST(TrigPolynomial, RootInABracketToRounding) {
  // cos(theta) - 0.3 on [0, pi]: acos(0.3).
  TrigPolynomial f;
  f.constant = -0.3;
  f.cos_coeff[0] = 1;
  EXPECT_NEAR(trig_root_in(f, 0, kPi), std::acos(0.3), 4e-16);
  EXPECT_NEAR(trig_root_in(f, kPi, 2 * kPi), 2 * kPi - std::acos(0.3), 1e-15);
}

// The length of a whole loop by 8-point Gauss-Legendre on `pieces` equal pieces. The integrand's
// last digits are noise within ~1e-3 of an arc's turning points (sqrt(Delta) of a Delta formed with
// cancellation: relative error ~1e-16 scale / Delta), where finer rules put nodes: the reference
// uses 32 pieces (nodes >= 2e-3 from the ends), converged on these analytic integrands (checked
// against 16 pieces).
double gauss_legendre_length(const RuledCurves& rc, const RuledLoop& loop, int pieces) {
  static constexpr double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double h = loop.period() / pieces;
  double sum = 0;
  for (int j = 0; j < pieces; ++j) {
    const double mid = (j + 0.5) * h;
    for (int k = 0; k < 4; ++k)
      sum += w[k] * (rc.derivative(loop, mid + 0.5 * h * x[k]).norm() + rc.derivative(loop, mid - 0.5 * h * x[k]).norm());
  }
  return 0.5 * h * sum;
}

// The loops of the section of `ruled` with `other`, inside a region that holds them all, handed to
// `check` with the section they come from (the section refers to the rulings and the quadric,
// which live here).
template <class Check>
void with_section_loops(const Surface& ruled, const Surface& other, Check check) {
  const auto rulings = rulings_of(ruled);
  const auto q = quadric_matrix(other);
  ASSERT_TRUE(rulings && q);
  const RuledCurves rc(*rulings, *q);
  const auto section = rc.section();
  ASSERT_TRUE(section.has_value());
  const auto curves = ruled_curves_in(rc, *section, {}, 1e-4, 0.1);
  ASSERT_TRUE(curves.has_value());
  check(rc, *section, *curves);
}

// Every loop is a closed curve whose length agrees with Gauss-Legendre's to 1e-12 relative.
void expect_lengths_as_gauss_legendre(const Surface& ruled, const Surface& other) {
  with_section_loops(ruled, other, [](const RuledCurves& rc, const RuledSection& section, const std::vector<TracedCurve>& curves) {
    ASSERT_EQ(curves.size(), section.loops.size());
    for (std::size_t i = 0; i < curves.size(); ++i) {
      EXPECT_TRUE(curves[i].closed);
      const double reference = gauss_legendre_length(rc, section.loops[i], 32);
      ASSERT_NEAR(gauss_legendre_length(rc, section.loops[i], 16) / reference - 1, 0, 1e-12) << "reference not converged";
      EXPECT_NEAR(curves[i].length / reference - 1, 0, 1e-12) << "loop " << i << (section.loops[i].arc ? " (arc)" : " (circle)");
    }
  });
}

TEST(RuledLoopLength, TrapezoidalLengthsAsGaussLegendre) {
  // Steinmetz (circles around the cylinder, through the two nodes), a loop between two simple
  // roots (arc), two loops around an off-axis cylinder, a narrow arc of a cylinder grazing a
  // sphere, and a cone's loops.
  {
    SCOPED_TRACE("Steinmetz");
    expect_lengths_as_gauss_legendre(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-2, 2}), Cylinder(Vec3::Zero(), Vec3::UnitX(), 1, {-2, 2}));
  }
  {
    SCOPED_TRACE("cylinder biting an ellipsoid");
    expect_lengths_as_gauss_legendre(Cylinder(Vec3(1, 0, 0), Vec3(0, 1, 0.3), 0.6, {-4, 4}), Ellipsoid(Vec3::Zero(), {1, 1.5, 2}));
  }
  {
    SCOPED_TRACE("off-axis cylinder through a sphere");
    expect_lengths_as_gauss_legendre(Cylinder(Vec3(0.7, 0.2, 0), Vec3(0.1, 0, 1), 0.5, {-3, 3}), Sphere(Vec3::Zero(), 2));
  }
  {
    SCOPED_TRACE("cylinder grazing a sphere");
    expect_lengths_as_gauss_legendre(Cylinder(Vec3(2.45, 0, 0), Vec3::UnitZ(), 0.5, {-3, 3}), Sphere(Vec3::Zero(), 2));
  }
  {
    SCOPED_TRACE("cone through a sphere");
    expect_lengths_as_gauss_legendre(Cone(Vec3(0, 0, -3), Vec3(0.1, 0, 1), 0.3, {0, 6}), Sphere(Vec3(0.3, 0.1, 0), 1.5));
  }
}

TEST(RuledLoopLength, SteinmetzEllipsesAsTheEllipticIntegral) {
  // The ellipses z = +-x on x^2 + y^2 = 1: semi-axes sqrt 2 and 1, perimeter 4 sqrt(2) E(k),
  // k^2 = 1 - 1/2 (std::comp_ellint_2 takes the modulus k).
  const double perimeter = 4 * std::sqrt(2.0) * std::comp_ellint_2(std::sqrt(0.5));
  with_section_loops(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-2, 2}), Cylinder(Vec3::Zero(), Vec3::UnitX(), 1, {-2, 2}),
                     [&](const RuledCurves&, const RuledSection&, const std::vector<TracedCurve>& curves) {
                       ASSERT_EQ(curves.size(), 2u);
                       for (const TracedCurve& c : curves) EXPECT_NEAR(c.length / perimeter - 1, 0, 1e-13);
                     });
}

}  // namespace
}  // namespace ssimarch
