#include "ssimarch/expr/referenced_names.hpp"

#include <set>

#include "lexer.hpp"

namespace ssimarch {

std::vector<std::string> referenced_names(std::string_view source) {
  std::vector<std::string> names;
  std::set<std::string_view> seen;
  internal::Lexer lexer(source);
  try {
    for (internal::Token t = lexer.next(); t.kind != internal::TokenKind::kEnd; t = lexer.next()) {
      if (t.kind != internal::TokenKind::kName) continue;
      const std::string_view name = source.substr(t.begin, t.end - t.begin);
      if (seen.insert(name).second) names.emplace_back(name);
    }
  } catch (const internal::CompileFailure&) {
    // The names before the bad character; compile_or_throw reports the character itself.
  }
  return names;
}

}  // namespace ssimarch
