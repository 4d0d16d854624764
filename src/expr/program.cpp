#include "ssimarch/expr/program.hpp"

#include <cstdio>

#include "ssimarch/core/error.hpp"

namespace ssimarch {

namespace {

const char* op_name(OpCode op) {
  switch (op) {
    case OpCode::kConst: return "const";
    case OpCode::kVar: return "var";
    case OpCode::kNeg: return "neg";
    case OpCode::kAdd: return "add";
    case OpCode::kSub: return "sub";
    case OpCode::kMul: return "mul";
    case OpCode::kDiv: return "div";
    case OpCode::kPow: return "pow";
    case OpCode::kAtan2: return "atan2";
    case OpCode::kAddC: return "addc";
    case OpCode::kSubC: return "subc";
    case OpCode::kRSubC: return "rsubc";
    case OpCode::kMulC: return "mulc";
    case OpCode::kDivC: return "divc";
    case OpCode::kRDivC: return "rdivc";
    case OpCode::kPowInt: return "powi";
    case OpCode::kPowReal: return "powr";
    case OpCode::kSqrt: return "sqrt";
    case OpCode::kCbrt: return "cbrt";
    case OpCode::kExp: return "exp";
    case OpCode::kLog: return "log";
    case OpCode::kSin: return "sin";
    case OpCode::kCos: return "cos";
    case OpCode::kTan: return "tan";
    case OpCode::kAsin: return "asin";
    case OpCode::kAcos: return "acos";
    case OpCode::kAtan: return "atan";
    case OpCode::kSinh: return "sinh";
    case OpCode::kCosh: return "cosh";
    case OpCode::kTanh: return "tanh";
    case OpCode::kAbs: return "abs";
  }
  return "?";
}

}  // namespace

Program Program::compile_or_throw(std::string_view source, std::span<const std::string> variables,
                                  const Constants& constants, std::string where) {
  Program p;
  ParseError error;
  if (!compile(source, variables, constants, &p, &error)) throw InputError(std::move(where), error.format(source));
  return p;
}

std::string Program::disassemble() const {
  std::string out;
  char buf[128];
  for (const Instruction& in : code_) {
    const char* name = op_name(in.op);
    switch (in.op) {
      case OpCode::kConst: std::snprintf(buf, sizeof buf, "r%d = %.17g\n", in.dst, in.imm); break;
      case OpCode::kVar:
        std::snprintf(buf, sizeof buf, "r%d = %s\n", in.dst, variables_[static_cast<std::size_t>(in.a)].c_str());
        break;
      case OpCode::kAdd: case OpCode::kSub: case OpCode::kMul: case OpCode::kDiv: case OpCode::kPow:
      case OpCode::kAtan2:
        std::snprintf(buf, sizeof buf, "r%d = %s r%d, r%d\n", in.dst, name, in.a, in.b);
        break;
      case OpCode::kAddC: case OpCode::kSubC: case OpCode::kRSubC: case OpCode::kMulC: case OpCode::kDivC:
      case OpCode::kRDivC: case OpCode::kPowReal:
        std::snprintf(buf, sizeof buf, "r%d = %s r%d, %.17g\n", in.dst, name, in.a, in.imm);
        break;
      case OpCode::kPowInt: std::snprintf(buf, sizeof buf, "r%d = powi r%d, %d\n", in.dst, in.a, in.b); break;
      default: std::snprintf(buf, sizeof buf, "r%d = %s r%d\n", in.dst, name, in.a); break;
    }
    out += buf;
  }
  out += "result r" + std::to_string(result_) + "\n";
  return out;
}

double evaluate_constant(std::string_view source, const Constants& constants, std::string where) {
  Program p = Program::compile_or_throw(source, std::span<const std::string>(), constants, std::move(where));
  // Without variables everything folds to one finite constant (folding rejects inf and NaN).
  return p.constant_value();
}

}  // namespace ssimarch
