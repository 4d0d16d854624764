#include "lexer.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <system_error>

namespace ssimarch::internal {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

std::uint32_t decode(std::string_view s, std::size_t offset, std::size_t len) {
  auto b = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(s[offset + i])); };
  switch (len) {
    case 2: return ((b(0) & 0x1Fu) << 6) | (b(1) & 0x3Fu);
    case 3: return ((b(0) & 0x0Fu) << 12) | ((b(1) & 0x3Fu) << 6) | (b(2) & 0x3Fu);
    case 4: return ((b(0) & 0x07u) << 18) | ((b(1) & 0x3Fu) << 12) | ((b(2) & 0x3Fu) << 6) | (b(3) & 0x3Fu);
    default: return b(0);
  }
}

// Look-alikes people paste from papers, with what to type instead.
const char* hint_for(std::uint32_t cp) {
  switch (cp) {
    case 0x03C0: return " (write pi)";
    case 0x2212: case 0x2013: case 0x2014: return " (use the ASCII '-')";
    case 0x00D7: case 0x00B7: case 0x22C5: case 0x2217: return " (use '*')";
    case 0x00F7: case 0x2215: return " (use '/')";
    case 0x00B2: return " (write ^2)";
    case 0x00B3: return " (write ^3)";
    default: return "";
  }
}

}  // namespace

void fail(std::size_t offset, ParseErrorKind kind, std::string message) {
  ParseError e;
  e.offset = offset;
  e.kind = kind;
  e.message = std::move(message);
  throw CompileFailure{std::move(e)};
}

std::size_t utf8_sequence_length(std::string_view s, std::size_t offset) {
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[offset + i]); };
  unsigned char c = byte(0);
  std::size_t len = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte (RFC 3629 table)
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) {
    len = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    len = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    len = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (offset + len > s.size()) return 0;
  if (byte(1) < lo || byte(1) > hi) return 0;
  for (std::size_t i = 2; i < len; ++i)
    if (byte(i) < 0x80 || byte(i) > 0xBF) return 0;
  return len;
}

std::string describe_character(std::string_view s, std::size_t offset) {
  char buf[64];
  auto c = static_cast<unsigned char>(s[offset]);
  if (c >= 0x20 && c < 0x7F) return std::string("'") + static_cast<char>(c) + "'";
  if (c < 0x80) {
    std::snprintf(buf, sizeof buf, "'\\x%02X' (a control character)", c);
    return buf;
  }
  std::size_t len = utf8_sequence_length(s, offset);
  if (len == 0) {
    std::snprintf(buf, sizeof buf, "byte 0x%02X (not valid UTF-8)", c);
    return buf;
  }
  std::uint32_t cp = decode(s, offset, len);
  std::snprintf(buf, sizeof buf, "' (U+%04X)%s", static_cast<unsigned>(cp), hint_for(cp));
  std::string r(1, '\'');
  r.append(s.substr(offset, len));
  r += buf;
  return r;
}

bool Lexer::next_char_is(char c) const {
  std::size_t p = pos_;
  while (p < s_.size() && is_blank(s_[p])) ++p;
  return p < s_.size() && s_[p] == c;
}

Token Lexer::next() {
  while (pos_ < s_.size() && is_blank(s_[pos_])) ++pos_;
  Token t;
  t.begin = pos_;
  if (pos_ == s_.size()) {
    t.kind = TokenKind::kEnd;
    t.end = pos_;
    return t;
  }
  char c = s_[pos_];
  if (is_digit(c) || (c == '.' && pos_ + 1 < s_.size() && is_digit(s_[pos_ + 1]))) return number(pos_);
  if (is_name_start(c)) {
    while (pos_ < s_.size() && is_name_char(s_[pos_])) ++pos_;
    t.kind = TokenKind::kName;
    t.end = pos_;
    return t;
  }
  switch (c) {
    case '+': t.kind = TokenKind::kPlus; break;
    case '-': t.kind = TokenKind::kMinus; break;
    case '*': t.kind = TokenKind::kStar; break;
    case '/': t.kind = TokenKind::kSlash; break;
    case '^': t.kind = TokenKind::kCaret; break;
    case '(': t.kind = TokenKind::kLParen; break;
    case ')': t.kind = TokenKind::kRParen; break;
    case ',': t.kind = TokenKind::kComma; break;
    case '[': case ']': case '{': case '}':
      fail(pos_, ParseErrorKind::kUnexpectedCharacter,
           "unexpected character " + describe_character(s_, pos_) + " (only round parentheses group)");
    case '.':
      fail(pos_, ParseErrorKind::kBadNumber, "bad number literal '.': no digits");
    default:
      fail(pos_, ParseErrorKind::kUnexpectedCharacter, "unexpected character " + describe_character(s_, pos_));
  }
  ++pos_;
  t.end = pos_;
  return t;
}

// number := digits ['.' digits*] [exponent] | '.' digits [exponent];  exponent := ('e'|'E') ['+'|'-'] digits
Token Lexer::number(std::size_t begin) {
  std::size_t p = begin;
  while (p < s_.size() && is_digit(s_[p])) ++p;
  if (p < s_.size() && s_[p] == '.') {
    ++p;
    while (p < s_.size() && is_digit(s_[p])) ++p;
  }
  bool exponent_without_digits = false;
  if (p < s_.size() && (s_[p] == 'e' || s_[p] == 'E')) {
    std::size_t q = p + 1;
    if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
    if (q < s_.size() && is_digit(s_[q])) {
      while (q < s_.size() && is_digit(s_[q])) ++q;
      p = q;
    } else {
      exponent_without_digits = true;
      p = q;
    }
  }
  // A literal runs into letters, digits or dots only by mistake: show the whole run.
  std::size_t end = p;
  while (end < s_.size() && (is_name_char(s_[end]) || s_[end] == '.')) ++end;
  std::string_view text = s_.substr(begin, end - begin);
  if (exponent_without_digits) {
    text = s_.substr(begin, p - begin);
    std::string message = "bad number literal '" + std::string(text) + "': the exponent has no digits";
    if (s_[p - 1] == 'e' && end == p)  // "2e": perhaps 2 times Euler's number
      message += " (write " + std::string(text.substr(0, text.size() - 1)) + "*e for a product)";
    fail(begin, ParseErrorKind::kBadNumber, std::move(message));
  }
  if (end != p) {
    std::string message = "bad number literal '" + std::string(text) + "'";
    if (!exponent_without_digits && is_name_start(s_[p]))
      message += " (write " + std::string(s_.substr(begin, p - begin)) + "*" + std::string(s_.substr(p, end - p)) +
                 " for a product)";
    fail(begin, ParseErrorKind::kBadNumber, std::move(message));
  }
  Token t;
  t.kind = TokenKind::kNumber;
  t.begin = begin;
  t.end = end;
  auto [ptr, ec] = std::from_chars(s_.data() + begin, s_.data() + end, t.number);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(t.number)))
    fail(begin, ParseErrorKind::kBadNumber, "number literal '" + std::string(text) + "' is out of the range of a double");
  if (ec != std::errc() || ptr != s_.data() + end)
    fail(begin, ParseErrorKind::kBadNumber, "bad number literal '" + std::string(text) + "'");
  pos_ = end;
  return t;
}

}  // namespace ssimarch::internal
