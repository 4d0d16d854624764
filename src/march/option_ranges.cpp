// The ranges of the numeric trace options (march/options.hpp says what each option means).
#include "ssimarch/march/option_ranges.hpp"

#include <charconv>
#include <cmath>
#include <type_traits>
#include <utility>

#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A length where 0 asks for the automatic value (derived from the model's size).
OptionRange automatic_length() {
  OptionRange r;
  r.zero_is_automatic = true;
  return r;
}

OptionRange at_least(double lo, bool open, std::string_view why = {}) {
  OptionRange r;
  r.lo = lo;
  r.lo_open = open;
  r.why = why;
  return r;
}

OptionRange between(double lo, double hi, bool lo_open, std::string_view why = {}) {
  OptionRange r = at_least(lo, lo_open, why);
  r.hi = hi;
  return r;
}

template <auto Field>
using FieldType = std::remove_cvref_t<decltype(std::declval<TraceOptions&>().*Field)>;

// One numeric option: its key, range, unit ("" for none), default as the docs state it, meaning.
template <auto Field>
TraceOptionRange field(std::string_view key, OptionRange range, std::string_view unit, std::string_view default_text,
                       std::string_view help) {
  return TraceOptionRange{key,
                          std::is_integral_v<FieldType<Field>>,
                          range,
                          [](const TraceOptions& o) { return static_cast<double>(o.*Field); },
                          [](TraceOptions& o, double x) { o.*Field = static_cast<FieldType<Field>>(x); },
                          unit,
                          default_text,
                          help};
}

std::vector<TraceOptionRange> make_ranges() {
  using O = TraceOptions;
  OptionRange unbounded_length = at_least(0, true);
  unbounded_length.infinity_is_unbounded = true;
  constexpr std::string_view kLength = "model length", kRadians = "radians";
  return {
      field<&O::step_length>("step_length", automatic_length(), kLength, "0 = automatic",
                             "the constant rule's step L; the adaptive rules' largest step. Automatic: extent/100 "
                             "(constant), extent/10 (adaptive), extent = diagonal of the problem's region"),
      field<&O::min_step_length>("min_step_length", automatic_length(), kLength, "0 = 1e-3 step_length",
                                 "smallest step an adaptive rule proposes"),
      field<&O::deviation>("deviation", automatic_length(), kLength, "0 = 1e-4 extent",
                           "chordal deviation delta: the `chordal` rule keeps each chord's midpoint within delta of "
                           "the curve"),
      field<&O::turn_angle>("turn_angle", between(0, 1.5, true), kRadians, "0.1",
                            "the `angular` rule's tangent turn per step"),
      field<&O::min_step>("min_step", automatic_length(), kLength, "0 = 1e-7 step_length",
                          "below this the tracer stops at the point and reports why"),
      field<&O::taylor_order>("taylor_order", between(1, kMaxCurveJetOrder, false, "the orders of the curve jet"), "",
                              "4", "order of the `taylor` predictor"),
      field<&O::tolerance>("tolerance", automatic_length(), kLength, "0 = 1e-13 extent",
                           "a point is accepted when its distance from both surfaces is at most this; the automatic "
                           "value scales with the model, so the same part in millimetres or metres is traced alike"),
      field<&O::max_corrector_iterations>("max_corrector_iterations", between(1, 1000, false), "", "12",
                                          "Newton updates per point"),
      field<&O::max_turn_angle>("max_turn_angle", between(0, 3.14159, true, "below pi"), kRadians, "0.6",
                                "a step turning the tangent by more is rejected and retried shorter (branch-jump "
                                "guard)"),
      field<&O::max_correction_ratio>("max_correction_ratio", at_least(0, true), "", "0.5",
                                      "a step whose corrected point is farther than this times the step from the "
                                      "prediction is rejected"),
      field<&O::max_points>("max_points", between(2, 1e15, false), "", "200000", "per curve"),
      field<&O::max_length>("max_length", unbounded_length, kLength, "unbounded", "per curve"),
      // The sampling search costs n^2 corrector runs (start/start_points.cpp; docs/reliability.md).
      field<&O::start_samples>("start_samples",
                               between(2, 200, false,
                                       "each of the n^2 corrector runs costs up to about 0.3 ms (200: about 12 s; "
                                       "docs/reliability.md)"),
                               "", "24",
                               "samples per parameter direction (per axis, at most 16, for implicit pairs) when "
                               "searching start points by sampling; cost: n^2 corrector runs (n^3 for implicit "
                               "pairs)"),
      field<&O::start_box_budget>("start_box_budget", between(1, 1e9, false), "", "5000",
                                  "boxes the certified search examines per square system before it reports the rest "
                                  "as `uncertain_regions`"),
  };
}

}  // namespace

bool OptionRange::admits(double x) const {
  if (zero_is_automatic && x == 0) return true;
  return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
}

std::string OptionRange::rule(bool integer) const {
  std::string s = integer ? "an integer" : "a finite number";
  if (hi == kInf) s += (lo_open ? " > " : " >= ") + shortest_number(lo);
  else
    s += std::string(" in ") + (lo_open ? "(" : "[") + shortest_number(lo) + ", " + shortest_number(hi) +
         (hi_open ? ")" : "]");
  if (zero_is_automatic) s += " (0 = automatic)";
  if (!why.empty()) s += "; " + std::string(why);
  return s;
}

std::string OptionRange::check(double x, bool integer) const {
  if (infinity_is_unbounded && x == kInf) return {};
  const std::string must = "must be " + rule(integer);
  if (!std::isfinite(x)) return must + ", got a value that is not finite";
  if (x != 0 && std::fabs(x) < std::numeric_limits<double>::min())
    return must + ", got the subnormal " + shortest_number(x) + " (below 2.2e-308 double precision loses digits)";
  if ((integer && x != std::floor(x)) || !admits(x)) return must + ", got " + shortest_number(x);
  return {};
}

const std::vector<TraceOptionRange>& trace_option_ranges() {
  static const std::vector<TraceOptionRange> r = make_ranges();
  return r;
}

const TraceOptionRange* find_trace_option_range(std::string_view key) {
  for (const TraceOptionRange& r : trace_option_ranges())
    if (r.key == key) return &r;
  return nullptr;
}

std::string shortest_number(double x) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace ssimarch
