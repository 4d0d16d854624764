// Scene files: named constants, named surfaces and the intersections to trace (JSON; schema in
// docs/scene-format.md). Errors are InputError with the file and the JSON path or line:column.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/march/options.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// One entry of "intersections".
struct IntersectionSpec {
  std::string name;
  std::array<std::string, 2> surfaces;  // names as written in the scene
  PairKind kind = PairKind::kImplicitImplicit;
  bool swapped = false;                 // true when the Problem takes the surfaces in the other order
  std::vector<Vec3> starts;             // empty: find start points automatically
  TraceOptions options;
  nlohmann::json extra_options = nlohmann::json::object();  // option keys other modules read (e.g. "geometry")
};

struct Scene {
  std::string source;  // file name (for messages)
  expr::Constants constants;
  std::vector<std::string> surface_names;  // in file order
  std::map<std::string, Surface> surfaces;
  std::vector<IntersectionSpec> intersections;

  /// Throws InputError naming the known surfaces when `name` is unknown.
  const Surface& surface(const std::string& name) const;
  /// The Problem of an intersection (surfaces in the order its pair kind needs).
  Problem problem(const IntersectionSpec& spec) const;
};

/// Reads and validates a scene file. Throws InputError (missing file, JSON syntax error with
/// line and column, unknown keys, bad values with their JSON path).
Scene load_scene(const std::filesystem::path& path);
/// Same, from text; `source` names it in messages.
Scene parse_scene(const std::string& text, const std::string& source);

/// Pair kind of two surfaces: both implicit-capable -> implicit-implicit; one -> parametric-
/// implicit (the implicit-capable one used implicitly); none -> parametric-parametric.
/// `as` ("parametric"/"implicit" per surface) overrides. *swapped tells whether the Problem
/// takes them in the other order (parametric first).
PairKind choose_pair_kind(const Surface& a, const Surface& b, const std::optional<std::array<std::string, 2>>& as,
                          const std::string& where, bool* swapped);

/// Applies the keys of an "options" object to TraceOptions (numbers may be expressions using
/// the constants). Unknown keys are an error unless listed in `passthrough`, whose values go
/// into *extra. Keys: docs/scene-format.md.
void apply_trace_options(const nlohmann::json& options, const expr::Constants& constants, const std::string& where,
                         TraceOptions* out, nlohmann::json* extra);

/// Option keys accepted by apply_trace_options, for help texts and error messages.
const std::vector<std::string>& trace_option_keys();

/// A JSON value that is a number or an expression string, as a double. Throws InputError.
double number_from_json(const nlohmann::json& j, const expr::Constants& constants, const std::string& where);

}  // namespace ssimarch
