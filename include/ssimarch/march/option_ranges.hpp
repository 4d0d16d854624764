// Every numeric trace option, spelled once: key, admissible values, unit, default and meaning.
// TraceOptions::is_valid checks options built in code by them; the option table
// (pipeline/option_table.cpp) takes these rows as they are, parses scene keys and command-line
// flags by them and states them in docs/scene-format.md.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/march/options.hpp"

namespace ssimarch {

/// Admissible numbers: lo <(=) x <(=) hi, or 0 where 0 asks for the automatic value.
struct OptionRange {
  double lo = 0, hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool zero_is_automatic = false;
  std::string_view why;                // appended to the rule: why the bound exists
  bool infinity_is_unbounded = false;  // +inf means "no bound" (the default of max_length)

  bool admits(double x) const;
  /// The rule as the docs and messages state it: "a finite number >= 0 (0 = automatic)",
  /// "an integer in [1, 8]; the orders of the curve jet".
  std::string rule(bool integer) const;
  /// Empty when x is admissible; else why not: "must be <rule>, got -1". Besides the range,
  /// a value must be finite (unless infinity_is_unbounded), not subnormal (a step of 1e-320 has
  /// no usable precision) and, where `integer`, whole (4294967297 is not 1).
  std::string check(double x, bool integer) const;
};

/// A numeric field of TraceOptions: its one row, from which the scene key, the CLI flag, the
/// Python keyword, the checks and the docs table come (pipeline/option_table.hpp adds the rows
/// of the choices, flags and job options, which march does not know).
struct TraceOptionRange {
  std::string_view key;  // "step_length"
  bool integer = false;
  OptionRange range;
  double (*get)(const TraceOptions&) = nullptr;
  void (*set)(TraceOptions&, double) = nullptr;
  std::string_view unit;          // "model length", "radians" or empty
  std::string_view default_text;  // as the docs state it ("0 = automatic")
  std::string_view help;          // what it means
};

/// Every numeric field of TraceOptions (the choices and flags have no range).
const std::vector<TraceOptionRange>& trace_option_ranges();
/// The field with this key, or nullptr.
const TraceOptionRange* find_trace_option_range(std::string_view key);

/// Shortest decimal text that reads back as x ("1e-09", "0.5").
std::string shortest_number(double x);

}  // namespace ssimarch
