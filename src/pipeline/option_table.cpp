// The trace options, each spelled once: key, unit, default, meaning, admissible values and the
// field it sets. Meanings and defaults: docs/marching.md (the strategies), docs/geometry.md.
#include "ssimarch/pipeline/option_table.hpp"

#include <charconv>
#include <functional>

#include "ssimarch/core/contract.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/core/text_cat.hpp"
#include "ssimarch/march/option_ranges.hpp"

namespace ssimarch {

namespace {

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
  OptionRange range;
  Setter set_number;
  ChoiceSetter set_choice;
  Getter get;
  std::function<double(const TraceJobOptions&)> number;  // kReal, kInteger: the value as a double
};

// A number of the marching: its row is march's (march/option_ranges.hpp: range, unit, default,
// meaning), the one TraceOptions::is_valid checks.
Row number_row(std::string_view key) {
  const TraceOptionRange* field = find_trace_option_range(key);
  SSIMARCH_EXPECTS(field, "trace option \"" + std::string(key) + "\" has no row in march/option_ranges.cpp");
  TraceOptionSpec spec = describe(field->key, field->unit, field->default_text, field->help);
  spec.type = field->integer ? TraceOptionSpec::Type::kInteger : TraceOptionSpec::Type::kReal;
  spec.rule = field->range.rule(field->integer);
  return Row{std::move(spec), field->range, [field](TraceJobOptions* o, double x) { field->set(o->trace, x); }, {},
             [field](const TraceJobOptions& o) { return shortest_number(field->get(o.trace)); },
             [field](const TraceJobOptions& o) { return field->get(o.trace); }};
}

template <class E>
Row choice_row(TraceOptionSpec spec, std::initializer_list<E> values, E TraceOptions::*field) {
  spec.type = TraceOptionSpec::Type::kChoice;
  for (E v : values) spec.choices.emplace_back(to_string(v));
  spec.rule = "one of " + internal::join_names(spec.choices);
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
  spec.rule = "one of " + internal::join_names(spec.choices);
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
  OptionRange range;
  range.zero_is_automatic = true;
  spec.type = TraceOptionSpec::Type::kReal;
  spec.rule = range.rule(false);
  return Row{std::move(spec), range, [](TraceJobOptions* o, double x) { o->spline.tolerance = x; }, {},
             [](const TraceJobOptions& o) { return shortest_number(o.spline.tolerance); },
             [](const TraceJobOptions& o) { return o.spline.tolerance; }};
}

std::vector<Row> make_rows() {
  using P = PredictorKind;
  using C = CorrectorKind;
  using S = StepRule;
  std::vector<Row> rows;
  rows.push_back(choice_row<P>(describe("predictor", "", "`taylor`", "where the next point is guessed (docs/marching.md)", "predictor"),
                               {P::kTangent, P::kCircle, P::kCircleWuAndrade, P::kParabola, P::kPolynomial, P::kHelix, P::kTaylor},
                               &TraceOptions::predictor));
  rows.push_back(choice_row<C>(describe("corrector", "", "`newton`", "how a guess is pulled onto the curve", "corrector"),
                               {C::kNewton, C::kProjection}, &TraceOptions::corrector));
  rows.push_back(choice_row<S>(describe("step", "", "`chordal`", "step rule", "step rule"),
                               {S::kConstant, S::kAngular, S::kDeviation, S::kOrder3, S::kChordal}, &TraceOptions::step));
  for (const char* key : {"step_length", "min_step_length", "deviation", "turn_angle", "min_step", "taylor_order",
                          "tolerance", "max_corrector_iterations", "max_turn_angle", "max_correction_ratio",
                          "max_points", "max_length", "start_samples"})
    rows.push_back(number_row(key));
  rows.push_back(flag_row(describe("certified_start_points", "", "true",
                                   "find start points by the certified interval search (docs/topology.md); false: by sampling",
                                   "yes/no"),
                          &TraceOptions::certified_start_points));
  rows.push_back(number_row("start_box_budget"));
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
  rows.push_back(job_flag_row(describe("solid_topology", "", "true",
                                       "answer two faces of one solid of a STEP model by the edges and vertices they "
                                       "share, which is all a valid solid's faces have in common (docs/cad.md, \"Faces "
                                       "of one solid\"); false: trace them",
                                       "yes/no"),
                              &TraceJobOptions::solid_topology));
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
  SSIMARCH_CONTRACT_FAILURE("trace option \"" + std::string(spec.key) + "\" is not in the table");
}

// A number given as text (a CLI flag, a scene's constant expression). A plain number, including
// "nan" and "inf" (which the expression language does not know), is read as one, so that the
// range check names the rule ("must be a finite number ...") rather than the expression compiler
// an unknown name.
double number_of(const OptionValue& value, const Constants& constants, const std::string& where) {
  if (const double* x = std::get_if<double>(&value)) return *x;
  const std::string& text = std::get<std::string>(value);
  double x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec == std::errc() && end == text.data() + text.size()) return x;
  return evaluate_constant(text, constants, where);
}

void check_number(const Row& row, double x, const std::string& where) {
  const std::string why = row.range.check(x, row.spec.type == TraceOptionSpec::Type::kInteger);
  if (!why.empty()) throw InputError(where, why);
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
  return internal::join_names(keys);
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
    throw InputError(where, "unknown " + std::string(spec.noun) + " \"" + *name +
                                "\" (known: " + internal::join_names(spec.choices) + ")");
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
