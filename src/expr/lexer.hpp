// Tokens of the expression language (docs/expressions.md, "Lexical structure"). Internal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "ssimarch/expr/parse_error.hpp"

namespace ssimarch::internal {

/// Thrown inside the compiler only; Program::compile turns it into its ParseError result.
struct CompileFailure {
  ParseError error;
};

[[noreturn]] void fail(std::size_t offset, ParseErrorKind kind, std::string message);

enum class TokenKind { kNumber, kName, kPlus, kMinus, kStar, kSlash, kCaret, kLParen, kRParen, kComma, kEnd };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::size_t begin = 0;
  std::size_t end = 0;
  double number = 0.0;  // kNumber only
};

/// Splits the source on demand, so that the leftmost problem is the one reported.
class Lexer {
 public:
  explicit Lexer(std::string_view source) : s_(source) {}
  /// The next token; throws CompileFailure for an unexpected character or a bad number literal.
  Token next();
  /// Whether the next non-blank character is `c` (a name followed by '(' is a call).
  bool next_char_is(char c) const;

 private:
  Token number(std::size_t begin);
  std::string_view s_;
  std::size_t pos_ = 0;
};

/// How a character (one UTF-8 code point or one invalid byte) at `offset` is named in messages:
/// '#', '\x01', 'é' (U+00E9), byte 0xFF (not valid UTF-8).
std::string describe_character(std::string_view source, std::size_t offset);

/// Length in bytes of the well-formed UTF-8 sequence starting at `offset`, 0 if it is not one.
std::size_t utf8_sequence_length(std::string_view s, std::size_t offset);

}  // namespace ssimarch::internal
