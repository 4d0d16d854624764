// The trace options, each spelled once: key, unit, default, meaning, admissible values and the
// field it sets. Meanings and defaults: docs/marching.md (the strategies), docs/geometry.md.
#include "ssimarch/pipeline/option_table.hpp"

#include <charconv>
#include <cmath>
#include <functional>
#include <limits>

#include "ssimarch/core/error.hpp"
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& x : names) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// Admissible numbers: lo <(=) x <(=) hi, or 0 where 0 asks for the automatic value.
struct Range {
  double lo = 0, hi = kInf;
  bool lo_open = false, hi_open = false;
  bool zero_is_automatic = false;
  std::string_view why;  // appended to the rule, e.g. why a bound exists
  bool infinity_is_unbounded = false;  // the default +inf means "no bound" (a file cannot write inf)

  bool admits(double x) const {
    if (zero_is_automatic && x == 0) return true;
    return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  }
};

std::string shortest(double x) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string range_rule(const Range& r, bool integer) {
  std::string s = integer ? "an integer" : "a finite number";
  if (r.hi == kInf) s += (r.lo_open ? " > " : " >= ") + shortest(r.lo);
  else s += std::string(" in ") + (r.lo_open ? "(" : "[") + shortest(r.lo) + ", " + shortest(r.hi) + (r.hi_open ? ")" : "]");
  if (r.zero_is_automatic) s += " (0 = automatic)";
  if (!r.why.empty()) s += "; " + std::string(r.why);
  return s;
}

TraceOptionSpec describe(std::string_view key, std::string_view unit, std::string_view default_text, std::string_view help,
                         std::string_view noun = {}) {
  TraceOptionSpec s;
  s.key = key;
  s.unit = unit;
  s.default_text = default_text;
  s.help = help;
  s.noun = noun;
  return s;
}

using Setter = std::function<void(TraceJobOptions*, double)>;
using ChoiceSetter = std::function<bool(TraceJobOptions*, std::string_view)>;
using Getter = std::function<std::string(const TraceJobOptions&)>;

struct Row {
  TraceOptionSpec spec;
  Range range;
  Setter set_number;
  ChoiceSetter set_choice;
  Getter get;
  std::function<double(const TraceJobOptions&)> number;  // kReal, kInteger: the value as a double
};

template <class T>
Row number_row(TraceOptionSpec spec, Range range, T TraceOptions::*field) {
  const bool integer = std::is_integral_v<T>;
  spec.type = integer ? TraceOptionSpec::Type::kInteger : TraceOptionSpec::Type::kReal;
  spec.rule = range_rule(range, integer);
  return Row{std::move(spec), range,
             [field](TraceJobOptions* o, double x) { o->trace.*field = static_cast<T>(x); }, {},
             [field](const TraceJobOptions& o) { return shortest(static_cast<double>(o.trace.*field)); },
             [field](const TraceJobOptions& o) { return static_cast<double>(o.trace.*field); }};
}

template <class E>
Row choice_row(TraceOptionSpec spec, std::initializer_list<E> values, E TraceOptions::*field) {
  spec.type = TraceOptionSpec::Type::kChoice;
  for (E v : values) spec.choices.emplace_back(to_string(v));
  spec.rule = "one of " + join(spec.choices);
  return Row{std::move(spec), {}, {},
             [field](TraceJobOptions* o, std::string_view s) { return parse(s, &(o->trace.*field)); },
             [field](const TraceJobOptions& o) { return std::string(to_string(o.trace.*field)); }, {}};
}

// A yes/no option: a choice between "true" and "false" (a scene may write JSON true/false).
// `field(options)` is the flag's reference in a const or non-const TraceJobOptions.
template <class Field>
Row yes_no_row(TraceOptionSpec spec, Field field) {
  spec.type = TraceOptionSpec::Type::kChoice;
  spec.choices = {"true", "false"};
  spec.rule = "true or false";
  return Row{std::move(spec), {}, {},
             [field](TraceJobOptions* o, std::string_view s) {
               if (s != "true" && s != "false") return false;
               field(*o) = s == "true";
               return true;
             },
             [field](const TraceJobOptions& o) { return std::string(field(o) ? "true" : "false"); }, {}};
}

