// Expression values on double: every operator, precedence and associativity rule, every function,
// constants, folding and sharing, register spilling, evaluation overloads. Expected values are
// written out by hand or computed by the same double operations in C++ (so EXPECT_EQ is exact).
#include "ssimarch/expr/program.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ssimarch/core/error.hpp"

namespace ssimarch {
namespace {

const std::vector<std::string> kUV = {"u", "v"};
const std::vector<std::string> kXYZ = {"x", "y", "z"};

double eval_uv(const std::string& source, double u, double v, const Constants& constants = {}) {
  Program p = Program::compile_or_throw(source, kUV, constants, "test");
  return p.eval({u, v});
}

// Keeps the compiler from folding expected values with its own (correctly rounded) libm: the
// program calls the run-time library, which may differ in the last bit (glibc's cbrt does).
double opaque(double x) {
  volatile double v = x;
  return v;
}

double value(const std::string& source, const Constants& constants = {}) {
  return evaluate_constant(source, constants, "test");
}

TEST(ExprProgram, NumberLiterals) {
  EXPECT_EQ(value("0"), 0.0);
  EXPECT_EQ(value("42"), 42.0);
  EXPECT_EQ(value("3.25"), 3.25);
  EXPECT_EQ(value(".5"), 0.5);
  EXPECT_EQ(value("5."), 5.0);
  EXPECT_EQ(value("1e-3"), 1e-3);
  EXPECT_EQ(value("1E3"), 1000.0);
  EXPECT_EQ(value("2.5e+2"), 250.0);
  EXPECT_EQ(value(".5e1"), 5.0);
  EXPECT_EQ(value("007"), 7.0);
  EXPECT_EQ(value("0.1"), 0.1);  // correctly rounded, as the C++ literal
}

TEST(ExprProgram, ArithmeticOperators) {
  EXPECT_EQ(value("7+2"), 9.0);
  EXPECT_EQ(value("7-2"), 5.0);
  EXPECT_EQ(value("7*2"), 14.0);
  EXPECT_EQ(value("7/2"), 3.5);
  EXPECT_EQ(value("2^10"), 1024.0);
  EXPECT_EQ(value("-7"), -7.0);
  EXPECT_EQ(value("+7"), 7.0);
  EXPECT_EQ(value("--7"), 7.0);
  EXPECT_EQ(value("-+-7"), 7.0);
  EXPECT_EQ(value("---7"), -7.0);
  EXPECT_EQ(eval_uv("u+v", 1.5, 2.25), 3.75);
  EXPECT_EQ(eval_uv("u-v", 1.5, 2.25), -0.75);
  EXPECT_EQ(eval_uv("u*v", 1.5, 2.25), 3.375);
  EXPECT_EQ(eval_uv("u/v", 3.0, 4.0), 0.75);
  EXPECT_EQ(eval_uv("-u", 3.0, 0.0), -3.0);
  EXPECT_EQ(eval_uv("+u", 3.0, 0.0), 3.0);
}

TEST(ExprProgram, PrecedenceAndAssociativity) {
  EXPECT_EQ(value("1+2*3"), 7.0);
  EXPECT_EQ(value("(1+2)*3"), 9.0);
  EXPECT_EQ(value("2*3+1"), 7.0);
  EXPECT_EQ(value("8-4-2"), 2.0);     // left-associative
  EXPECT_EQ(value("8/4/2"), 1.0);     // left-associative
  EXPECT_EQ(value("8/4*2"), 4.0);
  EXPECT_EQ(value("8-4+2"), 6.0);
  EXPECT_EQ(value("2^3^2"), 512.0);   // right-associative: 2^(3^2)
  EXPECT_EQ(value("(2^3)^2"), 64.0);
  EXPECT_EQ(value("-2^2"), -4.0);     // -(2^2)
  EXPECT_EQ(value("(-2)^2"), 4.0);
  EXPECT_EQ(value("2^-1"), 0.5);      // a signed exponent
  EXPECT_EQ(value("2^-1^2"), 0.5);    // 2^(-(1^2))
  EXPECT_EQ(value("-2^-2"), -0.25);
  EXPECT_EQ(value("2*3^2"), 18.0);
  EXPECT_EQ(value("2^3*2"), 16.0);
  EXPECT_EQ(value("-3*-2"), 6.0);     // a sign after '*'
  EXPECT_EQ(value("6/-2"), -3.0);
  EXPECT_EQ(value("1--1"), 2.0);
  EXPECT_EQ(value("2*-3^2"), -18.0);
  EXPECT_EQ(value("((((3))))"), 3.0);
  EXPECT_EQ(eval_uv("-u^2", 3.0, 0.0), -9.0);
  EXPECT_EQ(eval_uv("u^v^2", 2.0, 2.0), 16.0);
  EXPECT_EQ(eval_uv("u - v - 1", 10.0, 3.0), 6.0);
  EXPECT_EQ(eval_uv("u / v / 2", 12.0, 3.0), 2.0);
  EXPECT_EQ(eval_uv(" u\t+\n v\r", 1.0, 2.0), 3.0);  // any blank separates
}

TEST(ExprProgram, IntegerPowers) {
  // Integer exponents take the binary-powering path of pow(Jet, int): x^3 = (1*x)*(x*x).
  const double x = 1.1;
  EXPECT_EQ(eval_uv("u^3", x, 0), (1.0 * x) * (x * x));
  EXPECT_EQ(eval_uv("u^2", x, 0), x * x);
  EXPECT_EQ(eval_uv("u^1", x, 0), x);
  EXPECT_EQ(eval_uv("u^0", 0.0, 0), 1.0);
  EXPECT_EQ(eval_uv("u^-1", 4.0, 0), 0.25);
  EXPECT_EQ(eval_uv("u^-2", 4.0, 0), 0.0625);
  EXPECT_EQ(eval_uv("u^2", -3.0, 0), 9.0);   // negative base fine for integer exponents
  EXPECT_EQ(eval_uv("u^3", -2.0, 0), -8.0);
  EXPECT_EQ(eval_uv("u^(1+1)", 5.0, 0), 25.0);  // a constant exponent that folds to an integer
  EXPECT_EQ(eval_uv("pow(u, 2)", 5.0, 0), 25.0);
  EXPECT_EQ(eval_uv("u^2.0", 5.0, 0), 25.0);
  EXPECT_EQ(integer_power(3.0, 5), 243.0);
  EXPECT_EQ(integer_power(2.0, -3), 0.125);
  EXPECT_EQ(integer_power(0.0, 0), 1.0);
  Program p = Program::compile_or_throw("u^2", kUV, {});
  ASSERT_EQ(p.code().size(), 2u);
  EXPECT_EQ(p.code()[1].op, OpCode::kPowInt);
  EXPECT_EQ(p.code()[1].b, 2);
  // Beyond kMaxIntegerExponent the real power takes over.
  Program q = Program::compile_or_throw("u^2097152", kUV, {});
  EXPECT_EQ(q.code().back().op, OpCode::kPowReal);
  EXPECT_EQ(q.eval({1.0, 0.0}), 1.0);
}

TEST(ExprProgram, RealPowers) {
  EXPECT_EQ(eval_uv("u^0.5", 2.0, 0), std::pow(opaque(2.0), 0.5));
  EXPECT_EQ(eval_uv("u^(1/3)", 5.0, 0), std::pow(opaque(5.0), 1.0 / 3.0));
  EXPECT_EQ(eval_uv("u^v", 2.0, 0.3), std::pow(opaque(2.0), 0.3));
  EXPECT_EQ(eval_uv("pow(u, v)", 2.0, 0.3), std::pow(opaque(2.0), 0.3));
  EXPECT_EQ(eval_uv("2^v", 0, 0.3), std::pow(opaque(2.0), 0.3));
  EXPECT_EQ(eval_uv("e^v", 0, 0.3), std::pow(opaque(std::numbers::e), 0.3));
  EXPECT_TRUE(std::isnan(eval_uv("u^0.5", -1.0, 0)));
  Program p = Program::compile_or_throw("u^0.5", kUV, {});
  EXPECT_EQ(p.code().back().op, OpCode::kPowReal);
}

TEST(ExprProgram, EveryFunction) {
  const double a = opaque(0.37), b = opaque(-1.25);
  struct Case {
    const char* source;
    double expected;
  };
  const std::vector<Case> cases = {
      {"sqrt(u)", std::sqrt(a)},   {"cbrt(v)", std::cbrt(b)},   {"exp(v)", std::exp(b)},
      {"log(u)", std::log(a)},     {"ln(u)", std::log(a)},      {"sin(v)", std::sin(b)},
      {"cos(v)", std::cos(b)},     {"tan(v)", std::tan(b)},     {"asin(u)", std::asin(a)},
      {"acos(u)", std::acos(a)},   {"atan(v)", std::atan(b)},   {"sinh(v)", std::sinh(b)},
      {"cosh(v)", std::cosh(b)},   {"tanh(v)", std::tanh(b)},   {"abs(v)", 1.25},
      {"atan2(u, v)", std::atan2(a, b)}, {"atan2(v, u)", std::atan2(b, a)},
      {"pow(u, v)", std::pow(a, b)},     {"pow(u, 3)", (1.0 * a) * (a * a)},
  };
  for (const auto& c : cases) EXPECT_EQ(eval_uv(c.source, a, b), c.expected) << c.source;
  // Folded at compile time with the same functions.
  EXPECT_EQ(value("sqrt(2)"), std::sqrt(opaque(2.0)));
  EXPECT_EQ(value("atan2(1, -1)"), std::atan2(opaque(1.0), -1.0));
  EXPECT_EQ(value("abs(-3)"), 3.0);
  EXPECT_EQ(value("exp(1)"), std::exp(opaque(1.0)));
  EXPECT_EQ(value("cbrt(-27)"), std::cbrt(opaque(-27.0)));
  EXPECT_NEAR(value("cbrt(-27)"), -3.0, 1e-15);
}

TEST(ExprProgram, BuiltinAndCallerConstants) {
  EXPECT_EQ(value("pi"), std::numbers::pi);
  EXPECT_EQ(value("e"), std::numbers::e);
  EXPECT_EQ(value("2*pi"), 2.0 * std::numbers::pi);
  Constants c{{"R", 2.0}, {"r_1", 0.5}, {"pi", 3.0}};
  EXPECT_EQ(value("R^2 + r_1", c), 4.5);
  EXPECT_EQ(value("pi", c), 3.0);  // caller constants shadow the built-ins
  EXPECT_EQ(eval_uv("R*u", 1.5, 0, {{"R", 2.0}}), 3.0);
  // Variables shadow constants.
  std::vector<std::string> vars = {"e"};
  Program p = Program::compile_or_throw("e*2", vars, {});
  EXPECT_EQ(p.eval({5.0}), 10.0);
  // A constant named like a function is still a value when not called.
  EXPECT_EQ(value("sin*2", {{"sin", 4.0}}), 8.0);
  EXPECT_EQ(value("sin(0)+1", {{"sin", 4.0}}), 1.0);
}

TEST(ExprProgram, ExampleExpressionMatchesHandWrittenCode) {
  const std::string source = "(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)";
  Program p = Program::compile_or_throw(source, kUV, {});
  for (double u0 : {0.0, 0.3, 1.7, -2.9, 6.2}) {
    for (double v0 : {0.0, -0.4, 1.3}) {
      const double u = opaque(u0), v = opaque(v0);
      double expected = (4 + std::cos(4 * u)) * std::cos(u) + v * (std::cos(4 * u) + std::sin(4 * u)) * std::cos(u);
      EXPECT_EQ(p.eval({u, v}), expected) << u << " " << v;
    }
  }
  // Shared subexpressions: cos(4u), cos(u) and 4u are each computed once.
  int trig = 0;
  for (const auto& in : p.code()) trig += in.op == OpCode::kCos || in.op == OpCode::kSin;
  EXPECT_EQ(trig, 3);
  EXPECT_EQ(p.source(), source);
  EXPECT_LE(p.num_registers(), 5);
}

TEST(ExprProgram, ImplicitExampleAndUsedVariables) {
  Program p = Program::compile_or_throw("x^2+y^2-x", kXYZ, {});
  EXPECT_EQ(p.num_variables(), 3);
  EXPECT_EQ(p.eval({1.0, 1.0, 7.0}), 1.0);
  EXPECT_EQ(p.eval({0.5, 0.0, 0.0}), -0.25);
  EXPECT_TRUE(p.uses_variable(0));
  EXPECT_TRUE(p.uses_variable(1));
  EXPECT_FALSE(p.uses_variable(2));
  EXPECT_FALSE(p.uses_variable(3));
  EXPECT_FALSE(p.uses_variable(-1));
  Program q = Program::compile_or_throw("v^2 + 2*pi", kUV, {});
  EXPECT_FALSE(q.uses_variable(0));
  EXPECT_TRUE(q.uses_variable(1));
  EXPECT_FALSE(q.is_constant());
  // Not simplified away: 0*u is NaN at u = inf, so u stays in use.
  EXPECT_TRUE(Program::compile_or_throw("0*u + v", kUV, {}).uses_variable(0));
}

TEST(ExprProgram, ConstantFoldingAndImmediates) {
  Program p = Program::compile_or_throw("2*3 + u", kUV, {});
  ASSERT_EQ(p.code().size(), 2u);
  EXPECT_EQ(p.code()[0].op, OpCode::kVar);
  EXPECT_EQ(p.code()[1].op, OpCode::kAddC);
  EXPECT_EQ(p.code()[1].imm, 6.0);
  Program c = Program::compile_or_throw("2*pi/4 + sqrt(16)", kUV, {});
  EXPECT_TRUE(c.is_constant());
  EXPECT_EQ(c.constant_value(), 2 * std::numbers::pi / 4 + 4.0);
  EXPECT_FALSE(c.uses_variable(0));
  EXPECT_EQ(c.eval({1.0, 2.0}), c.constant_value());
  EXPECT_THROW((void)p.constant_value(), std::logic_error);
  // Each constant-operand form, with the operand order kept (c - u is not u - c).
  struct Case {
    const char* source;
    OpCode op;
    double expected;  // at u = 4
  };
  for (const Case& k : {Case{"u+2", OpCode::kAddC, 6}, Case{"2+u", OpCode::kAddC, 6}, Case{"u-1", OpCode::kSubC, 3},
                        Case{"1-u", OpCode::kRSubC, -3}, Case{"u*3", OpCode::kMulC, 12}, Case{"3*u", OpCode::kMulC, 12},
                        Case{"u/8", OpCode::kDivC, 0.5}, Case{"8/u", OpCode::kRDivC, 2}}) {
    Program q = Program::compile_or_throw(k.source, kUV, {});
    EXPECT_EQ(q.code().back().op, k.op) << k.source;
    EXPECT_EQ(q.eval({4.0, 0.0}), k.expected) << k.source;
  }
  // Both operands variable, and a constant register operand.
  EXPECT_EQ(eval_uv("atan2(1, u)", 1.0, 0), std::atan2(opaque(1.0), 1.0));
  EXPECT_EQ(eval_uv("atan2(u, 1)", 1.0, 0), std::atan2(opaque(1.0), 1.0));
}

TEST(ExprProgram, SharedSubexpressionsAreComputedOnce) {
  Program p = Program::compile_or_throw("sin(u)*sin(u) + sin(u)", kUV, {});
  int sines = 0;
  for (const auto& in : p.code()) sines += in.op == OpCode::kSin;
  EXPECT_EQ(sines, 1);
  const double s = std::sin(opaque(0.5));
  EXPECT_EQ(p.eval({0.5, 0.0}), s * s + s);
  EXPECT_FALSE(p.disassemble().empty());
}

TEST(ExprProgram, ManyLiveRegistersSpillToTheHeap) {
  // 300 shared values stay live from their first to their second use: more registers than the
  // evaluator's stack buffer holds (64).
  std::string first, second;
  double expected = 0;
  const double u = 0.1;
  for (int k = 1; k <= 300; ++k) {
    std::string term = "sin(" + std::to_string(k) + "*u)";
    first += (k > 1 ? "+" : "") + term;
    second += "+" + term;
    expected += std::sin(k * opaque(u));
  }
  for (int k = 1; k <= 300; ++k) expected += std::sin(k * opaque(u));
  Program p = Program::compile_or_throw(first + second, kUV, {});
  EXPECT_GT(p.num_registers(), 64);
  EXPECT_EQ(p.eval({u, 0.0}), expected);
}

TEST(ExprProgram, LongFlatChainsCompileWithoutRecursion) {
  std::string s = "u";
  for (int i = 0; i < 100000; ++i) s += "+u";
  Program p = Program::compile_or_throw(s, kUV, {});
  EXPECT_EQ(p.eval({1.0, 0.0}), 100001.0);
  std::string signs(100000, '-');
  EXPECT_EQ(eval_uv(signs + "u", 2.0, 0.0), 2.0);  // an even number of signs
  EXPECT_EQ(eval_uv("-" + signs + "u", 2.0, 0.0), -2.0);
}

TEST(ExprProgram, EvalOverloads) {
  Program p = Program::compile_or_throw("u - 2*v", kUV, {});
  std::array<double, 2> arr{5.0, 1.0};
  std::vector<double> vec{5.0, 1.0};
  EXPECT_EQ(p.eval(arr), 3.0);
  EXPECT_EQ(p.eval({5.0, 1.0}), 3.0);
  EXPECT_EQ(p.eval(arr.data()), 3.0);
  EXPECT_EQ(p.eval<double>(vec), 3.0);
  EXPECT_EQ(p.eval(std::span<const double>(vec)), 3.0);
  EXPECT_THROW((void)p.eval({5.0}), std::out_of_range);
  EXPECT_EQ(p.num_variables(), 2);
  EXPECT_EQ(p.variables(), kUV);
  // More inputs than variables are fine (the rest is ignored).
  EXPECT_EQ(p.eval({5.0, 1.0, 99.0}), 3.0);
}

TEST(ExprProgram, CompileOrThrowAndEvaluateConstant) {
  EXPECT_EQ(value("R/2", {{"R", 3.0}}), 1.5);
  try {
    (void)evaluate_constant("2*pj", {}, "surfaces.cyl.u[1]");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "surfaces.cyl.u[1]");
    EXPECT_EQ(std::string(e.what()),
              "surfaces.cyl.u[1]: column 3: unknown name 'pj'; did you mean 'pi'? (variables: none; constants: pi, e)\n"
              "  2*pj\n"
              "    ^");
  }
  EXPECT_THROW((void)evaluate_constant("u", {}), InputError);  // no variables in a constant
  EXPECT_THROW((void)Program::compile_or_throw("u+", kUV, {}), InputError);
}

TEST(ExprProgram, CompileLeavesOutputUntouchedOnError) {
  Program p = Program::compile_or_throw("u+1", kUV, {});
  ParseError error;
  EXPECT_FALSE(Program::compile("u+", kUV, {}, &p, &error));
  EXPECT_EQ(p.source(), "u+1");
  EXPECT_EQ(p.eval({1.0, 0.0}), 2.0);
  EXPECT_FALSE(Program::compile("u+", kUV, {}, &p, nullptr));  // a null error is allowed
  EXPECT_TRUE(Program::compile("v", kUV, {}, nullptr, nullptr));
}

TEST(ExprProgram, DefaultProgramEvaluatesToZero) {
  Program p;
  EXPECT_EQ(p.num_variables(), 0);
  EXPECT_EQ(p.eval(static_cast<const double*>(nullptr)), 0.0);
}

}  // namespace
}  // namespace ssimarch
