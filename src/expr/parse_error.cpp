#include "ssimarch/expr/parse_error.hpp"

#include "lexer.hpp"

namespace ssimarch {

namespace {

// Calls f(begin, length, valid) for each display unit: a well-formed UTF-8 sequence, or one byte.
template <class F>
void for_each_unit(std::string_view s, F&& f) {
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t len = internal::utf8_sequence_length(s, i);
    bool valid = len > 0;
    if (!valid) len = 1;
    if (!f(i, len, valid)) return;
    i += len;
  }
}

}  // namespace

int display_column(std::string_view source, std::size_t offset) {
  int column = 1;
  for_each_unit(source, [&](std::size_t begin, std::size_t, bool) {
    if (begin >= offset) return false;
    ++column;
    return true;
  });
  return column;
}

std::string ParseError::format(std::string_view source, std::string_view where) const {
  std::string out;
  if (!where.empty()) out.append(where).append(": ");
  int col = display_column(source, offset);
  out += "column " + std::to_string(col) + ": " + message + "\n  ";
  for_each_unit(source, [&](std::size_t begin, std::size_t len, bool valid) {
    auto c = static_cast<unsigned char>(source[begin]);
    if (!valid)
      out += '?';
    else if (c == '\t')
      out += ' ';
    else if (c < 0x20 || c == 0x7F)
      out += '?';
    else
      out.append(source.substr(begin, len));
    return true;
  });
  out += "\n  ";
  out.append(static_cast<std::size_t>(col - 1), ' ');
  out += '^';
  return out;
}

}  // namespace ssimarch