// A flag of the marching (TraceOptions).
Row flag_row(TraceOptionSpec spec, bool TraceOptions::*field) {
  return yes_no_row(std::move(spec), [field](auto& o) -> auto& { return o.trace.*field; });
}

// A flag of the job (TraceJobOptions itself): which engine answers.
Row job_flag_row(TraceOptionSpec spec, bool TraceJobOptions::*field) {
  return yes_no_row(std::move(spec), [field](auto& o) -> auto& { return o.*field; });
}

Row geometry_row() {
  TraceOptionSpec spec = describe("geometry", "", "none",
                                  "add t, n, b, kappa, tau, kappa_prime, theta to each output point, by this method "
                                  "(docs/geometry.md)",
                                  "geometry method");
  spec.type = TraceOptionSpec::Type::kChoice;
  for (auto m : {GeometryMethod::kExact, GeometryMethod::kYeMaekawa, GeometryMethod::kWillmore,
                 GeometryMethod::kStoyanov, GeometryMethod::kEstimate,
                 GeometryMethod::kBarnhillKersey, GeometryMethod::kMixed})
    spec.choices.emplace_back(to_string(m));
  spec.rule = "one of " + join(spec.choices);
  return Row{std::move(spec), {}, {},
             [](TraceJobOptions* o, std::string_view s) {
               GeometryMethod m;
               if (!parse(s, &m)) return false;
               o->geometry = m;
               return true;
             },
             [](const TraceJobOptions& o) { return o.geometry ? std::string(to_string(*o.geometry)) : "none"; },
             {}};
}

// The certified B-spline output (geometry/curve_spline.hpp): opt-in, and its tolerance.
Row bspline_row() {
  TraceOptionSpec spec = describe("bspline", "", "false",
                                  "add to each curve a degree-5 B-spline, its p-curves and `max_deviation`, the measured "
                                  "bound on their distance from the true curve (docs/math/curve_spline.md); "
                                  "`--format step` turns it on",
                                  "yes/no");
  return job_flag_row(std::move(spec), &TraceJobOptions::bspline);
}

Row bspline_tolerance_row() {
  TraceOptionSpec spec = describe("bspline_tolerance", "model length", "0 = 1e-9 extent",
                                  "the B-spline and each p-curve's image stay within this of the true curve; pieces "
                                  "whose measured distance exceeds it are halved at an exact curve point");
  const Range range{0, kInf, false, false, true, {}};
  spec.type = TraceOptionSpec::Type::kReal;
  spec.rule = range_rule(range, false);
  return Row{std::move(spec), range, [](TraceJobOptions* o, double x) { o->spline.tolerance = x; }, {},
             [](const TraceJobOptions& o) { return shortest(o.spline.tolerance); },
             [](const TraceJobOptions& o) { return o.spline.tolerance; }};
}

