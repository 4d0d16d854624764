// Compiled arithmetic expressions ("(4+cos(4*u))*cos(u)", "x^2+y^2-x"), evaluated generically on
// double, Jet<NV,K> and any number type with the same operations (grammar: docs/expressions.md).
//
// compile() parses by recursive descent into a hash-consed DAG (common subexpressions shared,
// constant subexpressions folded, constant operands turned into immediates so 4*u is a scalar
// product and not a jet product), then emits it in topological order as a register program
// (SSA values mapped onto a few reusable registers by a linear scan over last uses). eval() is one
// pass over that flat list with no recursion and, for double and small jets, no heap allocation.
//
// Number type requirements for eval<T>: T(double), copy, unary -, T op T and T op double and
// double op T for + - * /, and found by ADL or in std: sqrt cbrt exp log sin cos tan asin acos
// atan sinh cosh tanh abs atan2(T,T) pow(T,int) pow(T,double) pow(T,T).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "ssimarch/core/contract.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/expr/parse_error.hpp"

namespace ssimarch {

namespace internal {
class Compiler;
}  // namespace internal

/// Named constants supplied by the caller (a scene's "constants"); `pi` and `e` are built in.
using Constants = std::map<std::string, double, std::less<>>;

/// Instruction codes of a Program. Suffix C: the second operand is the immediate `imm`.
enum class OpCode : std::uint8_t {
  kConst,    // r[dst] = imm
  kVar,      // r[dst] = vars[a]
  kNeg,      // -r[a]
  kAdd, kSub, kMul, kDiv, kPow, kAtan2,  // r[a] op r[b]
  kAddC,     // r[a] + imm
  kSubC,     // r[a] - imm
  kRSubC,    // imm - r[a]
  kMulC,     // r[a] * imm
  kDivC,     // r[a] / imm
  kRDivC,    // imm / r[a]
  kPowInt,   // r[a]^b, b an integer exponent (exact at r[a] = 0 on jets)
  kPowReal,  // r[a]^imm, imm not an integer
  kSqrt, kCbrt, kExp, kLog, kSin, kCos, kTan, kAsin, kAcos, kAtan, kSinh, kCosh, kTanh, kAbs,
};

struct Instruction {
  OpCode op;
  std::int32_t dst = 0;
  std::int32_t a = 0;  // register (or variable index for kVar)
  std::int32_t b = 0;  // register, or the exponent of kPowInt
  double imm = 0.0;
};

/// a^n by binary powering: the same sequence of products as pow(Jet, int) in core/jet.hpp, so a
/// double evaluation equals the value part of a jet evaluation bit for bit.
inline double integer_power(double x, std::int32_t n) {
  switch (n) {  // the common small cases, unrolled (same products as the loop below)
    case 0: return 1.0;
    case 1: return x;
    case 2: return x * x;
    case 3: return x * (x * x);
    case 4: return (x * x) * (x * x);
    default: break;
  }
  if (n < 0) return 1.0 / integer_power(x, -n);
  double result = 1.0, base = x;
  while (n > 0) {
    if (n & 1) result = result * base;
    n >>= 1;
    if (n > 0) base = base * base;
  }
  return result;
}

class Program {
 public:
  /// Nesting limit (parentheses, function calls, chained '^'; the top level counts as one):
  /// deeper input is a ParseError (kTooDeep) rather than a stack overflow of the recursive-descent
  /// parser, which needs up to about 1.3 KiB of stack per level (so at most ~130 KiB).
  static constexpr int kMaxNesting = 100;
  /// Integer exponents up to this size use the exact integer-power path; larger ones pow(x, real).
  static constexpr std::int32_t kMaxIntegerExponent = 1 << 20;

  Program() = default;

  /// Compile `source` with the given variable names (their order = the order of eval's inputs).
  /// Returns false and fills *error (if not null) on bad input; *out is then left unchanged.
  /// Names resolve as: variables, then `constants`, then the built-ins pi and e.
  static bool compile(std::string_view source, std::span<const std::string> variables, const Constants& constants,
                      Program* out, ParseError* error);
  /// As compile(), but throws ssimarch::InputError(where, "column N: message\n  source\n  ^").
  static Program compile_or_throw(std::string_view source, std::span<const std::string> variables,
                                  const Constants& constants, std::string where = {});
  static Program compile_or_throw(std::string_view source, std::initializer_list<std::string> variables,
                                  const Constants& constants = {}, std::string where = {}) {
    std::vector<std::string> v(variables);
    return compile_or_throw(source, std::span<const std::string>(v), constants, std::move(where));
  }

  /// Value of the expression at `vars` (at least num_variables() of them; throws
  /// std::out_of_range otherwise).
  template <class T>
  T eval(std::span<const T> vars) const {
    if (vars.size() < variables_.size()) throw std::out_of_range("ssimarch::Program::eval: too few variables");
    return eval(vars.data());
  }
  template <class T>
  T eval(std::initializer_list<T> vars) const {
    return eval(std::span<const T>(vars.begin(), vars.size()));
  }
  template <class T, std::size_t N>
  T eval(const std::array<T, N>& vars) const {
    return eval(std::span<const T>(vars.data(), N));
  }
  /// Unchecked: `vars` must point at num_variables() values.
  template <class T>
  T eval(const T* vars) const;

  int num_variables() const { return static_cast<int>(variables_.size()); }
  const std::vector<std::string>& variables() const { return variables_; }
  const std::string& source() const { return source_; }
  /// Whether the compiled expression depends on variable i (false for u in "v^2 + 0*1").
  bool uses_variable(int i) const {
    return i >= 0 && i < static_cast<int>(uses_.size()) && uses_[static_cast<std::size_t>(i)];
  }
  /// True when the expression uses no variable at all (then constant_value() is its value).
  bool is_constant() const { return code_.size() == 1 && code_[0].op == OpCode::kConst; }
  double constant_value() const {
    SSIMARCH_EXPECTS(is_constant(), "ssimarch::Program::constant_value: not a constant");
    return code_[0].imm;
  }

