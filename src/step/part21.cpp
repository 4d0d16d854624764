// ISO 10303-21 clear-text syntax (§5 tokens, §8 header, §9 data, §10 complex instances): a
// recursive-descent reader with bounded nesting. Only the exchange structure is read; the
// meaning of entities is step/reader.cpp's.
#include "ssimarch/step/part21.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/text_file.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch {

using internal::cat;

const StepRecord* StepInstance::record(const std::string& type) const {
  for (const StepRecord& r : records)
    if (r.type == type) return &r;
  return nullptr;
}

std::string StepInstance::type_text() const {
  if (records.size() == 1) return records[0].type;
  std::string s = "(";
  for (std::size_t i = 0; i < records.size(); ++i) s.append(i ? " " : "").append(records[i].type);
  return s.append(")");
}

std::string StepFile::where(const StepInstance& inst) const { return cat(source, ":", inst.line, ": #", inst.id); }

const StepInstance* StepFile::find(std::int64_t id) const {
  const auto it = instances_.find(id);
  return it == instances_.end() ? nullptr : &it->second;
}

const StepInstance& StepFile::at(std::int64_t id, const StepInstance& from) const {
  const StepInstance* inst = find(id);
  if (!inst) throw InputError(where(from), cat("refers to #", id, ", which the file does not define"));
  return *inst;
}

void StepFile::add(StepInstance inst) {
  const std::int64_t id = inst.id;
  const int line = inst.line;
  const auto [it, fresh] = instances_.emplace(id, std::move(inst));
  if (!fresh)
    throw InputError(cat(source, ":", line),
                     cat("instance #", id, " is defined twice (first on line ", it->second.line, ")"));
  order.push_back(id);
}

namespace {

// Ids and integers beyond 2^53 are not exact in a double; no real file comes near.
constexpr double kMaxStepInteger = 9007199254740992.0;

class Part21Parser {
 public:
  Part21Parser(const std::string& text, const std::string& source) : s_(text), source_(source) {}

  StepFile parse() {
    StepFile file;
    file.source = source_;
    expect_word("ISO-10303-21");
    expect(';');
    expect_word("HEADER");
    expect(';');
    while (!at_word("ENDSEC")) header_entry(&file);
    expect_word("ENDSEC");
    expect(';');
    while (at_word("DATA")) data_section(&file);
    expect_word("END-ISO-10303-21");
    expect(';');
    return file;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw InputError(cat(source_, ":", line_), message); }