std::vector<Row> make_rows() {
  using P = PredictorKind;
  using C = CorrectorKind;
  using S = StepRule;
  const Range auto_length{0, kInf, false, false, true, {}};
  std::vector<Row> rows;
  rows.push_back(choice_row<P>(describe("predictor", "", "`taylor`", "where the next point is guessed (docs/marching.md)", "predictor"),
                               {P::kTangent, P::kCircle, P::kCircleWuAndrade, P::kParabola, P::kPolynomial, P::kHelix, P::kTaylor},
                               &TraceOptions::predictor));
  rows.push_back(choice_row<C>(describe("corrector", "", "`newton`", "how a guess is pulled onto the curve", "corrector"),
                               {C::kNewton, C::kProjection}, &TraceOptions::corrector));
  rows.push_back(choice_row<S>(describe("step", "", "`chordal`", "step rule", "step rule"),
                               {S::kConstant, S::kAngular, S::kDeviation, S::kOrder3, S::kChordal}, &TraceOptions::step));
  rows.push_back(number_row(describe("step_length", "model length", "0 = automatic", "the constant rule's step L; the adaptive rules' largest step. Automatic: extent/100 (constant), "
                              "extent/10 (adaptive), extent = diagonal of the problem's region"),
                            auto_length, &TraceOptions::step_length));
  rows.push_back(number_row(describe("min_step_length", "model length", "0 = 1e-3 step_length", "smallest step an adaptive rule proposes"),
                            auto_length, &TraceOptions::min_step_length));
  rows.push_back(number_row(describe("deviation", "model length", "0 = 1e-4 extent", "chordal deviation delta: the `chordal` rule keeps each chord's midpoint within delta of the curve"),
                            auto_length, &TraceOptions::deviation));
  rows.push_back(number_row(describe("turn_angle", "radians", "0.1", "the `angular` rule's tangent turn per step"),
                            Range{0, 1.5, true, false, false, {}}, &TraceOptions::turn_angle));
  rows.push_back(number_row(describe("min_step", "model length", "0 = 1e-7 step_length", "below this the tracer stops at the point and reports why"),
                            auto_length, &TraceOptions::min_step));
  rows.push_back(number_row(describe("taylor_order", "", "4", "order of the `taylor` predictor"),
                            Range{1, static_cast<double>(kMaxCurveJetOrder), false, false, false, "the orders of the curve jet"},
                            &TraceOptions::taylor_order));
  rows.push_back(number_row(describe("tolerance", "model length", "1e-12", "a point is accepted when its distance from both surfaces is at most this"),
                            Range{1e-15, kInf, false, false, false, "smaller cannot be reached in double precision"},
                            &TraceOptions::tolerance));
  rows.push_back(number_row(describe("max_corrector_iterations", "", "12", "Newton updates per point"),
                            Range{1, 1000, false, false, false, {}}, &TraceOptions::max_corrector_iterations));
  rows.push_back(number_row(describe("max_turn_angle", "radians", "0.6", "a step turning the tangent by more is rejected and retried shorter (branch-jump guard)"),
                            Range{0, 3.14159, true, false, false, "below pi"}, &TraceOptions::max_turn_angle));
  rows.push_back(number_row(describe("max_correction_ratio", "", "0.5", "a step whose corrected point is farther than this times the step from the prediction is rejected"),
                            Range{0, kInf, true, false, false, {}}, &TraceOptions::max_correction_ratio));
  rows.push_back(number_row(describe("max_points", "", "200000", "per curve"),
                            Range{2, 1e15, false, false, false, {}}, &TraceOptions::max_points));
  rows.push_back(number_row(describe("max_length", "model length", "unbounded", "per curve"),
                            Range{0, kInf, true, false, false, {}, true}, &TraceOptions::max_length));
  rows.push_back(number_row(describe("start_samples", "", "24", "samples per parameter direction (per axis, at most 16, for implicit pairs) when searching "
                              "start points by sampling; cost: n^2 corrector runs (n^3 for implicit pairs)"),
                            Range{2, 200, false, false, false,
                                  "each of the n^2 corrector runs costs up to about 0.3 ms (200: about 12 s; docs/reliability.md)"},
                            &TraceOptions::start_samples));
  rows.push_back(flag_row(describe("certified_start_points", "", "true",
                                   "find start points by the certified interval search (docs/topology.md); false: by sampling",
                                   "yes/no"),
                          &TraceOptions::certified_start_points));
  rows.push_back(number_row(describe("start_box_budget", "", "5000",
                                     "boxes the certified search examines per square system before it reports the rest "
                                     "as `uncertain_regions`"),
                            Range{1, 1e9, false, false, false, {}}, &TraceOptions::start_box_budget));
  rows.push_back(job_flag_row(describe("closed_form", "", "true",
                                       "answer pairs of primitives with an exact intersection (a plane and a quadric, "
                                       "coaxial surfaces of revolution, two spheres, a cylinder or cone and a quadric) in "
                                       "closed form, as conics or curves of exact points "
                                       "(docs/math/closed_form_quadrics.md); false: trace them",
                                       "yes/no"),
                              &TraceJobOptions::closed_form));
  rows.push_back(job_flag_row(describe("hunt_isolated_points", "", "true",
                                       "report the isolated points and the curves of tangential contact no traced curve "
                                       "meets, hunted where the start-point search left uncertain regions (docs/singular.md)",
                                       "yes/no"),
                              &TraceJobOptions::hunt_isolated_points));
  rows.push_back(geometry_row());
  rows.push_back(bspline_row());
  rows.push_back(bspline_tolerance_row());
  return rows;
}

const std::vector<Row>& rows() {
  static const std::vector<Row> r = make_rows();
  return r;
}

