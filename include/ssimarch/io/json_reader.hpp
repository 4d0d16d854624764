// The one JSON layer of the input files (scenes and their surfaces): strict parsing and typed
// readers that turn every problem into an InputError naming the file, the JSON path (or the
// line:column of a syntax error) and the rule that was broken. No exception of the JSON library
// reaches a caller.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/core/text_file.hpp"  // read_text_file, for the readers of JSON files
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/expr/program.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

/// Parses JSON text (comments allowed). Throws InputError("source:line:column", ...) for a
/// syntax error, a NUL byte (nlohmann's lexer would take it for the end of the text and accept
/// what precedes it) and a number outside double's range (1e400); InputError("source: path",
/// ...) for a key that appears twice in one object (JSON leaves that undefined).
nlohmann::json parse_json_text(const std::string& text, const std::string& source);

/// "a number", "a string", "an object", ... for messages.
std::string json_kind(const nlohmann::json& j);
/// "a, b, c".
std::string join_names(const std::vector<std::string>& names);
/// where + "[i]" and where + "." + key (where + " " + key after a file name "scene.json:").
std::string index_path(const std::string& where, std::size_t i);
std::string key_path(const std::string& where, std::string_view key);
/// A double with 17 significant digits (reads back exactly), for messages.
std::string format_number(double x);

/// A JSON number, or a string holding an expression of the constants ("2*pi", "R/2"); finite.
double json_number(const nlohmann::json& j, const Constants& constants, const std::string& where);
/// A JSON string; `what` describes the expected value ("a surface name").
std::string json_string(const nlohmann::json& j, const std::string& where, std::string_view what = "a string");
/// An array of exactly n elements; `what` describes it ("an interval [lo, hi]").
const nlohmann::json& json_array(const nlohmann::json& j, std::size_t n, const std::string& where, std::string_view what);
/// [x, y, z] of numbers or expressions.
Vec3 json_vec3(const nlohmann::json& j, const Constants& constants, const std::string& where);
/// [lo, hi] with lo < hi.
Interval json_interval(const nlohmann::json& j, const Constants& constants, const std::string& where);
/// [[xlo, xhi], [ylo, yhi], [zlo, zhi]].
Box json_box(const nlohmann::json& j, const Constants& constants, const std::string& where);

/// An object with the given required and optional keys and no others.
class JsonObject {
 public:
  /// Throws InputError when `obj` is not an object, lacks a required key or has an unknown one.
  JsonObject(const nlohmann::json& obj, std::string where, std::initializer_list<const char*> required,
             std::initializer_list<const char*> optional);
  bool has(const char* key) const { return obj_.contains(key); }
  const nlohmann::json& at(const char* key) const { return obj_.at(key); }
  std::string path(const char* key) const { return key_path(where_, key); }
  const std::string& where() const { return where_; }

 private:
  const nlohmann::json& obj_;
  std::string where_;
};

}  // namespace ssimarch
