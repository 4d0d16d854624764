// Randomized tests of the parser: (1) mangled expressions and random bytes must compile or give a
// ParseError inside the source, never crash; (2) randomly generated well-formed expressions,
// printed with the fewest parentheses the precedence rules allow, must evaluate to the value of
// the tree they were printed from (an independent check of precedence and associativity).
//
// The seed is logged; rerun one with SSIMARCH_FUZZ_SEED=<seed>. SSIMARCH_FUZZ_SCALE=<n>
// multiplies the number of cases (default 1).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/expr/program.hpp"

namespace ssimarch {
namespace {

const std::vector<std::string> kUV = {"u", "v"};
const Constants kConstants = {{"R", 1.75}, {"r_2", 0.5}};
constexpr double kU = 0.7, kV = -0.3;

std::uint64_t fuzz_seed() {
  if (const char* s = std::getenv("SSIMARCH_FUZZ_SEED")) return std::strtoull(s, nullptr, 10);
  return 20240611;
}
int fuzz_scale() {
  if (const char* s = std::getenv("SSIMARCH_FUZZ_SCALE")) return std::max(1, std::atoi(s));
  return 1;
}

const std::vector<std::string> kValid = {
    "(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)",
    "(4+cos(4*u))*sin(u) + v*(cos(4*u)+sin(4*u))*sin(u)",
    "sin(4*u) + v*(sin(4*u)-cos(4*u))",
    "u^2+v^2-u",
    "R*cos(u)*sin(v) - r_2",
    "sqrt(u^2 + v^2) - 2",
    "atan2(v, u) + pow(u, 2.5e-1) * exp(-v^2/2)",
    "-u^-2 + 1e-3*abs(v) - .5/cbrt(u)",
    "log(cosh(u)) + ln(2) * tanh(v) - asin(v/2) + acos(u/2) + atan(u*v)",
    "2*pi*R - e^u + tan(v)*sinh(u)",
};

const std::vector<std::string> kVocabulary = {
    "(",    ")",     ",",     "+",     "-",     "*",      "/",     "^",       "**",  "u",   "v",  "R",
    "pi",   "e",     "sin",   "atan2", "pow",   "sqrt(",  "exp",   "1",       "0",   ".5",  "1e", "1e-3",
    "2.",   "1.2.3", "1e308", "-0",    "#",     "\xcf\x80", " ",   "\t",      "((((", "))))", "2u", "x",
    "sinn", "()",    "(,)",   "$",     "[",     "\xff",   std::string(1, '\0'), "\xc3", "^-", "e^",
};

// Splits an expression into tokens for token-level mutation (names, numbers, single characters).
std::vector<std::string> tokens_of(const std::string& s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t j = i + 1;
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; };
    if (word(s[i]))
      while (j < s.size() && word(s[j])) ++j;
    out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

struct Outcome {
  long compiled = 0;
  long rejected = 0;
};

// Compiles `s`; on success evaluates on double and on a jet (the results may be NaN); on failure
// checks the error is inside the source and formats. Returns false on a violated property.
bool exercise(const std::string& s, Outcome* outcome) {
  Program p;
  ParseError e;
  if (Program::compile(s, kUV, kConstants, &p, &e)) {
    ++outcome->compiled;
    volatile double d = p.eval({kU, kV});
    Jet<2, 2> j = p.eval({Jet<2, 2>::variable(0, kU), Jet<2, 2>::variable(1, kV)});
    (void)d;
    (void)j;
    return p.num_registers() >= 1 && !p.code().empty();
  }
  ++outcome->rejected;
  if (e.offset > s.size() || e.column < 1 || e.message.empty()) return false;
  std::string text = e.format(s, "fuzz");
  return text.find('^') != std::string::npos && text.rfind("fuzz: column ", 0) == 0;
}

std::string escaped(const std::string& s) {
  std::string r;
  for (unsigned char c : s) {
    if (c >= 0x20 && c < 0x7F && c != '\\') {
      r += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      r += buf;
    }
  }
  return r;
}

TEST(ExprFuzz, MangledExpressionsNeverCrash) {
  const std::uint64_t seed = fuzz_seed();
  std::cout << "[ fuzz seed ] " << seed << " (rerun with SSIMARCH_FUZZ_SEED=" << seed << ")\n";
  RecordProperty("fuzz_seed", std::to_string(seed));
  std::mt19937_64 rng(seed);
  auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  const auto start = std::chrono::steady_clock::now();
  Outcome outcome;
  long failures = 0;
  auto run = [&](const std::string& s) {
    if (!exercise(s, &outcome) && failures++ < 10) ADD_FAILURE() << "seed " << seed << ": input \"" << escaped(s) << "\"";
  };
  const int scale = fuzz_scale();

  // Token-level mutations of valid expressions: deletions, insertions, swaps, replacements, duplications.
  for (int n = 0; n < 20000 * scale; ++n) {
    std::vector<std::string> t = tokens_of(kValid[pick(kValid.size())]);
    const int edits = 1 + static_cast<int>(pick(4));
    for (int k = 0; k < edits; ++k) {
      switch (pick(5)) {
        case 0:
          if (!t.empty()) t.erase(t.begin() + static_cast<std::ptrdiff_t>(pick(t.size())));
          break;
        case 1: t.insert(t.begin() + static_cast<std::ptrdiff_t>(pick(t.size() + 1)), kVocabulary[pick(kVocabulary.size())]); break;
        case 2:
          if (!t.empty()) std::swap(t[pick(t.size())], t[pick(t.size())]);
          break;
        case 3:
          if (!t.empty()) t[pick(t.size())] = kVocabulary[pick(kVocabulary.size())];
          break;
        case 4:
          if (!t.empty()) {
            std::size_t a = pick(t.size()), b = a + pick(t.size() - a);
            std::vector<std::string> piece(t.begin() + static_cast<std::ptrdiff_t>(a), t.begin() + static_cast<std::ptrdiff_t>(b) + 1);
            t.insert(t.begin() + static_cast<std::ptrdiff_t>(pick(t.size() + 1)), piece.begin(), piece.end());
          }
          break;
      }
    }
    std::string s;
    for (const auto& x : t) s += x;
    run(s);
  }
  // Byte-level mutations: any byte value, NUL and non-ASCII included.
  for (int n = 0; n < 10000 * scale; ++n) {
    std::string s = kValid[pick(kValid.size())];
    const int edits = 1 + static_cast<int>(pick(6));
    for (int k = 0; k < edits; ++k) {
      const char byte = static_cast<char>(rng() & 0xFF);
      switch (pick(3)) {
        case 0:
          if (!s.empty()) s.erase(pick(s.size()), 1);
          break;
        case 1: s.insert(s.begin() + static_cast<std::ptrdiff_t>(pick(s.size() + 1)), byte); break;
        case 2:
          if (!s.empty()) s[pick(s.size())] = byte;
          break;
      }
    }
    run(s);
  }
  // Random strings over the language's own characters (most are nonsense, some are valid).
  const std::string alphabet = "uvReipsnco0123456789.+-*/^(),  \t";
  for (int n = 0; n < 10000 * scale; ++n) {
    std::string s(pick(24), ' ');
    for (char& c : s) c = alphabet[pick(alphabet.size())];
    run(s);
  }
  // Random bytes.
  for (int n = 0; n < 5000 * scale; ++n) {
    std::string s(pick(32), ' ');
    for (char& c : s) c = static_cast<char>(rng() & 0xFF);
    run(s);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long total = outcome.compiled + outcome.rejected;
  std::cout << "[ fuzz ] " << total << " inputs: " << outcome.compiled << " compiled and evaluated, "
            << outcome.rejected << " rejected with an error, in " << seconds << " s\n";
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(total, 45000L * scale);
  // Both outcomes occur in quantity, so neither path goes untested.
  EXPECT_GT(outcome.compiled, 1000L * scale);
  EXPECT_GT(outcome.rejected, total / 2);
}

// --- generated well-formed expressions with their value -------------------------------------------

struct Gen {
  std::string text;
  int prec;        // 1 sum, 2 product, 3 signed, 4 power, 5 primary
  double value;
  bool has_var;
  bool non_finite_constant;  // some variable-free subexpression is inf/NaN: must be rejected
};

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  Gen expression(int depth) {
    if (depth == 0 || pick(4) == 0) return leaf();
    switch (pick(6)) {
      case 0: return negate(expression(depth - 1));
      case 1: return binary(expression(depth - 1), expression(depth - 1));
      case 2: return binary(expression(depth - 1), expression(depth - 1));
      case 3: return call(depth);
      case 4: return paren(expression(depth - 1));
      default: return binary(expression(depth - 1), expression(depth - 1));
    }
  }

 private:
  std::size_t pick(std::size_t n) { return static_cast<std::size_t>(rng_() % n); }
  std::string blank() { return pick(3) == 0 ? " " : ""; }

  static Gen finish(Gen g, std::initializer_list<const Gen*> children) {
    for (const Gen* c : children) {
      g.has_var = g.has_var || c->has_var;
      g.non_finite_constant = g.non_finite_constant || c->non_finite_constant;
    }
    if (!g.has_var && !std::isfinite(g.value)) g.non_finite_constant = true;
    return g;
  }

  Gen leaf() {
    struct Lit {
      const char* text;
      double value;
      bool var;
    };
    static const Lit kLeaves[] = {{"0", 0.0, false},    {"1", 1.0, false},     {"2", 2.0, false},
                                  {"3", 3.0, false},    {"0.5", 0.5, false},   {".25", 0.25, false},
                                  {"1e-3", 1e-3, false}, {"2.5E1", 25.0, false}, {"10", 10.0, false},
                                  {"pi", std::numbers::pi, false}, {"e", std::numbers::e, false},
                                  {"R", 1.75, false},   {"r_2", 0.5, false},   {"u", kU, true},
                                  {"v", kV, true},      {"u", kU, true},       {"v", kV, true}};
    const Lit& l = kLeaves[pick(std::size(kLeaves))];
    return {l.text, 5, l.value, l.var, false};
  }

  static std::string wrap(const Gen& g, int min_prec) {
    return g.prec >= min_prec ? g.text : std::string("(").append(g.text).append(")");
  }

  Gen paren(const Gen& a) { return finish({std::string("(") + blank() + a.text + blank() + ")", 5, a.value, false, false}, {&a}); }

  Gen negate(const Gen& a) {
    return finish({std::string("-") + blank() + wrap(a, 3), 3, -a.value, false, false}, {&a});
  }

  static double power(const Gen& a, const Gen& b) {
    // The program's rule: a variable-free exponent with an integer value takes integer_power.
    if (!b.has_var && std::trunc(b.value) == b.value && std::fabs(b.value) <= Program::kMaxIntegerExponent)
      return integer_power(a.value, static_cast<std::int32_t>(b.value));
    return std::pow(a.value, b.value);
  }

  Gen binary(const Gen& a, const Gen& b) {
    const std::string sp = blank();
    switch (pick(5)) {
      case 0: return finish({wrap(a, 1) + sp + "+" + sp + wrap(b, 2), 1, a.value + b.value, false, false}, {&a, &b});
      case 1: return finish({wrap(a, 1) + sp + "-" + sp + wrap(b, 2), 1, a.value - b.value, false, false}, {&a, &b});
      case 2: return finish({wrap(a, 2) + sp + "*" + sp + wrap(b, 3), 2, a.value * b.value, false, false}, {&a, &b});
      case 3: return finish({wrap(a, 2) + sp + "/" + sp + wrap(b, 3), 2, a.value / b.value, false, false}, {&a, &b});
      default: return finish({wrap(a, 5) + sp + "^" + sp + wrap(b, 3), 4, power(a, b), false, false}, {&a, &b});
    }
  }

  Gen call(int depth) {
    using F = double (*)(double);
    struct Unary {
      const char* name;
      F f;
    };
    static const Unary kUnary[] = {
        {"sqrt", [](double x) { return std::sqrt(x); }}, {"cbrt", [](double x) { return std::cbrt(x); }},
        {"exp", [](double x) { return std::exp(x); }},   {"log", [](double x) { return std::log(x); }},
        {"ln", [](double x) { return std::log(x); }},    {"sin", [](double x) { return std::sin(x); }},
        {"cos", [](double x) { return std::cos(x); }},   {"tan", [](double x) { return std::tan(x); }},
        {"asin", [](double x) { return std::asin(x); }}, {"acos", [](double x) { return std::acos(x); }},
        {"atan", [](double x) { return std::atan(x); }}, {"sinh", [](double x) { return std::sinh(x); }},
        {"cosh", [](double x) { return std::cosh(x); }}, {"tanh", [](double x) { return std::tanh(x); }},
        {"abs", [](double x) { return std::fabs(x); }},
    };
    const std::size_t k = pick(std::size(kUnary) + 2);
    if (k < std::size(kUnary)) {
      Gen a = expression(depth - 1);
      return finish({std::string(kUnary[k].name) + "(" + blank() + a.text + ")", 5, kUnary[k].f(a.value), false, false},
                    {&a});
    }
    Gen a = expression(depth - 1), b = expression(depth - 1);
    if (k == std::size(kUnary))
      return finish({"atan2(" + a.text + "," + blank() + b.text + ")", 5, std::atan2(a.value, b.value), false, false},
                    {&a, &b});
    return finish({"pow(" + a.text + ", " + b.text + ")", 5, power(a, b), false, false}, {&a, &b});
  }

  std::mt19937_64 rng_;
};

TEST(ExprFuzz, GeneratedExpressionsEvaluateToTheirTreeValue) {
  const std::uint64_t seed = fuzz_seed() + 1;
  std::cout << "[ fuzz seed ] " << seed << " (generator)\n";
  Generator gen(seed);
  long checked = 0, rejected_non_finite = 0, failures = 0;
  for (int n = 0; n < 10000 * fuzz_scale(); ++n) {
    Gen g = gen.expression(1 + n % 6);
    Program p;
    ParseError e;
    const bool ok = Program::compile(g.text, kUV, kConstants, &p, &e);
    if (g.non_finite_constant) {
      ++rejected_non_finite;
      if ((ok || e.kind != ParseErrorKind::kNotFinite) && failures++ < 10)
        ADD_FAILURE() << g.text << ": expected a non-finite-constant error, got "
                      << (ok ? std::string("success") : e.format(g.text));
      continue;
    }
    if (!ok) {
      if (failures++ < 10) ADD_FAILURE() << e.format(g.text);
      continue;
    }
    ++checked;
    const double got = p.eval({kU, kV});
    const bool same = std::isnan(g.value) ? std::isnan(got) : got == g.value;
    if (!same && failures++ < 10) ADD_FAILURE() << g.text << " = " << got << ", tree value " << g.value;
  }
  std::cout << "[ fuzz ] " << checked << " generated expressions matched their tree value, " << rejected_non_finite
            << " correctly rejected as non-finite constants\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(checked, 5000 * fuzz_scale());
}

}  // namespace
}  // namespace ssimarch
