// Where and why an expression failed to compile (docs/expressions.md, "Error messages").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ssimarch {

/// What kind of mistake a ParseError reports (for programs; people read `message`).
enum class ParseErrorKind {
  kEmpty,                // nothing but white space
  kUnexpectedCharacter,  // a byte that starts no token ('#', '[', a non-ASCII letter, NUL, ...)
  kBadNumber,            // malformed literal (1e, 1.2.3, 2u) or one that overflows a double
  kUnknownName,          // a name that is neither a variable nor a constant (or a function used as a value)
  kUnknownFunction,      // name(...) with an unknown name (or a variable/constant called like a function)
  kArgumentCount,        // a known function with the wrong number of arguments
  kUnmatchedParenthesis, // '(' without ')' or ')' without '('
  kMissingOperand,       // an operator or '(' or ',' with nothing usable after (or before) it
  kMissingOperator,      // two operands side by side inside parentheses or arguments: "(u v)"
  kTrailing,             // something after a complete expression
  kTooDeep,              // nesting beyond Program::kMaxNesting
  kNotFinite,            // a constant or constant subexpression that is inf or NaN
  kBadVariable,          // the caller's variable list is invalid (not an identifier, duplicate)
};

struct ParseError {
  std::size_t offset = 0;  ///< 0-based byte offset into the source (<= source.size())
  int column = 0;          ///< 1-based display column (UTF-8 code points; bad bytes count one each)
  std::string message;     ///< what is wrong, without position
  ParseErrorKind kind = ParseErrorKind::kEmpty;

  /// "where: column N: message\n  <source>\n  <spaces>^" ("where: " left out when empty).
  /// Control characters in the echoed source are shown as '?' (tab as a space) so that the
  /// caret stays under the offending character.
  std::string format(std::string_view source, std::string_view where = {}) const;
};

/// 1-based display column of byte `offset` in `source` (see ParseError::column).
int display_column(std::string_view source, std::size_t offset);

}  // namespace ssimarch
