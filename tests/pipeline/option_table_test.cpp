// The option table: every option's validation (bad value -> InputError naming the file, the JSON
// path and the rule), the typed geometry option, and the docs' option list kept equal to it.
#include "ssimarch/pipeline/option_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/march/option_ranges.hpp"

namespace ssimarch {
namespace {

using ::testing::HasSubstr;

std::string scene_with_options(const std::string& options) {
  return R"({"constants": {"R": 2}, "surfaces": {"a": {"sphere": {"center": [0,0,0], "radius": 1}},
    "b": {"implicit": "z", "box": [[-2,2],[-2,2],[-2,2]]}},
    "intersections": [{"surfaces": ["a", "b"], "options": )" + options + "}]}";
}

std::string option_error(const std::string& key, const std::string& json_value) {
  try {
    parse_scene(scene_with_options("{\"" + key + "\": " + json_value + "}"), "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

struct BadValue {
  const char* key;
  const char* value;  // JSON
  const char* message;
};

// One or more bad values per option, each with the whole message (file, JSON path, rule, value).
const BadValue kBadValues[] = {
    {"predictor", "\"magic\"",
     "unknown predictor \"magic\" (known: tangent, circle, circle-wu-andrade, parabola, polynomial, helix, taylor)"},
    {"corrector", "\"guess\"", "unknown corrector \"guess\" (known: newton, projection)"},
    {"step", "\"big\"", "unknown step rule \"big\" (known: constant, angular, deviation, order3, chordal)"},
    {"step_length", "-1", "must be a finite number >= 0 (0 = automatic), got -1"},
    {"step_length", "1e-320",
     "must be a finite number >= 0 (0 = automatic), got the subnormal 1e-320 (below 2.2e-308 double precision loses "
     "digits)"},
    {"step_length", "\"R/0\"", "not finite"},
    {"min_step_length", "-0.5", "must be a finite number >= 0 (0 = automatic), got -0.5"},
    {"deviation", "\"-R\"", "must be a finite number >= 0 (0 = automatic), got -2"},
    {"turn_angle", "0", "must be a finite number in (0, 1.5], got 0"},
    {"turn_angle", "2", "must be a finite number in (0, 1.5], got 2"},
    {"min_step", "-1e-9", "must be a finite number >= 0 (0 = automatic), got -1e-09"},
    {"taylor_order", "4294967297", "must be an integer in [1, 8]; the orders of the curve jet, got 4294967297"},
    {"taylor_order", "2.5", "must be an integer in [1, 8]; the orders of the curve jet, got 2.5"},
    {"taylor_order", "0", "must be an integer in [1, 8]; the orders of the curve jet, got 0"},
    {"tolerance", "-1", "must be a finite number >= 0 (0 = automatic), got -1"},
    {"max_corrector_iterations", "1001", "must be an integer in [1, 1000], got 1001"},
    {"max_turn_angle", "4", "must be a finite number in (0, 3.14159]; below pi, got 4"},
    {"max_correction_ratio", "0", "must be a finite number > 0, got 0"},
    {"max_points", "1", "must be an integer in [2, 1e+15], got 1"},
    {"max_points", "1e300", "got 1e+300"},
    {"max_length", "0", "must be a finite number > 0, got 0"},
    {"start_samples", "201",
     "must be an integer in [2, 200]; each of the n^2 corrector runs costs up to about 0.3 ms (200: about 12 s; "
     "docs/reliability.md), got 201"},
    {"certified_start_points", "1", "expected a yes/no name (true or false), got a number"},
    {"certified_start_points", "\"maybe\"", "maybe"},
    {"closed_form", "0", "expected a yes/no name (true or false), got a number"},
    {"closed_form", "\"exact\"", "exact"},
    {"start_box_budget", "0", "must be an integer in [1, 1e+09], got 0"},
    {"hunt_isolated_points", "1", "expected a yes/no name (true or false), got a number"},
    {"hunt_isolated_points", "\"sometimes\"", "sometimes"},
    {"solid_topology", "0", "expected a yes/no name (true or false), got a number"},
    {"solid_topology", "\"often\"", "often"},
    {"geometry", "\"guesswork\"",
     "unknown geometry method \"guesswork\" (known: exact, ye-maekawa, willmore, stoyanov, estimate, barnhill-kersey, "
     "mixed)"},
    {"geometry", "true",
     "must be one of exact, ye-maekawa, willmore, stoyanov, estimate, barnhill-kersey, mixed, got a boolean"},
    {"bspline", "\"yes\"", "yes"},
    {"bspline", "1", "expected a yes/no name (true or false), got a number"},
    {"bspline_tolerance", "-1e-9", "must be a finite number >= 0 (0 = automatic), got -1e-09"},
};

TEST(OptionTable, EveryBadValueNamesTheFileThePathAndTheRule) {
  for (const BadValue& b : kBadValues) {
    const std::string where = std::string("s.json: intersections[0].options.") + b.key + ": ";
    const std::string e = option_error(b.key, b.value);
    EXPECT_THAT(e, HasSubstr(where)) << b.key << " = " << b.value;
    EXPECT_THAT(e, HasSubstr(b.message)) << b.key << " = " << b.value;
  }
  // Every option of the table has at least one bad value above.
  for (const TraceOptionSpec& o : trace_option_table()) {
    bool tested = false;
    for (const BadValue& b : kBadValues) tested = tested || o.key == b.key;
    EXPECT_TRUE(tested) << o.key;
  }
}

TEST(OptionTable, UnknownKeysAndRulesBetweenOptions) {
  EXPECT_THAT(option_error("step_lenght", "1"), HasSubstr("s.json: intersections[0].options.step_lenght: unknown option (known options: predictor, "));
  std::string e;
  try {
    parse_scene(scene_with_options(R"({"step_length": 0.1, "min_step": 0.5})"), "s.json");
  } catch (const InputError& err) {
    e = err.what();
  }
  EXPECT_EQ(e, "s.json: intersections[0].options: min_step must not exceed step_length");
}

TEST(OptionTable, ValuesAreTypedAndExpressionsUseTheConstants) {
  Scene s = parse_scene(scene_with_options(R"({"step_length": "R/40", "taylor_order": 6, "geometry": "ye-maekawa", "step": "constant"})"),
                        "s.json");
  const TraceJobOptions& o = s.intersections[0].options;
  EXPECT_EQ(o.trace.step_length, 0.05);
  EXPECT_EQ(o.trace.taylor_order, 6);
  EXPECT_EQ(o.trace.step, StepRule::kConstant);
  ASSERT_TRUE(o.geometry.has_value());
  EXPECT_EQ(*o.geometry, GeometryMethod::kYeMaekawa);
  EXPECT_FALSE(parse_scene(scene_with_options("{}"), "s.json").intersections[0].options.geometry.has_value());
  // Zero is the automatic value, not a subnormal or an out-of-range number.
  EXPECT_EQ(option_error("step_length", "0"), "(no error)");
  EXPECT_EQ(option_error("step_length", "-0.0"), "(no error)");
}

TEST(OptionTable, CommandLineTextIsParsedByTheSameRules) {
  TraceJobOptions o;
  const Constants c{{"R", 2.0}};
  apply_trace_option(*find_trace_option("step_length"), std::string("R/20"), c, "--step-length", &o);
  EXPECT_EQ(o.trace.step_length, 0.1);
  auto error = [&](const char* key, const std::string& text) {
    try {
      apply_trace_option(*find_trace_option(key), text, c, find_trace_option(key)->flag(), &o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error("step_length", "-1"), "--step-length: must be a finite number >= 0 (0 = automatic), got -1");
  // Non-finite spellings are numbers to the range check, not unknown names to the expression compiler.
  EXPECT_EQ(error("step_length", "nan"), "--step-length: must be a finite number >= 0 (0 = automatic), got a value that is not finite");
  EXPECT_THAT(error("step_length", "-inf"), HasSubstr("--step-length: must be a finite number >= 0"));
  EXPECT_THAT(error("tolerance", "-1"), HasSubstr("--tolerance: must be a finite number >= 0 (0 = automatic)"));
  EXPECT_THAT(error("deviation", "nan"), HasSubstr("--deviation: must be a finite number"));
  EXPECT_THAT(error("tolerance", "nan"), HasSubstr("--tolerance: must be a finite number >= 0 (0 = automatic)"));
  EXPECT_THAT(error("taylor_order", "4294967297"), HasSubstr("--taylor-order: must be an integer in [1, 8]"));
  EXPECT_THAT(error("predictor", "nonsense"), HasSubstr("--predictor: unknown predictor \"nonsense\""));
  EXPECT_EQ(error("max_points", "1e3"), "(no error)");
  EXPECT_EQ(o.trace.max_points, 1000);
  EXPECT_THROW(apply_trace_option(*find_trace_option("step_length"), std::numeric_limits<double>::quiet_NaN(), c, "x", &o),
               InputError);
  EXPECT_THROW(apply_trace_option(*find_trace_option("step_length"), std::numeric_limits<double>::infinity(), c, "x", &o),
               InputError);
  // max_length's default, +inf, means unbounded (a flag may write it as "inf"; JSON cannot).
  EXPECT_NO_THROW(apply_trace_option(*find_trace_option("max_length"), std::numeric_limits<double>::infinity(), c, "x", &o));
  EXPECT_THROW(apply_trace_option(*find_trace_option("max_length"), -std::numeric_limits<double>::infinity(), c, "x", &o),
               InputError);
}

TEST(OptionTable, FlagsAndKeysAreOneToOne) {
  EXPECT_EQ(find_trace_option("step_length")->flag(), "--step-length");
  EXPECT_EQ(find_trace_option("max_corrector_iterations")->flag(), "--max-corrector-iterations");
  EXPECT_EQ(find_trace_option("nope"), nullptr);
  const TraceJobOptions defaults;
  EXPECT_EQ(option_value_text(*find_trace_option("predictor"), defaults), "taylor");
  EXPECT_EQ(option_value_text(*find_trace_option("tolerance"), defaults), "0");  // automatic
  EXPECT_EQ(option_value_text(*find_trace_option("geometry"), defaults), "none");
}

// One statement of the ranges (march/option_ranges.hpp): the table's rule of every numeric field
// of TraceOptions is the one TraceOptions::is_valid checks, and both reject the same values.
TEST(OptionTable, TheTableAndTraceOptionsCheckOneRangePerField) {
  std::size_t numeric_rows = 0;
  for (const TraceOptionSpec& spec : trace_option_table()) {
    if (spec.type == TraceOptionSpec::Type::kChoice) continue;
    ++numeric_rows;
    const TraceOptionRange* field = find_trace_option_range(spec.key);
    if (spec.key == "bspline_tolerance") {  // a job option (the spline), not a field of the marching
      EXPECT_EQ(field, nullptr);
      continue;
    }
    ASSERT_NE(field, nullptr) << spec.key;
    EXPECT_EQ(spec.rule, field->range.rule(field->integer)) << spec.key;
  }
  EXPECT_EQ(numeric_rows, trace_option_ranges().size() + 1);
  // A value each rule rejects, set in code: is_valid names the field and says the table's rule.
  const std::pair<const char*, double> bad[] = {
      {"step_length", -1},         {"step_length", 1e-320},     {"min_step_length", -0.5},
      {"deviation", std::nan("")}, {"turn_angle", 2},           {"min_step", -1e-9},
      {"taylor_order", 9},         {"tolerance", -1e-16},       {"max_corrector_iterations", 0},
      {"max_turn_angle", 4},       {"max_correction_ratio", 0}, {"max_points", 1},
      {"max_length", 0},           {"start_samples", 201},      {"start_box_budget", 0}};
  std::size_t checked = 0;
  for (const TraceOptionRange& field : trace_option_ranges()) {
    TraceOptions o;
    std::string error;
    ASSERT_TRUE(o.is_valid(&error)) << error;
    for (const auto& [key, value] : bad) {
      if (field.key != key) continue;
      ++checked;
      field.set(o, value);
      ASSERT_FALSE(o.is_valid(&error)) << key << " = " << value;
      EXPECT_THAT(error, HasSubstr(std::string(key) + " must be " + find_trace_option(key)->rule)) << key;
      o = TraceOptions{};
    }
  }
  EXPECT_EQ(checked, std::size(bad));
  TraceOptions o;
  o.max_length = std::numeric_limits<double>::infinity();  // the default: no bound
  std::string error;
  EXPECT_TRUE(o.is_valid(&error)) << error;
}

// docs/scene-format.md's option list is the table's own (regenerate it with
// `ssimarch trace --list-options`).
TEST(OptionTable, TheDocsListEveryOptionAsTheTableDoes) {
  std::ifstream in(std::string(SSIMARCH_SOURCE_DIR) + "/docs/scene-format.md");
  ASSERT_TRUE(in) << "docs/scene-format.md";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string docs = ss.str();
  const std::string heading = "### Options\n\n";
  auto begin = docs.find(heading);
  ASSERT_NE(begin, std::string::npos);
  begin += heading.size();
  auto end = docs.find("\n\n", begin);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(docs.substr(begin, end + 1 - begin), trace_options_markdown());
}

}  // namespace
}  // namespace ssimarch
