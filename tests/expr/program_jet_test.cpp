// Programs evaluated on Taylor jets: identical coefficients to the same formula written with
// jets by hand, and derivatives equal to closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/expr/program.hpp"

namespace ssimarch {
namespace {

using J = Jet<2, 3>;
const std::vector<std::string> kUV = {"u", "v"};

void expect_same_jet(const J& got, const J& want, const std::string& what) {
  for (int i = 0; i < J::kSize; ++i) {
    if (std::isnan(want[i]))
      EXPECT_TRUE(std::isnan(got[i])) << what << " coefficient " << i;
    else
      EXPECT_EQ(got[i], want[i]) << what << " coefficient " << i;
  }
}

J eval_jet(const std::string& source, const J& u, const J& v) {
  Program p = Program::compile_or_throw(source, kUV, {}, "test");
  return p.eval({u, v});
}

TEST(ExprJet, ExampleExpressionEqualsHandWrittenJetFormula) {
  const J u = J::variable(0, 0.3), v = J::variable(1, -0.7);
  J got = eval_jet("(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)", u, v);
  J want = (4.0 + cos(4.0 * u)) * cos(u) + v * (cos(4.0 * u) + sin(4.0 * u)) * cos(u);
  expect_same_jet(got, want, "example");
  // And against closed-form partial derivatives of f = (4 + cos 4u) cos u + v (cos 4u + sin 4u) cos u.
  const double u0 = 0.3, v0 = -0.7, c4 = std::cos(4 * u0), s4 = std::sin(4 * u0), c = std::cos(u0), s = std::sin(u0);
  const double kTol = 1e-13;  // absolute, on values of order 10
  EXPECT_NEAR(got.value(), (4 + c4) * c + v0 * (c4 + s4) * c, kTol);
  EXPECT_NEAR(got.derivative({1, 0}), -4 * s4 * c - (4 + c4) * s + v0 * ((-4 * s4 + 4 * c4) * c - (c4 + s4) * s), kTol);
  EXPECT_NEAR(got.derivative({0, 1}), (c4 + s4) * c, kTol);
  EXPECT_NEAR(got.derivative({1, 1}), (-4 * s4 + 4 * c4) * c - (c4 + s4) * s, kTol);
  EXPECT_NEAR(got.derivative({0, 2}), 0.0, kTol);
  EXPECT_NEAR(got.derivative({0, 3}), 0.0, kTol);
}

TEST(ExprJet, EveryOperatorAndFunctionEqualsTheJetLibrary) {
  const J u = J::variable(0, 0.4), v = J::variable(1, 1.3);
  struct Case {
    const char* source;
    J want;
  };
  const std::vector<Case> cases = {
      {"u+v", u + v},
      {"u-v", u - v},
      {"u*v", u * v},
      {"u/v", u / v},
      {"-u", -u},
      {"u+2", u + 2.0},
      {"2-u", 2.0 - u},
      {"u-2", u - 2.0},
      {"3*u", u * 3.0},
      {"u/4", u / 4.0},
      {"4/u", 4.0 / u},
      {"u^3", pow(u, 3)},
      {"u^-2", pow(u, -2)},
      {"v^0.5", pow(v, 0.5)},
      {"u^v", pow(u, v)},
      {"2^u", pow(J(2.0), u)},
      {"pow(u, v)", pow(u, v)},
      {"sqrt(v)", sqrt(v)},
      {"cbrt(u)", cbrt(u)},
      {"exp(u)", exp(u)},
      {"log(v)", log(v)},
      {"ln(v)", log(v)},
      {"sin(u)", sin(u)},
      {"cos(u)", cos(u)},
      {"tan(u)", tan(u)},
      {"asin(u)", asin(u)},
      {"acos(u)", acos(u)},
      {"atan(u)", atan(u)},
      {"atan2(u, v)", atan2(u, v)},
      {"atan2(1, u)", atan2(J(1.0), u)},
      {"sinh(u)", sinh(u)},
      {"cosh(u)", cosh(u)},
      {"tanh(u)", tanh(u)},
      {"abs(-u)", abs(-u)},
      {"-u^2", -pow(u, 2)},
      {"u*v*u", (u * v) * u},
      {"u^v^2", pow(u, pow(v, 2))},
  };
  for (const auto& c : cases) expect_same_jet(eval_jet(c.source, u, v), c.want, c.source);
}

TEST(ExprJet, IntegerPowerIsExactAtZero) {
  // u^2 at u = 0 must go through pow(Jet, int): a real power would give NaN/inf coefficients.
  const J u = J::variable(0, 0.0), v = J::variable(1, 0.0);
  J got = eval_jet("u^2 + u^3*v - 2*v^2", u, v);
  EXPECT_TRUE(is_finite(got));
  EXPECT_EQ(got.value(), 0.0);
  EXPECT_EQ(got.derivative({1, 0}), 0.0);
  EXPECT_EQ(got.derivative({2, 0}), 2.0);
  EXPECT_EQ(got.derivative({0, 2}), -4.0);
  EXPECT_EQ(got.derivative({1, 1}), 0.0);
  EXPECT_EQ(got.derivative({3, 0}), 0.0);
  // u^3 v has total degree 4 > K = 3: truncated away.
  EXPECT_EQ(got.derivative({2, 1}), 0.0);
  // The real path really would fail there: the point of the integer path.
  EXPECT_FALSE(is_finite(eval_jet("u^2.5", u, v)));
}

TEST(ExprJet, ImplicitSurfaceGradientAndHessian) {
  using J3 = Jet<3, 2>;
  const std::vector<std::string> xyz = {"x", "y", "z"};
  Program p = Program::compile_or_throw("x^2+y^2-x", xyz, {});
  const double x0 = 0.25, y0 = -1.5, z0 = 9.0;
  J3 f = p.eval({J3::variable(0, x0), J3::variable(1, y0), J3::variable(2, z0)});
  EXPECT_EQ(f.value(), x0 * x0 + y0 * y0 - x0);
  EXPECT_EQ(f.derivative({1, 0, 0}), 2 * x0 - 1);
  EXPECT_EQ(f.derivative({0, 1, 0}), 2 * y0);
  EXPECT_EQ(f.derivative({0, 0, 1}), 0.0);
  EXPECT_EQ(f.derivative({2, 0, 0}), 2.0);
  EXPECT_EQ(f.derivative({0, 2, 0}), 2.0);
  EXPECT_EQ(f.derivative({1, 1, 0}), 0.0);
  EXPECT_EQ(f.derivative({0, 0, 2}), 0.0);
}

TEST(ExprJet, HighOrderTaylorSeries) {
  // exp(2s) at s0 = 0.5: k-th coefficient 2^k e^(2 s0) / k!.
  using T8 = Taylor<8>;
  const std::vector<std::string> s = {"s"};
  Program p = Program::compile_or_throw("exp(2*s)", s, {});
  T8 f = p.eval({T8::variable(0, 0.5)});
  double fact = 1;
  for (int k = 0; k <= 8; ++k) {
    if (k > 0) fact *= k;
    EXPECT_NEAR(f[k], std::pow(2.0, k) * std::exp(1.0) / fact, 1e-14 * std::pow(2.0, k) * std::exp(1.0)) << k;
  }
  // Products of polynomials are exact: (1 + s)^5 at s0 = 1 has coefficients C(5,k) 2^(5-k).
  Program q = Program::compile_or_throw("(1+s)^5", s, {});
  T8 g = q.eval({T8::variable(0, 1.0)});
  const double binom[] = {1, 5, 10, 10, 5, 1};
  for (int k = 0; k <= 5; ++k) EXPECT_EQ(g[k], binom[k] * std::pow(2.0, 5 - k)) << k;
  for (int k = 6; k <= 8; ++k) EXPECT_EQ(g[k], 0.0) << k;
}

TEST(ExprJet, ValueOfAJetEqualsTheDoubleEvaluation) {
  // Same operations on the value part (including the integer-power path), so equal bit for bit
  // except where jets compute a/b as a * (1/b) and pow through exp/log.
  Program p = Program::compile_or_throw("(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u) - u^3 + sqrt(v^2+1)",
                                        kUV, {});
  for (double u0 : {-2.0, -0.1, 0.0, 0.7, 3.1})
    for (double v0 : {-1.0, 0.0, 2.5}) {
      J j = p.eval({J::variable(0, u0), J::variable(1, v0)});
      EXPECT_EQ(j.value(), p.eval({u0, v0})) << u0 << " " << v0;
    }
}

TEST(ExprJet, ConstantProgramGivesConstantJet) {
  Program p = Program::compile_or_throw("2*pi", kUV, {});
  J j = p.eval({J::variable(0, 1.0), J::variable(1, 2.0)});
  EXPECT_EQ(j.value(), 2 * M_PI);
  for (int i = 1; i < J::kSize; ++i) EXPECT_EQ(j[i], 0.0);
}

}  // namespace
}  // namespace ssimarch
