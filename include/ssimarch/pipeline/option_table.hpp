// The one table of the trace options. From it come the keys of a scene's "options" object,
// their parsing and validation (io/scene.cpp), the flags of `ssimarch trace` and the option
// list of docs/scene-format.md (trace_options_markdown(); a test keeps the two equal).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/geometry/curve_spline.hpp"
#include "ssimarch/march/options.hpp"

namespace ssimarch {

/// Everything an intersection of a trace job is traced and decorated with.
struct TraceJobOptions {
  TraceOptions trace;                      // how the curve is marched (march/options.hpp)
  std::optional<GeometryMethod> geometry;  // differential geometry at every output point, by this method
  bool bspline = false;                    // a certified B-spline and p-curves per curve (geometry/curve_spline.hpp)
  CurveSplineOptions spline;               // its tolerance
  bool closed_form = true;  // answer primitive pairs with a closed form exactly (analytic/closed_form.hpp)
  bool hunt_isolated_points = true;  // TraceAllOptions::hunt_isolated_points (trace/trace_all.hpp)
  bool solid_topology = true;        // faces of one solid answered by their shared edges (pipeline/shared_boundary.hpp)
};

/// A value as the user wrote it: a JSON number, or text (a name such as "taylor", or a number
/// or an expression of the scene's constants such as "R/10"; a command-line value is text).
using OptionValue = std::variant<double, std::string>;

/// One option: its key, what it means, and the values it admits.
struct TraceOptionSpec {
  enum class Type { kChoice, kReal, kInteger };
  std::string_view key;          // scene key ("step_length")
  Type type = Type::kReal;
  std::string_view unit;         // "model length", "radians" or empty
  std::string_view default_text; // as the docs state it ("0 = automatic", "`taylor`")
  std::string_view help;         // what it means
  std::string rule;              // the admissible values ("a finite number >= 0 (0 = automatic)")
  std::vector<std::string> choices;  // kChoice: the names, in the order the docs list them
  std::string_view noun;         // kChoice: what a name names ("predictor", "step rule")

  /// "--step-length".
  std::string flag() const;
};

/// Every option, in the order of the docs.
const std::vector<TraceOptionSpec>& trace_option_table();
/// The option with this key, or nullptr.
const TraceOptionSpec* find_trace_option(std::string_view key);
/// The keys, for messages ("predictor, corrector, ...").
std::string trace_option_keys();

/// Parses `value` by the option's type and rule and stores it in *options. Numbers must be
/// finite and normal (no subnormal: a step of 1e-320 has no usable precision), integers whole
/// and in range (4294967297 is not 1), names among the choices. Throws InputError(where, ...)
/// with the rule, e.g. where = "scene.json: intersections[0].options.step_length" or
/// "--step-length".
void apply_trace_option(const TraceOptionSpec& spec, const OptionValue& value, const Constants& constants,
                        const std::string& where, TraceJobOptions* options);

/// Every option by its rule (for options set in code), then the rules between options
/// (min_step <= step_length, ...). Throws InputError(where [+ "." + key], ...).
void check_trace_options(const TraceJobOptions& options, const std::string& where);

/// The option as text in a scene or on the command line ("taylor", "0.05"), for help texts.
std::string option_value_text(const TraceOptionSpec& spec, const TraceJobOptions& options);

/// The Markdown table of docs/scene-format.md, "### Options" (one row per option).
std::string trace_options_markdown();

}  // namespace ssimarch