const Row& row_of(const TraceOptionSpec& spec) {
  for (const Row& r : rows())
    if (r.spec.key == spec.key) return r;
  throw std::logic_error("trace option \"" + std::string(spec.key) + "\" is not in the table");
}

double number_of(const OptionValue& value, const Constants& constants, const std::string& where) {
  if (const double* x = std::get_if<double>(&value)) return *x;
  return evaluate_constant(std::get<std::string>(value), constants, where);
}

void check_number(const Row& row, double x, const std::string& where) {
  const bool integer = row.spec.type == TraceOptionSpec::Type::kInteger;
  if (row.range.infinity_is_unbounded && x == kInf) return;
  if (!std::isfinite(x)) throw InputError(where, "must be " + row.spec.rule + ", got a value that is not finite");
  if (x != 0 && std::fabs(x) < std::numeric_limits<double>::min())
    throw InputError(where, "must be " + row.spec.rule + ", got the subnormal " + shortest(x) +
                                " (below 2.2e-308 double precision loses digits)");
  if (integer && x != std::floor(x)) throw InputError(where, "must be " + row.spec.rule + ", got " + shortest(x));
  if (!row.range.admits(x)) throw InputError(where, "must be " + row.spec.rule + ", got " + shortest(x));
}

}  // namespace

std::string TraceOptionSpec::flag() const {
  std::string f = "--" + std::string(key);
  for (char& c : f)
    if (c == '_') c = '-';
  return f;
}

const std::vector<TraceOptionSpec>& trace_option_table() {
  static const std::vector<TraceOptionSpec> table = [] {
    std::vector<TraceOptionSpec> t;
    for (const Row& r : rows()) t.push_back(r.spec);
    return t;
  }();
  return table;
}

const TraceOptionSpec* find_trace_option(std::string_view key) {
  for (const TraceOptionSpec& s : trace_option_table())
    if (s.key == key) return &s;
  return nullptr;
}

std::string trace_option_keys() {
  std::vector<std::string> keys;
  for (const TraceOptionSpec& s : trace_option_table()) keys.emplace_back(s.key);
  return join(keys);
}

void apply_trace_option(const TraceOptionSpec& spec, const OptionValue& value, const Constants& constants,
                        const std::string& where, TraceJobOptions* options) {
  const Row& row = row_of(spec);
  if (spec.type != TraceOptionSpec::Type::kChoice) {
    const double x = number_of(value, constants, where);
    check_number(row, x, where);
    row.set_number(options, x);
    return;
  }
  const std::string* name = std::get_if<std::string>(&value);
  if (!name) throw InputError(where, "expected a " + std::string(spec.noun) + " name (" + spec.rule + "), got a number");
  if (!row.set_choice(options, *name))
    throw InputError(where, "unknown " + std::string(spec.noun) + " \"" + *name + "\" (known: " + join(spec.choices) + ")");
}

void check_trace_options(const TraceJobOptions& options, const std::string& where) {
  // Every value by its own rule (options built in code have not been through apply_trace_option),
  // then the rules between values.
  for (const Row& row : rows())
    if (row.number) check_number(row, row.number(options), where + "." + std::string(row.spec.key));
  std::string error;
  if (!options.trace.is_valid(&error)) throw InputError(where, error);
}

std::string option_value_text(const TraceOptionSpec& spec, const TraceJobOptions& options) { return row_of(spec).get(options); }

std::string trace_options_markdown() {
  // Appended piece by piece (GCC 12 warns falsely on chains of std::string + under -O3, bug 105651).
  auto cell = [](std::string* row, const std::string& text) {
    row->append(text.empty() ? "| " : "| ");
    row->append(text);
    if (!text.empty()) row->append(" ");
  };
  std::string s = "| key | unit | default | values | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const TraceOptionSpec& o : trace_option_table()) {
    std::string values;
    if (o.type != TraceOptionSpec::Type::kChoice) values = o.rule;
    for (const std::string& c : o.choices) {
      values.append(values.empty() ? "`" : ", `");
      values.append(c);
      values.append("`");
    }
    std::string key = "`";
    key.append(o.key);
    key.append("`");
    for (const std::string& text : {key, std::string(o.unit), std::string(o.default_text), values, std::string(o.help)})
      cell(&s, text);
    s.append("|\n");
  }
  return s;
}

}  // namespace ssimarch
