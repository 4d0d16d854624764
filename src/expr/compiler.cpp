// Recursive-descent parser (grammar in docs/expressions.md) building a hash-consed expression DAG
// with constant folding, then register allocation by a linear scan over last uses.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "lexer.hpp"
#include "ssimarch/expr/program.hpp"

// Error paths build long messages in std::string temporaries; keeping them out of line keeps the
// frames of the recursive parse functions small (at most about 1.3 KiB per nesting level, see
// Program::kMaxNesting).
#if defined(__GNUC__)
#define SSIMARCH_COLD [[gnu::noinline, gnu::cold]]
#else
#define SSIMARCH_COLD
#endif

namespace ssimarch::internal {

namespace {

struct FunctionInfo {
  const char* name;
  int arity;
  OpCode op;
  const char* signature;
};

// pow(a, b) is a^b; ln is log.
constexpr std::array<FunctionInfo, 17> kFunctions{{
    {"abs", 1, OpCode::kAbs, "abs(x)"},       {"acos", 1, OpCode::kAcos, "acos(x)"},
    {"asin", 1, OpCode::kAsin, "asin(x)"},    {"atan", 1, OpCode::kAtan, "atan(x)"},
    {"atan2", 2, OpCode::kAtan2, "atan2(y, x)"}, {"cbrt", 1, OpCode::kCbrt, "cbrt(x)"},
    {"cos", 1, OpCode::kCos, "cos(x)"},       {"cosh", 1, OpCode::kCosh, "cosh(x)"},
    {"exp", 1, OpCode::kExp, "exp(x)"},       {"ln", 1, OpCode::kLog, "ln(x)"},
    {"log", 1, OpCode::kLog, "log(x)"},       {"pow", 2, OpCode::kPow, "pow(a, b)"},
    {"sin", 1, OpCode::kSin, "sin(x)"},       {"sinh", 1, OpCode::kSinh, "sinh(x)"},
    {"sqrt", 1, OpCode::kSqrt, "sqrt(x)"},    {"tan", 1, OpCode::kTan, "tan(x)"},
    {"tanh", 1, OpCode::kTanh, "tanh(x)"},
}};

const FunctionInfo* find_function(std::string_view name) {
  for (const auto& f : kFunctions)
    if (name == f.name) return &f;
  return nullptr;
}

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return r;
}

// Optimal string alignment distance (Levenshtein plus adjacent transpositions), case-blind.
int edit_distance(std::string_view a0, std::string_view b0) {
  std::string a = lower(a0), b = lower(b0);
  const std::size_t n = a.size(), m = b.size();
  if (n > 64 || m > 64) return 1 << 20;
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

// The closest candidate if it is close enough to be a plausible typo (case-only differences
// always are; otherwise at most max(1, |name|/2) edits, and never for one-letter names).
std::optional<std::string> nearest(std::string_view name, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  int best_d = 1 << 20;
  for (const auto& c : candidates) {
    int dist = edit_distance(name, c);
    if (dist < best_d) best_d = dist, best = c;
  }
  if (!best) return best;
  if (best_d == 0) return best;
  if (name.size() < 2 || best->size() < 2) return std::nullopt;
  int limit = std::max(1, static_cast<int>(name.size()) / 2);
  if (best_d > limit) return std::nullopt;
  return best;
}

std::string join(const std::vector<std::string>& v, std::size_t max_items = 24) {
  std::string r;
  for (std::size_t i = 0; i < v.size() && i < max_items; ++i) r += (i ? ", " : "") + v[i];
  if (v.size() > max_items) r += ", ... (" + std::to_string(v.size() - max_items) + " more)";
  return r;
}

bool is_identifier(std::string_view s) {
  if (s.empty()) return false;
  auto start = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!start(s[0])) return false;
  for (char c : s)
    if (!start(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

std::string format_value(double v) {
  if (std::isnan(v)) return "nan";  // printf's sign of a NaN depends on the libm that made it
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string quote(std::string_view s) {
  std::string r(1, '\'');
  r.append(s);
  r += '\'';
  return r;
}

std::string token_text(std::string_view s, const Token& t) {
  switch (t.kind) {
    case TokenKind::kEnd: return "the end";
    case TokenKind::kName: return std::string("name ") + quote(s.substr(t.begin, t.end - t.begin));
    case TokenKind::kNumber: return std::string("number ") + quote(s.substr(t.begin, t.end - t.begin));
    default: return quote(s.substr(t.begin, t.end - t.begin));
  }
}

bool has_register_operands(OpCode op, int* count) {
  switch (op) {
    case OpCode::kConst: case OpCode::kVar: *count = 0; return false;
    case OpCode::kAdd: case OpCode::kSub: case OpCode::kMul: case OpCode::kDiv: case OpCode::kPow:
    case OpCode::kAtan2: *count = 2; return true;
    default: *count = 1; return true;
  }
}

}  // namespace

class Compiler {
 public:
  Compiler(std::string_view source, std::span<const std::string> variables, const Constants& constants)
      : s_(source), lexer_(source), variables_(variables), constants_(constants) {}

  Program compile() {
    for (std::size_t i = 0; i < variables_.size(); ++i) {
      if (!is_identifier(variables_[i]))
        fail(0, ParseErrorKind::kBadVariable, "invalid variable name '" + variables_[i] + "' (not an identifier)");
      for (std::size_t j = 0; j < i; ++j)
        if (variables_[j] == variables_[i])
          fail(0, ParseErrorKind::kBadVariable, "variable '" + variables_[i] + "' is listed twice");
    }
    advance();
    if (tok_.kind == TokenKind::kEnd) fail(0, ParseErrorKind::kEmpty, "empty expression");
    Value root = parse_expression();
    if (tok_.kind == TokenKind::kRParen) fail(tok_.begin, ParseErrorKind::kUnmatchedParenthesis, "unmatched ')'");
    if (tok_.kind != TokenKind::kEnd)
      fail(tok_.begin, ParseErrorKind::kTrailing,
           "unexpected " + token_text(s_, tok_) + " after a complete expression" +
               (tok_.kind == TokenKind::kComma ? " (',' only separates function arguments)" : " (missing operator?)"));
    return emit(root.node);
  }

 private:
  struct Node {
    OpCode op;
    int a = 0, b = 0;  // node ids (kVar: variable index in a; kPowInt: exponent in b)
    double imm = 0.0;
  };
  struct Value {
    int node;
    std::size_t begin;
  };
  using Key = std::tuple<OpCode, int, int, std::uint64_t>;

  // --- tokens -------------------------------------------------------------------------------
  void advance() {
    prev_ = tok_;
    has_prev_ = started_;
    started_ = true;
    tok_ = lexer_.next();
  }
  std::string text(const Token& t) const { return std::string(s_.substr(t.begin, t.end - t.begin)); }

  // --- DAG construction ---------------------------------------------------------------------
  [[gnu::noinline]] int add(const Node& n) {
    Key key{n.op, n.a, n.b, std::bit_cast<std::uint64_t>(n.imm)};
    auto [it, inserted] = index_.try_emplace(key, static_cast<int>(nodes_.size()));
    if (inserted) nodes_.push_back(n);
    return it->second;
  }
  bool is_const(int id) const { return nodes_[static_cast<std::size_t>(id)].op == OpCode::kConst; }
  double const_value(int id) const { return nodes_[static_cast<std::size_t>(id)].imm; }

  int constant(double v, std::size_t begin, const char* what) {
    if (!std::isfinite(v)) not_finite(begin, what, v);
    return add({OpCode::kConst, 0, 0, v});
  }
  [[noreturn]] SSIMARCH_COLD static void not_finite(std::size_t begin, const std::string& what, double v) {
    fail(begin, ParseErrorKind::kNotFinite, what + " is not finite (" + format_value(v) + ")");
  }

  // Folds when every operand is constant, with the evaluator's own arithmetic.
  [[gnu::noinline]] int fold_or_add(const Node& n, int operands, std::size_t begin) {
    bool all_const = true;
    for (int i = 0; i < operands; ++i) all_const = all_const && is_const(i == 0 ? n.a : n.b);
    if (!all_const) return add(n);
    double r[2] = {const_value(n.a), operands == 2 ? const_value(n.b) : 0.0};
    Instruction in{n.op, 0, 0, 1, n.imm};
    if (n.op == OpCode::kPowInt) in.b = n.b;
    double v = apply_instruction<double>(in, r, nullptr);
    return constant(v, begin, "this constant subexpression");
  }

  // `begin`: where the whole subexpression starts (for the non-finite-constant error).
  int unary(OpCode op, Value x, std::size_t begin) { return fold_or_add({op, x.node, 0, 0.0}, 1, begin); }

  int binary(OpCode op, Value x, Value y, std::size_t begin) {
    const bool cx = is_const(x.node), cy = is_const(y.node);
    if (cx && cy) {
      if (op == OpCode::kPow) {
        double e = const_value(y.node);
        if (is_integer_exponent(e))
          return fold_or_add({OpCode::kPowInt, x.node, static_cast<int>(e), 0.0}, 1, begin);
      }
      return fold_or_add({op, x.node, y.node, 0.0}, 2, begin);
    }
    switch (op) {
      case OpCode::kAdd:
        if (cx) return add({OpCode::kAddC, y.node, 0, const_value(x.node)});
        if (cy) return add({OpCode::kAddC, x.node, 0, const_value(y.node)});
        break;
      case OpCode::kSub:
        if (cx) return add({OpCode::kRSubC, y.node, 0, const_value(x.node)});
        if (cy) return add({OpCode::kSubC, x.node, 0, const_value(y.node)});
        break;
      case OpCode::kMul:
        if (cx) return add({OpCode::kMulC, y.node, 0, const_value(x.node)});
        if (cy) return add({OpCode::kMulC, x.node, 0, const_value(y.node)});
        break;
      case OpCode::kDiv:
        if (cx) return add({OpCode::kRDivC, y.node, 0, const_value(x.node)});
        if (cy) return add({OpCode::kDivC, x.node, 0, const_value(y.node)});
        break;
      case OpCode::kPow:
        if (cy) {
          double e = const_value(y.node);
          if (is_integer_exponent(e)) return add({OpCode::kPowInt, x.node, static_cast<int>(e), 0.0});
          return add({OpCode::kPowReal, x.node, 0, e});
        }
        break;
      default: break;
    }
    return add({op, x.node, y.node, 0.0});
  }

  static bool is_integer_exponent(double e) {
    return std::trunc(e) == e && std::fabs(e) <= static_cast<double>(Program::kMaxIntegerExponent);
  }

  // --- grammar ------------------------------------------------------------------------------
  struct DepthGuard {
    Compiler& c;
    DepthGuard(Compiler& compiler, std::size_t offset) : c(compiler) {
      if (++c.depth_ > Program::kMaxNesting) too_deep(offset);
    }
    [[noreturn]] SSIMARCH_COLD static void too_deep(std::size_t offset) {
      fail(offset, ParseErrorKind::kTooDeep,
           "expression nested too deeply (more than " + std::to_string(Program::kMaxNesting) +
               " levels of parentheses, function calls and '^')");
    }
    ~DepthGuard() { --c.depth_; }
  };

  // expression := term {('+' | '-') term}
  Value parse_expression() {
    DepthGuard guard(*this, tok_.begin);
    Value lhs = parse_term();
    while (tok_.kind == TokenKind::kPlus || tok_.kind == TokenKind::kMinus) {
      OpCode op = tok_.kind == TokenKind::kPlus ? OpCode::kAdd : OpCode::kSub;
      advance();
      Value rhs = parse_term();
      lhs = {binary(op, lhs, rhs, lhs.begin), lhs.begin};
    }
    return lhs;
  }

  // term := unary {('*' | '/') unary}
  Value parse_term() {
    Value lhs = parse_unary();
    while (tok_.kind == TokenKind::kStar || tok_.kind == TokenKind::kSlash) {
      OpCode op = tok_.kind == TokenKind::kStar ? OpCode::kMul : OpCode::kDiv;
      advance();
      Value rhs = parse_unary();
      lhs = {binary(op, lhs, rhs, lhs.begin), lhs.begin};
    }
    return lhs;
  }

  // unary := {'+' | '-'} power      (so -x^2 = -(x^2))
  Value parse_unary() {
    std::size_t begin = tok_.begin;
    bool negative = false;
    while (tok_.kind == TokenKind::kPlus || tok_.kind == TokenKind::kMinus) {
      negative = negative != (tok_.kind == TokenKind::kMinus);
      advance();
    }
    Value v = parse_power();
    if (negative) v = {unary(OpCode::kNeg, v, begin), begin};
    v.begin = begin;
    return v;
  }

  // power := primary ['^' unary]    (right-associative: a^b^c = a^(b^c); 2^-1 allowed)
  Value parse_power() {
    Value base = parse_primary();
    if (tok_.kind != TokenKind::kCaret) return base;
    DepthGuard guard(*this, tok_.begin);
    advance();
    Value exponent = parse_unary();
    return {binary(OpCode::kPow, base, exponent, base.begin), base.begin};
  }

  // primary := number | name | name '(' [expression {',' expression}] ')' | '(' expression ')'
  Value parse_primary() {
    const Token t = tok_;
    switch (t.kind) {
      case TokenKind::kNumber:
        advance();
        return {constant(t.number, t.begin, "this number"), t.begin};
      case TokenKind::kName:
        advance();
        if (tok_.kind == TokenKind::kLParen) return parse_call(t);
        return {resolve_name(t), t.begin};
      case TokenKind::kLParen: {
        advance();
        ++open_parens_;
        if (tok_.kind == TokenKind::kRParen) empty_parentheses();
        Value v = parse_expression();
        expect_close(t, "')' or an operator");
        --open_parens_;
        v.begin = t.begin;
        return v;
      }
      default: missing_operand();
    }
  }

  [[noreturn]] SSIMARCH_COLD void empty_parentheses() {
    fail(tok_.begin, ParseErrorKind::kMissingOperand, "missing operand: empty parentheses");
  }

  [[noreturn]] SSIMARCH_COLD void missing_operand() {
    const Token& t = tok_;
    if (!has_prev_) {
      if (t.kind == TokenKind::kRParen) fail(t.begin, ParseErrorKind::kUnmatchedParenthesis, "unmatched ')'");
      fail(t.begin, ParseErrorKind::kMissingOperand, "missing operand before '" + text(t) + "'");
    }
    if (t.kind == TokenKind::kEnd) {
      if (prev_.kind == TokenKind::kLParen)
        fail(prev_.begin, ParseErrorKind::kUnmatchedParenthesis, "unmatched '(' (missing ')')");
      fail(t.begin, ParseErrorKind::kMissingOperand, "missing operand after '" + text(prev_) + "'");
    }
    if (t.kind == TokenKind::kRParen && open_parens_ == 0)
      fail(t.begin, ParseErrorKind::kUnmatchedParenthesis, "unmatched ')'");
    std::string message = "missing operand between '" + text(prev_) + "' and '" + text(t) + "'";
    if (prev_.kind == TokenKind::kStar && t.kind == TokenKind::kStar && prev_.end == t.begin)
      message += " (write ^ for powers)";
    fail(t.begin, ParseErrorKind::kMissingOperand, std::move(message));
  }

  void expect_close(const Token& open, const char* expected) {
    if (tok_.kind != TokenKind::kRParen) not_closed(open, expected);
    advance();
  }
  [[noreturn]] SSIMARCH_COLD void not_closed(const Token& open, const char* expected) {
    if (tok_.kind == TokenKind::kEnd)
      fail(open.begin, ParseErrorKind::kUnmatchedParenthesis, "unmatched '(' (missing ')')");
    fail(tok_.begin, ParseErrorKind::kMissingOperator,
         std::string("expected ") + expected + " before " + token_text(s_, tok_) + " (inside the '(' at column " +
             std::to_string(display_column(s_, open.begin)) + ")");
  }

  Value parse_call(const Token& name) {
    const Token open = tok_;
    const FunctionInfo* f = find_function(s_.substr(name.begin, name.end - name.begin));
    if (f == nullptr) unknown_function(name);
    advance();  // '('
    ++open_parens_;
    std::vector<Value> args;
    if (tok_.kind == TokenKind::kRParen) {
      advance();
    } else {
      for (;;) {
        args.push_back(parse_expression());
        if (tok_.kind == TokenKind::kComma) {
          advance();
          continue;
        }
        expect_close(open, "',' or ')' or an operator");
        break;
      }
    }
    --open_parens_;
    if (static_cast<int>(args.size()) != f->arity) argument_count(name, *f, args.size());
    if (f->arity == 1) return {unary(f->op, args[0], name.begin), name.begin};
    return {binary(f->op, args[0], args[1], name.begin), name.begin};
  }

  [[noreturn]] SSIMARCH_COLD void argument_count(const Token& name, const FunctionInfo& f, std::size_t got) {
    fail(name.begin, ParseErrorKind::kArgumentCount,
         "'" + text(name) + "' takes " + std::to_string(f.arity) + (f.arity == 1 ? " argument" : " arguments") + " (" +
             f.signature + "), got " + std::to_string(got));
  }

  [[noreturn]] SSIMARCH_COLD void unknown_function(const Token& name) {
    const std::string fname = text(name);
    {
      if (auto kind = value_kind(fname))
        fail(name.begin, ParseErrorKind::kUnknownFunction,
             "'" + fname + "' is a " + *kind + ", not a function (write " + fname + "*(...) for a product)");
      std::vector<std::string> names;
      for (const auto& g : kFunctions) names.emplace_back(g.name);
      std::string message = "unknown function '" + fname + "'";
      if (auto near = nearest(fname, names))
        message += "; did you mean '" + *near + "'?";
      else
        message += "; known functions: " + join(names);
      fail(name.begin, ParseErrorKind::kUnknownFunction, std::move(message));
    }
  }

  std::optional<std::string> value_kind(const std::string& name) const {
    for (const auto& v : variables_)
      if (v == name) return "variable";
    if (constants_.find(name) != constants_.end() || name == "pi" || name == "e") return "constant";
    return std::nullopt;
  }

  int resolve_name(const Token& t) {
    const std::string_view name = s_.substr(t.begin, t.end - t.begin);
    for (std::size_t i = 0; i < variables_.size(); ++i)
      if (variables_[i] == name) return add({OpCode::kVar, static_cast<int>(i), 0, 0.0});
    if (auto it = constants_.find(name); it != constants_.end()) {
      if (!std::isfinite(it->second)) not_finite(t.begin, "constant '" + text(t) + "'", it->second);
      return add({OpCode::kConst, 0, 0, it->second});
    }
    if (name == "pi") return add({OpCode::kConst, 0, 0, std::numbers::pi});
    if (name == "e") return add({OpCode::kConst, 0, 0, std::numbers::e});
    unknown_name(t);
  }

  [[noreturn]] SSIMARCH_COLD void unknown_name(const Token& t) {
    const std::string name = text(t);
    if (find_function(name) != nullptr)
      fail(t.begin, ParseErrorKind::kUnknownName,
           "'" + name + "' is a function: call it as " + find_function(name)->signature);
    std::vector<std::string> vars(variables_.begin(), variables_.end()), consts;
    for (const auto& [k, v] : constants_)
      if (k != "pi" && k != "e") consts.push_back(k);
    consts.emplace_back("pi");
    consts.emplace_back("e");
    std::vector<std::string> all = vars;
    all.insert(all.end(), consts.begin(), consts.end());
    std::string message = "unknown name '" + name + "'";
    if (auto near = nearest(name, all)) message += "; did you mean '" + *near + "'?";
    message += " (variables: " + (vars.empty() ? std::string("none") : join(vars)) + "; constants: " + join(consts) + ")";
    fail(t.begin, ParseErrorKind::kUnknownName, std::move(message));
  }

  // --- code generation ----------------------------------------------------------------------
  Program emit(int root) {
    const std::size_t n = nodes_.size();
    std::vector<char> live(n, 0);
    live[static_cast<std::size_t>(root)] = 1;
    // Operands have smaller ids than their users, so one backward sweep marks everything reachable.
    for (std::size_t i = n; i-- > 0;) {
      if (!live[i]) continue;
      int count = 0;
      if (!has_register_operands(nodes_[i].op, &count)) continue;
      live[static_cast<std::size_t>(nodes_[i].a)] = 1;
      if (count == 2) live[static_cast<std::size_t>(nodes_[i].b)] = 1;
    }
    std::vector<std::size_t> last_use(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (!live[i]) continue;
      int count = 0;
      if (!has_register_operands(nodes_[i].op, &count)) continue;
      last_use[static_cast<std::size_t>(nodes_[i].a)] = i;
      if (count == 2) last_use[static_cast<std::size_t>(nodes_[i].b)] = i;
    }
    last_use[static_cast<std::size_t>(root)] = n;  // the result is never freed

    Program p;
    p.source_ = std::string(s_);
    p.variables_.assign(variables_.begin(), variables_.end());
    p.uses_.assign(variables_.size(), false);
    std::vector<int> reg(n, -1);
    std::vector<int> free_regs;
    int num_regs = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!live[i]) continue;
      const Node& node = nodes_[i];
      Instruction in{node.op, 0, 0, 0, node.imm};
      int count = 0;
      if (node.op == OpCode::kVar) {
        in.a = node.a;
        p.uses_[static_cast<std::size_t>(node.a)] = true;
      } else if (has_register_operands(node.op, &count)) {
        in.a = reg[static_cast<std::size_t>(node.a)];
        if (count == 2) in.b = reg[static_cast<std::size_t>(node.b)];
        if (node.op == OpCode::kPowInt) in.b = node.b;
        // Free operands dying here first, so that the result may reuse one of their registers.
        if (last_use[static_cast<std::size_t>(node.a)] == i) free_regs.push_back(reg[static_cast<std::size_t>(node.a)]);
        if (count == 2 && node.b != node.a && last_use[static_cast<std::size_t>(node.b)] == i)
          free_regs.push_back(reg[static_cast<std::size_t>(node.b)]);
      }
      if (free_regs.empty()) {
        in.dst = num_regs++;
      } else {
        in.dst = free_regs.back();
        free_regs.pop_back();
      }
      reg[i] = in.dst;
      p.code_.push_back(in);
    }
    p.num_registers_ = num_regs;
    p.result_ = reg[static_cast<std::size_t>(root)];
    return p;
  }

  std::string_view s_;
  Lexer lexer_;
  std::span<const std::string> variables_;
  const Constants& constants_;
  Token tok_, prev_;
  bool has_prev_ = false, started_ = false;
  int depth_ = 0;
  int open_parens_ = 0;
  std::vector<Node> nodes_;
  std::map<Key, int> index_;
};

}  // namespace ssimarch::internal

namespace ssimarch {

using internal::Compiler;
using internal::CompileFailure;

bool Program::compile(std::string_view source, std::span<const std::string> variables, const Constants& constants,
                      Program* out, ParseError* error) {
  try {
    Compiler compiler(source, variables, constants);
    Program p = compiler.compile();
    if (out != nullptr) *out = std::move(p);
    return true;
  } catch (CompileFailure& failure) {
    if (error != nullptr) {
      *error = std::move(failure.error);
      error->offset = std::min(error->offset, source.size());
      error->column = display_column(source, error->offset);
    }
    return false;
  }
}

}  // namespace ssimarch
