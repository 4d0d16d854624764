// Every kind of compile error, with its exact column and message, and the caret display.
#include "ssimarch/expr/parse_error.hpp"

#include <gtest/gtest.h>
#include <pthread.h>

#include <string>
#include <vector>

#include "ssimarch/core/error.hpp"
#include "ssimarch/expr/program.hpp"

namespace ssimarch {
namespace {

const std::vector<std::string> kUV = {"u", "v"};

ParseError error_of(const std::string& source, const Constants& constants = {{"R", 2.0}},
                    const std::vector<std::string>& vars = kUV) {
  Program p;
  ParseError e;
  EXPECT_FALSE(Program::compile(source, vars, constants, &p, &e)) << source;
  EXPECT_LE(e.offset, source.size());
  EXPECT_EQ(e.column, display_column(source, e.offset));
  return e;
}

struct ErrorCase {
  std::string source;
  ParseErrorKind kind;
  int column;
  std::string message;
};

void check(const std::vector<ErrorCase>& cases) {
  for (const auto& c : cases) {
    ParseError e = error_of(c.source);
    EXPECT_EQ(e.kind, c.kind) << c.source;
    EXPECT_EQ(e.column, c.column) << c.source;
    EXPECT_EQ(e.message, c.message) << c.source;
  }
}

using K = ParseErrorKind;

TEST(ExprErrors, EmptyExpression) {
  check({
      {"", K::kEmpty, 1, "empty expression"},
      {"   \t\n", K::kEmpty, 1, "empty expression"},
  });
}

TEST(ExprErrors, UnknownFunctionSuggestsTheNearestName) {
  check({
      {"sinn(u)", K::kUnknownFunction, 1, "unknown function 'sinn'; did you mean 'sin'?"},
      {"2*Cos(u)", K::kUnknownFunction, 3, "unknown function 'Cos'; did you mean 'cos'?"},
      {"u + arctan(v)", K::kUnknownFunction, 5, "unknown function 'arctan'; did you mean 'atan'?"},
      {"sqr(u)", K::kUnknownFunction, 1, "unknown function 'sqr'; did you mean 'sqrt'?"},
      {"foo(u)", K::kUnknownFunction, 1,
       "unknown function 'foo'; known functions: abs, acos, asin, atan, atan2, cbrt, cos, cosh, exp, ln, log, pow, "
       "sin, sinh, sqrt, tan, tanh"},
      {"u(2)", K::kUnknownFunction, 1, "'u' is a variable, not a function (write u*(...) for a product)"},
      {"1 + R (2)", K::kUnknownFunction, 5, "'R' is a constant, not a function (write R*(...) for a product)"},
      {"pi(2)", K::kUnknownFunction, 1, "'pi' is a constant, not a function (write pi*(...) for a product)"},
  });
}

TEST(ExprErrors, UnknownNameListsWhatIsAvailable) {
  check({
      {"w+1", K::kUnknownName, 1, "unknown name 'w' (variables: u, v; constants: R, pi, e)"},
      {"u*Pi", K::kUnknownName, 3, "unknown name 'Pi'; did you mean 'pi'? (variables: u, v; constants: R, pi, e)"},
      {"x^2+y^2", K::kUnknownName, 1, "unknown name 'x' (variables: u, v; constants: R, pi, e)"},
      {"2*sin", K::kUnknownName, 3, "'sin' is a function: call it as sin(x)"},
      {"atan2 + 1", K::kUnknownName, 1, "'atan2' is a function: call it as atan2(y, x)"},
  });
  ParseError e = error_of("2*pj", {}, {});
  EXPECT_EQ(e.message, "unknown name 'pj'; did you mean 'pi'? (variables: none; constants: pi, e)");
  EXPECT_EQ(e.column, 3);
}

TEST(ExprErrors, WrongNumberOfArguments) {
  check({
      {"atan2(u)", K::kArgumentCount, 1, "'atan2' takes 2 arguments (atan2(y, x)), got 1"},
      {"1+sin()", K::kArgumentCount, 3, "'sin' takes 1 argument (sin(x)), got 0"},
      {"sin(u, v)", K::kArgumentCount, 1, "'sin' takes 1 argument (sin(x)), got 2"},
      {"u*pow(u, v, 2)", K::kArgumentCount, 3, "'pow' takes 2 arguments (pow(a, b)), got 3"},
  });
}

TEST(ExprErrors, UnbalancedParenthesesPointAtTheUnmatchedOne) {
  check({
      {"(u+1", K::kUnmatchedParenthesis, 1, "unmatched '(' (missing ')')"},
      {"((u+1)*2", K::kUnmatchedParenthesis, 1, "unmatched '(' (missing ')')"},
      {"(u+(1)*2", K::kUnmatchedParenthesis, 1, "unmatched '(' (missing ')')"},
      {"2*(u+(1*2)", K::kUnmatchedParenthesis, 3, "unmatched '(' (missing ')')"},
      {"sin(u", K::kUnmatchedParenthesis, 4, "unmatched '(' (missing ')')"},
      {"atan2(u, v", K::kUnmatchedParenthesis, 6, "unmatched '(' (missing ')')"},
      {"u+(", K::kUnmatchedParenthesis, 3, "unmatched '(' (missing ')')"},
      {"u+1)", K::kUnmatchedParenthesis, 4, "unmatched ')'"},
      {"(u+1))", K::kUnmatchedParenthesis, 6, "unmatched ')'"},
      {")", K::kUnmatchedParenthesis, 1, "unmatched ')'"},
      {"u*)", K::kUnmatchedParenthesis, 3, "unmatched ')'"},
  });
}

TEST(ExprErrors, TrailingGarbage) {
  check({
      {"u+1 v", K::kTrailing, 5, "unexpected name 'v' after a complete expression (missing operator?)"},
      {"2 3", K::kTrailing, 3, "unexpected number '3' after a complete expression (missing operator?)"},
      {"2(u)", K::kTrailing, 2, "unexpected '(' after a complete expression (missing operator?)"},
      {"sin(u) cos(v)", K::kTrailing, 8, "unexpected name 'cos' after a complete expression (missing operator?)"},
      {"u,v", K::kTrailing, 2, "unexpected ',' after a complete expression (',' only separates function arguments)"},
  });
}

TEST(ExprErrors, MissingOperatorInsideParentheses) {
  check({
      {"(u v)", K::kMissingOperator, 4, "expected ')' or an operator before name 'v' (inside the '(' at column 1)"},
      {"atan2(u v)", K::kMissingOperator, 9,
       "expected ',' or ')' or an operator before name 'v' (inside the '(' at column 6)"},
  });
}

TEST(ExprErrors, BadNumberLiterals) {
  check({
      {"1.2.3", K::kBadNumber, 1, "bad number literal '1.2.3'"},
      {"u+1..2", K::kBadNumber, 3, "bad number literal '1..2'"},
      {"1e", K::kBadNumber, 1, "bad number literal '1e': the exponent has no digits (write 1*e for a product)"},
      {"1E", K::kBadNumber, 1, "bad number literal '1E': the exponent has no digits"},
      {"u*1e+", K::kBadNumber, 3, "bad number literal '1e+': the exponent has no digits"},
      {"1e-x", K::kBadNumber, 1, "bad number literal '1e-': the exponent has no digits"},
      {"2u", K::kBadNumber, 1, "bad number literal '2u' (write 2*u for a product)"},
      {"3*2pi", K::kBadNumber, 3, "bad number literal '2pi' (write 2*pi for a product)"},
      {"1e5x", K::kBadNumber, 1, "bad number literal '1e5x' (write 1e5*x for a product)"},
      {"1e999", K::kBadNumber, 1, "number literal '1e999' is out of the range of a double"},
      {".", K::kBadNumber, 1, "bad number literal '.': no digits"},
      {"u+.", K::kBadNumber, 3, "bad number literal '.': no digits"},
  });
}

TEST(ExprErrors, MissingOperand) {
  check({
      {"u+", K::kMissingOperand, 3, "missing operand after '+'"},
      {"-", K::kMissingOperand, 2, "missing operand after '-'"},
      {"u^", K::kMissingOperand, 3, "missing operand after '^'"},
      {"*u", K::kMissingOperand, 1, "missing operand before '*'"},
      {"^2", K::kMissingOperand, 1, "missing operand before '^'"},
      {"u+*v", K::kMissingOperand, 3, "missing operand between '+' and '*'"},
      {"u**2", K::kMissingOperand, 3, "missing operand between '*' and '*' (write ^ for powers)"},
      {"2^^3", K::kMissingOperand, 3, "missing operand between '^' and '^'"},
      {"()", K::kMissingOperand, 2, "missing operand: empty parentheses"},
      {"u*( )", K::kMissingOperand, 5, "missing operand: empty parentheses"},
      {"sin(u,)", K::kMissingOperand, 7, "missing operand between ',' and ')'"},
      {"atan2(,u)", K::kMissingOperand, 7, "missing operand between '(' and ','"},
      {"(u+)", K::kMissingOperand, 4, "missing operand between '+' and ')'"},
  });
}

TEST(ExprErrors, UnexpectedCharacters) {
  check({
      {"u # v", K::kUnexpectedCharacter, 3, "unexpected character '#'"},
      {"u = v", K::kUnexpectedCharacter, 3, "unexpected character '='"},
      {"[u]", K::kUnexpectedCharacter, 1, "unexpected character '[' (only round parentheses group)"},
      {"u+π", K::kUnexpectedCharacter, 3, "unexpected character 'π' (U+03C0) (write pi)"},
      {"u−v", K::kUnexpectedCharacter, 2, "unexpected character '−' (U+2212) (use the ASCII '-')"},
      {"u×v", K::kUnexpectedCharacter, 2, "unexpected character '×' (U+00D7) (use '*')"},
      {"u²", K::kUnexpectedCharacter, 2, "unexpected character '²' (U+00B2) (write ^2)"},
      {"é", K::kUnexpectedCharacter, 1, "unexpected character 'é' (U+00E9)"},
      {"u\x01", K::kUnexpectedCharacter, 2, "unexpected character '\\x01' (a control character)"},
      {std::string("u+\0", 3), K::kUnexpectedCharacter, 3, "unexpected character '\\x00' (a control character)"},
      {"u\xff", K::kUnexpectedCharacter, 2, "unexpected character byte 0xFF (not valid UTF-8)"},
      {"u+\xc3", K::kUnexpectedCharacter, 3, "unexpected character byte 0xC3 (not valid UTF-8)"},
  });
}

TEST(ExprErrors, NonFiniteConstants) {
  check({
      {"1/0 + u", K::kNotFinite, 1, "this constant subexpression is not finite (inf)"},
      {"u * log(-1)", K::kNotFinite, 5, "this constant subexpression is not finite (nan)"},
      {"u + 10^400", K::kNotFinite, 5, "this constant subexpression is not finite (inf)"},
  });
  ParseError e = error_of("2*R", {{"R", std::numeric_limits<double>::infinity()}});
  EXPECT_EQ(e.kind, K::kNotFinite);
  EXPECT_EQ(e.column, 3);
  EXPECT_EQ(e.message, "constant 'R' is not finite (inf)");
}

TEST(ExprErrors, NestingLimitInsteadOfStackOverflow) {
  const std::string deep = std::string(100000, '(') + "u" + std::string(100000, ')');
  ParseError e = error_of(deep);
  EXPECT_EQ(e.kind, K::kTooDeep);
  EXPECT_EQ(e.column, Program::kMaxNesting + 1);  // the first '(' beyond the limit
  EXPECT_EQ(e.message, "expression nested too deeply (more than 100 levels of parentheses, function calls and '^')");
  std::string calls;
  for (int i = 0; i < 50000; ++i) calls += "sin(";
  EXPECT_EQ(error_of(calls + "u").kind, K::kTooDeep);
  std::string tower = "u";
  for (int i = 0; i < 50000; ++i) tower += "^u";
  EXPECT_EQ(error_of(tower).kind, K::kTooDeep);
  // Just inside the limit compiles and evaluates.
  const int ok_depth = Program::kMaxNesting - 1;  // the whole expression is one level
  Program p = Program::compile_or_throw(std::string(ok_depth, '(') + "u+1" + std::string(ok_depth, ')'), kUV, {});
  EXPECT_EQ(p.eval({1.0, 0.0}), 2.0);
}

// The documented bound: the deepest accepted expressions compile on a thread with 256 KiB of stack.
TEST(ExprErrors, DeepestAcceptedExpressionsFitInASmallStack) {
  struct Job {
    static void* run(void* arg) {
      auto* ok = static_cast<bool*>(arg);
      const int depth = Program::kMaxNesting - 1;
      std::string parens = std::string(depth, '(') + "u" + std::string(depth, ')');
      std::string calls;
      for (int i = 0; i < depth; ++i) calls += "atan2(1, ";
      calls += "u" + std::string(depth, ')');
      std::string too_deep = "(" + parens + ")";
      Program p;
      ParseError e;
      *ok = Program::compile(parens, kUV, {}, &p, &e) && Program::compile(calls, kUV, {}, &p, &e) &&
            !Program::compile(too_deep, kUV, {}, &p, &e) && e.kind == ParseErrorKind::kTooDeep;
      return nullptr;
    }
  };
  pthread_attr_t attr;
  ASSERT_EQ(pthread_attr_init(&attr), 0);
  ASSERT_EQ(pthread_attr_setstacksize(&attr, 256 * 1024), 0);
  bool ok = false;
  pthread_t thread;
  ASSERT_EQ(pthread_create(&thread, &attr, &Job::run, &ok), 0);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  pthread_attr_destroy(&attr);
  EXPECT_TRUE(ok);
}

TEST(ExprErrors, InvalidVariableLists) {
  ParseError e = error_of("u", {}, {"u", "x y"});
  EXPECT_EQ(e.kind, K::kBadVariable);
  EXPECT_EQ(e.message, "invalid variable name 'x y' (not an identifier)");
  e = error_of("u", {}, {"u", "u"});
  EXPECT_EQ(e.kind, K::kBadVariable);
  EXPECT_EQ(e.message, "variable 'u' is listed twice");
  EXPECT_EQ(error_of("u", {}, {""}).kind, K::kBadVariable);
}

TEST(ExprErrors, TheLeftmostProblemIsReported) {
  ParseError e = error_of("sinn(u) + # + (");
  EXPECT_EQ(e.kind, K::kUnknownFunction);
  e = error_of("u + # + sinn(u)");
  EXPECT_EQ(e.kind, K::kUnexpectedCharacter);
}

TEST(ExprErrorFormat, CaretLineUnderTheColumn) {
  ParseError e = error_of("u + sinn(v)");
  EXPECT_EQ(e.format("u + sinn(v)", "surfaces.s.parametric[0]"),
            "surfaces.s.parametric[0]: column 5: unknown function 'sinn'; did you mean 'sin'?\n"
            "  u + sinn(v)\n"
            "      ^");
  EXPECT_EQ(e.format("u + sinn(v)"),
            "column 5: unknown function 'sinn'; did you mean 'sin'?\n"
            "  u + sinn(v)\n"
            "      ^");
}

TEST(ExprErrorFormat, ColumnsCountCharactersNotBytes) {
  // 'é' is two bytes and one column; the caret must sit under the error, not one further.
  const std::string s = "u\t+ \xc3\xa9";
  ParseError e = error_of(s);
  EXPECT_EQ(e.offset, 4u);
  EXPECT_EQ(e.column, 5);
  EXPECT_EQ(e.format(s), "column 5: unexpected character 'é' (U+00E9)\n  u + é\n      ^");
  EXPECT_EQ(display_column("a\xc3\xa9 b", 4), 4);
  EXPECT_EQ(display_column("a\xc3\xa9 b", 1), 2);
  EXPECT_EQ(display_column("ab", 2), 3);
  EXPECT_EQ(display_column("", 0), 1);
  // Control characters and invalid bytes are echoed as one '?' each.
  const std::string t = std::string("\x01\xff+", 3);
  ParseError f = error_of(t);
  EXPECT_EQ(f.format(t), "column 1: unexpected character '\\x01' (a control character)\n  ??+\n  ^");
}

TEST(ExprErrorFormat, CompileOrThrowCarriesWhereAndCaret) {
  try {
    (void)Program::compile_or_throw("(4+cos(4*u)*cos(u)", kUV, {}, "surfaces.torus.parametric[0]");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "surfaces.torus.parametric[0]");
    EXPECT_EQ(std::string(e.what()),
              "surfaces.torus.parametric[0]: column 1: unmatched '(' (missing ')')\n"
              "  (4+cos(4*u)*cos(u)\n"
              "  ^");
    EXPECT_EQ(e.message(), "column 1: unmatched '(' (missing ')')\n  (4+cos(4*u)*cos(u)\n  ^");
  }
}

}  // namespace
}  // namespace ssimarch
