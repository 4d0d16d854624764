// Jets against closed-form derivatives, identities and central differences.
#include "ssimarch/core/jet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace ssimarch {
namespace {

using T8 = Taylor<8>;

// k-th normalised Taylor coefficient from a closed-form k-th derivative.
double fact(int k) {
  double f = 1;
  for (int i = 2; i <= k; ++i) f *= i;
  return f;
}

struct UnaryCase {
  const char* name;
  std::function<T8(const T8&)> f;
  std::function<double(double, int)> deriv;  // closed-form k-th derivative (k <= 4)
  double x0;
};

TEST(Jet, UnivariateDerivativesMatchClosedForms) {
  const double kTol = 1e-12;  // relative, on coefficients of order <= 4
  std::vector<UnaryCase> cases = {
      {"exp", [](const T8& a) { return exp(a); }, [](double x, int) { return std::exp(x); }, 0.7},
      {"sin", [](const T8& a) { return sin(a); },
       [](double x, int k) { return std::sin(x + k * M_PI / 2); }, 0.3},
      {"cos", [](const T8& a) { return cos(a); },
       [](double x, int k) { return std::cos(x + k * M_PI / 2); }, 1.1},
      {"sinh", [](const T8& a) { return sinh(a); },
       [](double x, int k) { return k % 2 ? std::cosh(x) : std::sinh(x); }, 0.4},
      {"cosh", [](const T8& a) { return cosh(a); },
       [](double x, int k) { return k % 2 ? std::sinh(x) : std::cosh(x); }, -0.4},
      {"log", [](const T8& a) { return log(a); },
       [](double x, int k) { return k == 0 ? std::log(x) : std::pow(-1.0, k + 1) * fact(k - 1) / std::pow(x, k); }, 1.7},
      {"sqrt", [](const T8& a) { return sqrt(a); },
       [](double x, int k) {
         double c = 1, r = 0.5;
         for (int i = 0; i < k; ++i) c *= (r - i);
         return c * std::pow(x, r - k);
       }, 2.3},
      {"pow2.5", [](const T8& a) { return pow(a, 2.5); },
       [](double x, int k) {
         double c = 1, r = 2.5;
         for (int i = 0; i < k; ++i) c *= (r - i);
         return c * std::pow(x, r - k);
       }, 1.3},
      {"tan", [](const T8& a) { return tan(a); },
       [](double x, int k) {
         double t = std::tan(x), s = 1 + t * t;
         switch (k) {
           case 0: return t;
           case 1: return s;
           case 2: return 2 * t * s;
           case 3: return 2 * s * (1 + 3 * t * t);
           default: return 8 * t * s * (2 + 3 * t * t);
         }
       }, 0.5},
      {"tanh", [](const T8& a) { return tanh(a); },
       [](double x, int k) {
         double t = std::tanh(x), s = 1 - t * t;
         switch (k) {
           case 0: return t;
           case 1: return s;
           case 2: return -2 * t * s;
           case 3: return -2 * s * (1 - 3 * t * t);
           default: return 8 * t * s * (2 - 3 * t * t);
         }
       }, 0.5},
      {"atan", [](const T8& a) { return atan(a); },
       [](double x, int k) {
         double q = 1 + x * x;
         switch (k) {
           case 0: return std::atan(x);
           case 1: return 1 / q;
           case 2: return -2 * x / (q * q);
           case 3: return (6 * x * x - 2) / (q * q * q);
           default: return 24 * x * (1 - x * x) / (q * q * q * q);
         }
       }, 0.6},
      {"asin", [](const T8& a) { return asin(a); },
       [](double x, int k) {
         double w = 1 - x * x;
         switch (k) {
           case 0: return std::asin(x);
           case 1: return std::pow(w, -0.5);
           case 2: return x * std::pow(w, -1.5);
           case 3: return (1 + 2 * x * x) * std::pow(w, -2.5);
           default: return (6 * x * x * x + 9 * x) * std::pow(w, -3.5);
         }
       }, 0.35},
  };
  for (const auto& c : cases) {
    T8 r = c.f(T8::variable(0, c.x0));
    for (int k = 0; k <= 4; ++k) {
      double expected = c.deriv(c.x0, k) / fact(k);
      EXPECT_NEAR(r[k], expected, kTol * std::max(1.0, std::fabs(expected))) << c.name << " k=" << k;
    }
  }
}

TEST(Jet, AcosIsHalfPiMinusAsin) {
  T8 x = T8::variable(0, -0.2);
  T8 a = acos(x), b = asin(x);
  EXPECT_NEAR(a[0] + b[0], M_PI / 2, 1e-15);
  for (int k = 1; k <= 8; ++k) EXPECT_NEAR(a[k], -b[k], 1e-13);
}

TEST(Jet, IdentitiesHoldToEveryOrder) {
  const double kTol = 1e-11;
  for (double x0 : {0.3, 1.9, -2.4}) {
    T8 x = T8::variable(0, x0);
    T8 s2 = sin(2.0 * x), twice = 2.0 * sin(x) * cos(x);
    T8 one = sin(x) * sin(x) + cos(x) * cos(x);
    T8 e = exp(log(exp(x))) - exp(x);
    T8 ch = cosh(x) * cosh(x) - sinh(x) * sinh(x);
    T8 t = tan(x) - sin(x) / cos(x);
    T8 th = tanh(x) - sinh(x) / cosh(x);
    T8 at = atan(tan(x * 0.3)) - x * 0.3;  // |0.3 x| < pi/2
    for (int k = 0; k <= 8; ++k) {
      EXPECT_NEAR(s2[k], twice[k], kTol) << k;
      EXPECT_NEAR(one[k], k == 0 ? 1.0 : 0.0, kTol) << k;
      EXPECT_NEAR(e[k], 0.0, kTol * std::exp(std::fabs(x0))) << k;
      EXPECT_NEAR(ch[k], k == 0 ? 1.0 : 0.0, kTol * 100) << k;
      EXPECT_NEAR(t[k], 0.0, 1e-7 * std::max(1.0, std::fabs(tan(x)[k]))) << k;
      EXPECT_NEAR(th[k], 0.0, kTol) << k;
      EXPECT_NEAR(at[k], 0.0, kTol) << k;
    }
  }
}

TEST(Jet, PowersIntegerRealAndSqrtAgree) {
  T8 x = T8::variable(0, 1.6);
  T8 a = pow(x, 3), b = x * x * x, c = pow(x, 3.0), d = sqrt(x) * sqrt(x), e = pow(x, -2), f = 1.0 / (x * x);
  T8 g = cbrt(x) * cbrt(x) * cbrt(x);
  T8 h = pow(x, T8(0.5)) - sqrt(x);
  T8 xy = pow(x, 0.5 * x), xy2 = exp(0.5 * x * log(x));
  T8 i = pow(x, x * 0.5) - xy2;
  for (int k = 0; k <= 8; ++k) {
    EXPECT_NEAR(a[k], b[k], 1e-13);
    EXPECT_NEAR(a[k], c[k], 1e-13);
    EXPECT_NEAR(d[k], x[k], 1e-13);
    EXPECT_NEAR(e[k], f[k], 1e-13);
    EXPECT_NEAR(g[k], x[k], 1e-13);
    EXPECT_NEAR(h[k], 0.0, 1e-13);
    EXPECT_NEAR(i[k], 0.0, 1e-13);
    (void)xy;
  }
}

TEST(Jet, IntegerPowerAtZeroIsExact) {
  T8 x = T8::variable(0, 0.0);
  T8 p = pow(x, 4);
  for (int k = 0; k <= 8; ++k) EXPECT_EQ(p[k], k == 4 ? 1.0 : 0.0);
}

TEST(Jet, SingularInputsAreReportedNotHidden) {
  Taylor<3> z = Taylor<3>::variable(0, 0.0);
  EXPECT_FALSE(is_finite(sqrt(z)));
  EXPECT_FALSE(is_finite(log(z)));
  EXPECT_FALSE(is_finite(pow(z, 0.5)));
  EXPECT_FALSE(is_finite(abs(z)));
  EXPECT_TRUE(is_finite(sqrt(Taylor<3>::variable(0, 1.0))));
}

TEST(Jet, Atan2MatchesAtanOfRatioAndIsContinuousAcrossPi) {
  using J = Jet<2, 4>;
  for (double angle : {0.3, 2.0, 3.1, -3.1, -1.2}) {
    double x0 = 2 * std::cos(angle), y0 = 2 * std::sin(angle);
    J x = J::variable(0, x0), y = J::variable(1, y0);
    J r = atan2(y, x);
    EXPECT_NEAR(r.value(), std::atan2(y0, x0), 1e-15);
    // d/dx = -y/(x^2+y^2), d/dy = x/(x^2+y^2), d2/dx2 = 2xy/(x^2+y^2)^2
    double q = x0 * x0 + y0 * y0;
    EXPECT_NEAR(r.derivative({1, 0}), -y0 / q, 1e-14);
    EXPECT_NEAR(r.derivative({0, 1}), x0 / q, 1e-14);
    EXPECT_NEAR(r.derivative({2, 0}), 2 * x0 * y0 / (q * q), 1e-14);
    EXPECT_NEAR(r.derivative({0, 2}), -2 * x0 * y0 / (q * q), 1e-14);
  }
}

TEST(Jet, MultivariateMonomialLayoutAndMixedPartials) {
  using J = Jet<3, 4>;
  static_assert(J::kSize == 35);
  J x = J::variable(0, 1.5), y = J::variable(1, -0.5), z = J::variable(2, 2.0);
  J f = x * x * y * z * z + sin(x * y) * z;
  // d^5/dx^2 dy dz^2 of x^2 y z^2 = 2*1*2 = 4; sin part has no z^2.
  // Use order 4: check d^4 / dx^2 dy dz = 2*2 x0^0... (x^2 y z^2)_{xxyz} = 2*2 z0 = 4 z0.
  double x0 = 1.5, y0 = -0.5, z0 = 2.0;
  // (sin(xy) z)_{xxyz} = d/dy d2/dx2 sin(xy) = d/dy(-y^2 sin(xy)) = -2y sin(xy) - x y^2 cos(xy)
  double expected = 4 * z0 + (-2 * y0 * std::sin(x0 * y0) - x0 * y0 * y0 * std::cos(x0 * y0));
  EXPECT_NEAR(f.derivative({2, 1, 1}), expected, 1e-12);
  EXPECT_NEAR(f.derivative({0, 0, 0}), x0 * x0 * y0 * z0 * z0 + std::sin(x0 * y0) * z0, 1e-14);
  EXPECT_NEAR(f.derivative({0, 0, 2}), 2 * x0 * x0 * y0, 1e-13);
  EXPECT_EQ(f.coef({5, 0, 0}), 0.0);  // beyond the order
}

TEST(Jet, ProductMatchesNaivePolynomialProduct) {
  using J = Jet<2, 5>;
  std::mt19937 rng(12345);  // seed logged in the test name
  std::uniform_real_distribution<double> U(-1, 1);
  J a, b;
  for (int i = 0; i < J::kSize; ++i) {
    a[i] = U(rng);
    b[i] = U(rng);
  }
  J p = a * b;
  const auto& L = Jet<2, 5>::Layout::get();
  for (int k = 0; k < J::kSize; ++k) {
    double s = 0;
    for (int i = 0; i < J::kSize; ++i)
      for (int j = 0; j < J::kSize; ++j) {
        auto ei = L.exponents[i], ej = L.exponents[j], ek = L.exponents[k];
        if (ei[0] + ej[0] == ek[0] && ei[1] + ej[1] == ek[1]) s += a[i] * b[j];
      }
    EXPECT_NEAR(p[k], s, 1e-14);
  }
}

TEST(Jet, DivisionInvertsMultiplication) {
  using J = Jet<2, 6>;
  J u = J::variable(0, 0.7), v = J::variable(1, 1.3);
  J a = sin(u) + v * v, b = 2.0 + cos(u * v);
  J q = (a / b) * b - a;
  for (int i = 0; i < J::kSize; ++i) EXPECT_NEAR(q[i], 0.0, 1e-13);
}

TEST(Jet, DivisionByRecurrenceEqualsTheReciprocalSeries) {
  // The recurrence (core/jet.hpp) against the reciprocal's Taylor series 1/b0 sum (-h/b0)^k
  // multiplied out, to order 12 in three variables, and a zero constant term stays visible.
  using J = Jet<3, 12>;
  const J x = J::variable(0, 0.4), y = J::variable(1, -0.9), z = J::variable(2, 1.7);
  const J a = exp(x) * y + z, b = 3.0 + x * y - sin(z);
  J h = b;
  h[0] = 0.0;
  const std::array<double, 13> series = internal::reciprocal<12>(b.value());
  J inv(series[12]);
  for (int k = 11; k >= 0; --k) inv = inv * h + series[static_cast<std::size_t>(k)];
  const J expected = a * inv, got = a / b;
  for (int i = 0; i < J::kSize; ++i)
    EXPECT_NEAR(got[i], expected[i], 1e-12 * (1.0 + std::abs(expected[i]))) << "coefficient " << i;
  EXPECT_FALSE(is_finite(J(1.0) / (x - 0.4)));
  EXPECT_FALSE(is_finite(reciprocal(Taylor<4>::variable(0, 0.0))));
}

// The graded recurrences of sin, cos, exp, log, sqrt and real powers (core/jet.hpp, Jet::sin_cos,
// exp_of, power_of) against Horner's rule in h = a - a0 with the univariate series (Jet::apply, the
// way they were computed before): two independent computations of the same truncated
// composition, on random jets in two variables to order 12 (the local curves') and three to order 6.
template <int NV, int K>
void expect_recurrences_match_horner(unsigned seed) {
  using J = Jet<NV, K>;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> coefficient(-0.5, 0.5), value(0.3, 2.5);
  for (int trial = 0; trial < 20; ++trial) {
    J a;
    for (int i = 1; i < J::kSize; ++i) a[i] = coefficient(gen);
    a[0] = value(gen);
    const double a0 = a.value();
    const auto compare = [&](const J& got, const J& horner, const char* what) {
      for (int i = 0; i < J::kSize; ++i)
        EXPECT_NEAR(got[i], horner[i], 1e-13 * (1.0 + std::abs(horner[i]))) << what << " coefficient " << i;
    };
    compare(sin(a), J::apply(a, internal::sin<K>(a0)), "sin");
    compare(cos(a), J::apply(a, internal::cos<K>(a0)), "cos");
    compare(exp(a), J::apply(a, internal::exp<K>(a0)), "exp");
    compare(log(a), J::apply(a, internal::log<K>(a0)), "log");
    compare(sqrt(a), J::apply(a, internal::sqrt<K>(a0)), "sqrt");
    compare(pow(a, -0.37), J::apply(a, internal::pow<K>(a0, -0.37)), "pow");
  }
}

TEST(Jet, GradedRecurrencesEqualHornersRule) {
  expect_recurrences_match_horner<2, 12>(3);
  expect_recurrences_match_horner<3, 6>(5);
  expect_recurrences_match_horner<1, 8>(7);
  // Identities that hold coefficient by coefficient: sin^2 + cos^2 = 1, exp(log a) = a,
  // sqrt(a)^2 = a, on one jet of order 12 in two variables.
  using J = Jet<2, 12>;
  const J s = J::variable(0, 0.7), t = J::variable(1, -0.2);
  const J a = 1.5 + s * t + 0.3 * s * s - 0.2 * t;
  const J one = sin(a) * sin(a) + cos(a) * cos(a), back = exp(log(a)), square = sqrt(a) * sqrt(a);
  for (int i = 0; i < J::kSize; ++i) {
    EXPECT_NEAR(one[i], i == 0 ? 1.0 : 0.0, 1e-14) << i;
    EXPECT_NEAR(back[i], a[i], 1e-13) << i;
    EXPECT_NEAR(square[i], a[i], 1e-13) << i;
  }
  // Singular inputs stay visible: sqrt and log at 0.
  EXPECT_FALSE(is_finite(sqrt(J::variable(0, 0.0))));
  EXPECT_FALSE(is_finite(log(J::variable(0, 0.0))));
}

TEST(Jet, FirstOrderAgreesWithCentralDifferences) {
  using J = Jet<3, 1>;
  auto f = [](auto x, auto y, auto z) { return exp(x * 0.3) * sin(y) + sqrt(x * x + z * z) * atan(z); };
  double p[3] = {0.4, 1.2, -0.8};
  J r = f(J::variable(0, p[0]), J::variable(1, p[1]), J::variable(2, p[2]));
  const double h = 1e-6;
  for (int i = 0; i < 3; ++i) {
    double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
    a[i] += h;
    b[i] -= h;
    auto fd = [&](double* q) {
      return std::exp(q[0] * 0.3) * std::sin(q[1]) + std::sqrt(q[0] * q[0] + q[2] * q[2]) * std::atan(q[2]);
    };
    EXPECT_NEAR(r.d(i), (fd(a) - fd(b)) / (2 * h), 1e-8);
  }
}

TEST(Jet, CompositionGivesCurveOnSurfaceDerivatives) {
  // Surface F(u,v) = u^2 v + sin(v) along the curve (u,v) = (cos s, s^2) at s0 = 0.5:
  // g(s) = cos^2 s * s^2 + sin(s^2). Compare the composed jet with direct evaluation.
  constexpr int K = 6;
  double s0 = 0.5;
  Taylor<K> s = Taylor<K>::variable(0, s0);
  Taylor<K> us = cos(s), vs = s * s;
  Jet<2, K> u = Jet<2, K>::variable(0, us.value()), v = Jet<2, K>::variable(1, vs.value());
  Jet<2, K> F = u * u * v + sin(v);
  Taylor<K> composed = compose<2, 1, K>(F, {us, vs});
  Taylor<K> direct = us * us * vs + sin(vs);
  for (int k = 0; k <= K; ++k) EXPECT_NEAR(composed[k], direct[k], 1e-13) << k;
}

}  // namespace
}  // namespace ssimarch