  // Introspection (tests, benchmarks, debugging).
  const std::vector<Instruction>& code() const { return code_; }
  int num_registers() const { return num_registers_; }
  std::string disassemble() const;

 private:
  friend class internal::Compiler;
  template <class T>
  void run(T* r, const T* vars) const;

  std::string source_;
  std::vector<std::string> variables_;
  std::vector<bool> uses_;
  std::vector<Instruction> code_;
  int num_registers_ = 0;
  int result_ = 0;
};

/// Value of a constant expression (no variables), e.g. a scene's "2*pi" or "R/2".
/// Throws ssimarch::InputError(where, ...) when it does not compile or is not finite.
double evaluate_constant(std::string_view source, const Constants& constants, std::string where = {});

// ------------------------------------------------------------------------------------------------

/// The result of one instruction, reading registers `r` and inputs `vars` (the evaluator and
/// the compiler's constant folding share it, so folded and evaluated values agree exactly).
#if defined(__GNUC__)
#define SSIMARCH_EXPR_ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define SSIMARCH_EXPR_ALWAYS_INLINE inline
#endif

template <class T>
SSIMARCH_EXPR_ALWAYS_INLINE T apply_instruction(const Instruction& in, const T* r, const T* vars) {
  using std::abs, std::acos, std::asin, std::atan, std::atan2, std::cbrt, std::cos, std::cosh, std::exp,
      std::log, std::pow, std::sin, std::sinh, std::sqrt, std::tan, std::tanh;
  switch (in.op) {
    case OpCode::kConst: return T(in.imm);
    case OpCode::kVar: return vars[in.a];
    case OpCode::kNeg: return -r[in.a];
    case OpCode::kAdd: return r[in.a] + r[in.b];
    case OpCode::kSub: return r[in.a] - r[in.b];
    case OpCode::kMul: return r[in.a] * r[in.b];
    case OpCode::kDiv: return r[in.a] / r[in.b];
    case OpCode::kPow: return pow(r[in.a], r[in.b]);
    case OpCode::kAtan2: return atan2(r[in.a], r[in.b]);
    case OpCode::kAddC: return r[in.a] + in.imm;
    case OpCode::kSubC: return r[in.a] - in.imm;
    case OpCode::kRSubC: return in.imm - r[in.a];
    case OpCode::kMulC: return r[in.a] * in.imm;
    case OpCode::kDivC: return r[in.a] / in.imm;
    case OpCode::kRDivC: return in.imm / r[in.a];
    case OpCode::kPowInt:
      if constexpr (std::is_same_v<T, double>)
        return integer_power(r[in.a], in.b);
      else
        return pow(r[in.a], static_cast<int>(in.b));
    case OpCode::kPowReal: return pow(r[in.a], in.imm);
    case OpCode::kSqrt: return sqrt(r[in.a]);
    case OpCode::kCbrt: return cbrt(r[in.a]);
    case OpCode::kExp: return exp(r[in.a]);
    case OpCode::kLog: return log(r[in.a]);
    case OpCode::kSin: return sin(r[in.a]);
    case OpCode::kCos: return cos(r[in.a]);
    case OpCode::kTan: return tan(r[in.a]);
    case OpCode::kAsin: return asin(r[in.a]);
    case OpCode::kAcos: return acos(r[in.a]);
    case OpCode::kAtan: return atan(r[in.a]);
    case OpCode::kSinh: return sinh(r[in.a]);
    case OpCode::kCosh: return cosh(r[in.a]);
    case OpCode::kTanh: return tanh(r[in.a]);
    case OpCode::kAbs: return abs(r[in.a]);
  }
  return T(std::nan(""));  // unreachable: every OpCode is handled above
}

template <class T>
void Program::run(T* r, const T* vars) const {
  // The right side is computed into a temporary before the store, so dst may equal an operand.
  for (const Instruction& in : code_) r[in.dst] = apply_instruction(in, r, vars);
}

template <class T>
T Program::eval(const T* vars) const {
  // Registers live in a stack buffer of at most 64 values and about 32 KiB (but at least 16
  // values): 64 doubles or Jet<2,3>, 24 Jet<3,8>. Only programs needing more registers (many
  // long-lived shared subexpressions) fall back to the heap.
  constexpr std::size_t kInlineBytes = 32768;
  constexpr std::size_t kInline = std::clamp<std::size_t>(kInlineBytes / sizeof(T), 16, 64);
  const auto n = static_cast<std::size_t>(num_registers_);
  if (n == 0) return T(0.0);  // a default-constructed Program
  if (n <= kInline) {
    alignas(T) unsigned char storage[kInline * sizeof(T)];
    // Default-initialisation: no work for double, a zero fill of only the registers in use for jets.
    std::uninitialized_default_construct_n(reinterpret_cast<T*>(storage), n);
    T* r = std::launder(reinterpret_cast<T*>(storage));
    if constexpr (std::is_nothrow_destructible_v<T> && !std::is_trivially_destructible_v<T>) {
      struct Guard {
        T* r;
        std::size_t n;
        ~Guard() { std::destroy_n(r, n); }
      } guard{r, n};
      run(r, vars);
      return r[result_];
    } else {
      run(r, vars);
      return r[result_];
    }
  }
  std::vector<T> r(n);
  run(r.data(), vars);
  return r[static_cast<std::size_t>(result_)];
}

}  // namespace ssimarch

#undef SSIMARCH_EXPR_ALWAYS_INLINE