  // Spaces, line breaks and /* comments */ (§5.6).
  void skip() {
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (c == '\n')
        ++line_, ++pos_;
      else if (std::isspace(static_cast<unsigned char>(c)))
        ++pos_;
      else if (c == '/' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '*') {
        const std::size_t end = s_.find("*/", pos_ + 2);
        if (end == std::string::npos) fail("a comment /* is not closed");
        for (std::size_t k = pos_; k < end; ++k) line_ += s_[k] == '\n';
        pos_ = end + 2;
      } else
        break;
    }
  }
  char peek() {
    skip();
    return pos_ < s_.size() ? s_[pos_] : '\0';
  }
  std::string shown(char c) const { return c == '\0' ? std::string("the end of the file") : cat("'", c, "'"); }
  void expect(char c) {
    const char got = peek();
    if (got != c) fail(cat("expected '", c, "', found ", shown(got)));
    ++pos_;
  }
  static bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }
  // A keyword (§5.4: upper-case letters, digits, '_'; '!' starts a user-defined one), or the
  // section words with '-'.
  std::string word() {
    skip();
    const std::size_t start = pos_;
    if (pos_ < s_.size() && s_[pos_] == '!') ++pos_;
    while (pos_ < s_.size() && word_char(s_[pos_])) ++pos_;
    return s_.substr(start, pos_ - start);
  }
  bool at_word(const char* w) {
    skip();
    const std::size_t n = std::char_traits<char>::length(w);
    return s_.compare(pos_, n, w) == 0 && (pos_ + n >= s_.size() || !word_char(s_[pos_ + n]));
  }
  void expect_word(const char* w) {
    if (!at_word(w)) fail(cat("expected ", w, ", found ", shown(peek())));
    pos_ += std::char_traits<char>::length(w);
  }

  void header_entry(StepFile* file) {
    StepRecord r = record(0);
    expect(';');
    if (r.type == "FILE_SCHEMA" && !r.params.empty())
      for (const StepValue& v : r.params[0].items)
        if (v.kind == StepValue::Kind::kString) file->schemas.push_back(v.text);
  }

  void data_section(StepFile* file) {
    expect_word("DATA");
    if (peek() == '(') parameter_list(0);  // Part 21 edition 3: DATA('name',('schema'))
    expect(';');
    while (!at_word("ENDSEC")) {
      if (peek() != '#') fail(cat("expected an instance '#id=' or ENDSEC, found ", shown(peek())));
      file->add(instance());
    }
    expect_word("ENDSEC");
    expect(';');
  }

  StepInstance instance() {
    StepInstance inst;
    inst.line = line_;
    inst.id = instance_id();
    expect('=');
    if (peek() == '(') {  // complex instance (§10.2.5): records in a list without commas
      ++pos_;
      while (peek() != ')') {
        if (peek() == '\0') fail("a complex instance is not closed");
        inst.records.push_back(record(1));
      }
      ++pos_;
      if (inst.records.empty()) fail("a complex instance has no entity");
    } else {
      inst.records.push_back(record(0));
    }
    if (peek() != ';')
      fail(cat("instance #", inst.id, " (line ", inst.line, ") does not end with ';', found ", shown(peek())));
    ++pos_;
    return inst;
  }

  std::int64_t instance_id() {
    expect('#');
    const std::size_t start = pos_;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    if (pos_ == start) fail("expected digits after '#'");
    if (pos_ - start > 15) fail(cat("instance id ", s_.substr(start, pos_ - start), " is too large"));
    return std::stoll(s_.substr(start, pos_ - start));
  }

  StepRecord record(int depth) {
    StepRecord r;
    r.type = word();
    if (r.type.empty() || r.type == "!") fail(cat("expected an entity name, found ", shown(peek())));
    r.params = parameter_list(depth);
    return r;
  }

  std::vector<StepValue> parameter_list(int depth) {
    if (depth >= kMaxStepNesting) fail(cat("lists nested deeper than ", kMaxStepNesting));
    expect('(');
    std::vector<StepValue> items;
    if (peek() == ')') {
      ++pos_;
      return items;
    }
    for (;;) {
      items.push_back(value(depth + 1));
      const char c = peek();
      ++pos_;
      if (c == ')') return items;
      if (c != ',') fail(cat("expected ',' or ')' in a parameter list, found ", shown(c)));
    }
  }

  StepValue value(int depth) {
    StepValue v;
    const char c = peek();
    if (c == '$' || c == '*') {
      v.kind = c == '$' ? StepValue::Kind::kUnset : StepValue::Kind::kDerived;
      ++pos_;
    } else if (c == '#') {
      v.kind = StepValue::Kind::kRef;
      v.ref = instance_id();
    } else if (c == '\'') {
      v.kind = StepValue::Kind::kString;
      v.text = string_literal();
    } else if (c == '"') {
      v.kind = StepValue::Kind::kBinary;
      v.text = delimited('"', "a binary");
    } else if (c == '.') {
      v.kind = StepValue::Kind::kEnum;
      v.text = delimited('.', "an enumeration");
    } else if (c == '(') {
      v.kind = StepValue::Kind::kList;
      v.items = parameter_list(depth);
    } else if (c == '+' || c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
      number(&v);
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '!') {
      v.kind = StepValue::Kind::kTyped;  // typed parameter (§6.4): LENGTH_MEASURE(2.5)
      v.text = word();
      v.items = parameter_list(depth);
    } else {
      fail(cat("expected a parameter, found ", shown(c)));
    }
    return v;
  }

  // '...' with '' for a quote (§6.3.3); \X2\ and other control directives are kept as written.
  std::string string_literal() {
    std::string out;
    for (++pos_;; ++pos_) {
      if (pos_ >= s_.size()) fail("a string is not closed");
      const char c = s_[pos_];
      if (c == '\n') ++line_;
      if (c != '\'') {
        out += c;
        continue;
      }
      if (pos_ + 1 < s_.size() && s_[pos_ + 1] == '\'') {
        out += '\'';
        ++pos_;
        continue;
      }
      ++pos_;
      return out;
    }
  }

  std::string delimited(char quote, const char* what) {
    const std::size_t start = ++pos_;
    while (pos_ < s_.size() && s_[pos_] != quote) {
      const char c = s_[pos_];
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) fail(cat(what, " contains '", c, "'"));
      ++pos_;
    }
    if (pos_ >= s_.size()) fail(cat(what, " is not closed"));
    return s_.substr(start, pos_++ - start);
  }

  // Integer or real (§6.3.1-2): sign, digits, '.', digits, exponent.
  void number(StepValue* v) {
    const std::size_t start = pos_;
    if (s_[pos_] == '+' || s_[pos_] == '-') ++pos_;
    bool real = false;
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (std::isdigit(static_cast<unsigned char>(c)))
        ++pos_;
      else if (c == '.' || c == 'E' || c == 'e')
        real = true, ++pos_;
      else if ((c == '+' || c == '-') && (s_[pos_ - 1] == 'E' || s_[pos_ - 1] == 'e'))
        ++pos_;
      else
        break;
    }
    std::string t = s_.substr(start, pos_ - start);
    if (!t.empty() && t[0] == '+') t.erase(0, 1);
    double x = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(x))
      fail(cat("'", s_.substr(start, pos_ - start), "' is not a finite number"));
    if (!real && std::abs(x) >= kMaxStepInteger) fail(cat("the integer ", t, " is too large"));
    v->kind = real ? StepValue::Kind::kReal : StepValue::Kind::kInteger;
    v->number = x;
  }

  const std::string& s_;
  std::string source_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

StepFile parse_step(const std::string& text, const std::string& source) { return Part21Parser(text, source).parse(); }

StepFile read_step_file(const std::filesystem::path& path, const InputLimits& limits) {
  return parse_step(read_text_file(path, "STEP file", limits.max_step_bytes), path.string());
}

}  // namespace ssimarch
