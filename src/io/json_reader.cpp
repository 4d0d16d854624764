// Strict JSON for input files: one set of messages for scenes and surfaces (docs/scene-format.md).
#include "ssimarch/io/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/input_files.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch {

using nlohmann::json;

namespace {

// The narrowest interval (a parameter domain or a box side) the readers accept: absolute, and
// relative to the endpoints (docs/scene-format.md).
constexpr double kMinIntervalWidth = 1e-100, kMinIntervalRelativeWidth = 1e-10;

// Line and column (1-based) of a byte offset.
std::string line_column(const std::string& text, std::size_t offset) {
  int line = 1, col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

// The JSON path of the value being parsed, kept from the parser's events, so that a repeated
// key can be reported where it is (the parser callback knows no byte offset).
class PathTracker {
 public:
  explicit PathTracker(std::string source) : source_(std::move(source)) {}

  bool on_event(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: frames_.push_back({false, 0, {}, {}}); break;
      case json::parse_event_t::array_start: frames_.push_back({true, 0, {}, {}}); break;
      case json::parse_event_t::key: on_key(parsed.get<std::string>()); break;
      case json::parse_event_t::value: next_element(); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!frames_.empty()) frames_.pop_back();
        next_element();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
    std::set<std::string, std::less<>> keys;
  };

  void next_element() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  void on_key(const std::string& key) {
    Frame& f = frames_.back();
    f.key = key;
    if (!f.keys.insert(key).second)
      throw InputError(source_ + ": " + path(), "duplicate key \"" + key + "\" (a key may appear only once in an object)");
  }
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      if (f.array) p += "[" + std::to_string(f.index) + "]";
      else p += (p.empty() ? "" : ".") + f.key;
    }
    return p;
  }

  std::string source_;
  std::vector<Frame> frames_;
};

// The text nlohmann quotes in "number overflow parsing '1e400'", located in the input.
std::string overflow_location(const std::string& text, const std::string& message) {
  auto a = message.find('\'');
  auto b = message.rfind('\'');
  if (a == std::string::npos || b <= a) return {};
  auto at = text.find(message.substr(a + 1, b - a - 1));
  return at == std::string::npos ? std::string{} : ":" + line_column(text, at);
}

}  // namespace

json parse_json_text(const std::string& text, const std::string& source) {
  if (auto nul = text.find('\0'); nul != std::string::npos)
    throw InputError(source + ":" + line_column(text, nul), "a NUL byte: JSON text must not contain one");
  PathTracker tracker(source);
  json::parser_callback_t callback = [&tracker](int, json::parse_event_t event, json& parsed) {
    return tracker.on_event(event, parsed);
  };
  try {
    return json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    std::string msg = e.what();
    auto pos = msg.find("syntax error");
    throw InputError(source + ":" + line_column(text, e.byte > 0 ? e.byte - 1 : 0),
                     "invalid JSON: " + (pos != std::string::npos ? msg.substr(pos) : msg));
  } catch (const json::out_of_range& e) {
    throw InputError(source + overflow_location(text, e.what()),
                     "a number outside the range of double precision (about 1.8e308)");
  } catch (const json::exception& e) {
    throw InputError(source, std::string("invalid JSON: ") + e.what());
  }
}

std::string json_kind(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "a number";
    default: return "an unsupported JSON value";
  }
}

std::string join_names(const std::vector<std::string>& names) { return internal::join_names(names); }

std::string index_path(const std::string& where, std::size_t i) { return where + "[" + std::to_string(i) + "]"; }
std::string key_path(const std::string& where, std::string_view key) {
  // "scene.json:" (the top level of a file) + "surfaces" -> "scene.json: surfaces"
  if (!where.empty() && where.back() == ':') return where + " " + std::string(key);
  return where + "." + std::string(key);
}

std::string format_number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

double json_number(const json& j, const Constants& constants, const std::string& where) {
  double x;
  if (j.is_number()) {
    x = j.get<double>();
  } else if (j.is_string()) {
    x = evaluate_constant(j.get<std::string>(), constants, where);
  } else {
    throw InputError(where, "expected a number or an expression string, got " + json_kind(j));
  }
  if (!std::isfinite(x)) throw InputError(where, "the value is not a finite number");
  return x;
}

std::string json_string(const json& j, const std::string& where, std::string_view what) {
  if (!j.is_string()) throw InputError(where, "expected " + std::string(what) + ", got " + json_kind(j));
  return j.get<std::string>();
}

const json& json_array(const json& j, std::size_t n, const std::string& where, std::string_view what) {
  if (!j.is_array()) throw InputError(where, "must be " + std::string(what) + ", got " + json_kind(j));
  if (j.size() != n)
    throw InputError(where, "must be " + std::string(what) + ", got " + std::to_string(j.size()) + " components");
  return j;
}

Vec3 json_vec3(const json& j, const Constants& c, const std::string& where) {
  json_array(j, 3, where, "a list of 3 numbers [x, y, z]");
  return {json_number(j[0], c, index_path(where, 0)), json_number(j[1], c, index_path(where, 1)),
          json_number(j[2], c, index_path(where, 2))};
}

Interval json_interval(const json& j, const Constants& c, const std::string& where) {
  json_array(j, 2, where, "an interval [lo, hi]");
  const Interval i{json_number(j[0], c, index_path(where, 0)), json_number(j[1], c, index_path(where, 1))};
  if (!(i.lo < i.hi))
    throw InputError(where, "interval must have lo < hi, got [" + format_number(i.lo) + ", " + format_number(i.hi) + "]");
  // Samples, steps and periods are fractions of the width: it must be a normal double well above
  // the spacing of doubles at the endpoints (a periodic domain of width 5e-324 gave null points).
  const double width = i.hi - i.lo, scale = std::max(std::fabs(i.lo), std::fabs(i.hi));
  if (!(width >= kMinIntervalWidth) || !(width >= kMinIntervalRelativeWidth * scale))
    throw InputError(where, "interval [" + format_number(i.lo) + ", " + format_number(i.hi) +
                                "] is too narrow for double precision: its width must be at least 1e-100 and at least "
                                "1e-10 times its largest endpoint");
  return i;
}

Box json_box(const json& j, const Constants& c, const std::string& where) {
  json_array(j, 3, where, "a box [[xlo, xhi], [ylo, yhi], [zlo, zhi]]");
  return {json_interval(j[0], c, index_path(where, 0)), json_interval(j[1], c, index_path(where, 1)),
          json_interval(j[2], c, index_path(where, 2))};
}

JsonObject::JsonObject(const json& obj, std::string where, std::initializer_list<const char*> required,
                       std::initializer_list<const char*> optional)
    : obj_(obj), where_(std::move(where)) {
  if (!obj.is_object()) throw InputError(where_, "must be an object, got " + json_kind(obj));
  std::vector<std::string> known;
  for (const char* k : required) known.emplace_back(k);
  for (const char* k : optional) known.emplace_back(k);
  for (const char* k : required)
    if (!obj.contains(k)) throw InputError(where_, std::string("missing key '") + k + "' (keys: " + join_names(known) + ")");
  for (const auto& [k, v] : obj.items())
    if (std::find(known.begin(), known.end(), k) == known.end())
      throw InputError(key_path(where_, k), "unknown key '" + k + "' (keys: " + join_names(known) + ")");
}

}  // namespace ssimarch
