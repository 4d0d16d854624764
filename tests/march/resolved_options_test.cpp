// The automatic trace options resolved against the model (march/resolved_options.hpp): the
// values of docs/scene-format.md at a model of size 10, the constant rule's smaller step, an
// explicit step kept with its derived lengths, and the key an invalid option is reported under.
#include "ssimarch/march/resolved_options.hpp"

#include <gtest/gtest.h>

#include "ssimarch/core/error.hpp"

namespace ssimarch {
namespace {

TEST(ResolvedTraceOptions, AutomaticValuesAtSizeTen) {
  const ResolvedTraceOptions r = resolve_trace_options(TraceOptions{}, 10.0);
  EXPECT_DOUBLE_EQ(r.options.tolerance, 1e-12);  // 1e-13 x size
  EXPECT_DOUBLE_EQ(r.options.step_length, 1.0);  // size / 10, adaptive rule (chordal)
  EXPECT_DOUBLE_EQ(r.options.min_step_length, 1e-3);
  EXPECT_DOUBLE_EQ(r.options.min_step, 1e-7);
  EXPECT_DOUBLE_EQ(r.options.deviation, 1e-3);  // 1e-4 x size
  EXPECT_DOUBLE_EQ(r.spacing, 0.1);             // size / 100 whatever the rule
  TraceOptions constant;
  constant.step = StepRule::kConstant;
  EXPECT_DOUBLE_EQ(resolve_trace_options(constant, 10.0).options.step_length, 0.1);
}

TEST(ResolvedTraceOptions, AnExplicitStepIsKeptAndSetsTheSpacing) {
  TraceOptions o;
  o.step_length = 0.5;
  o.tolerance = 1e-10;
  const ResolvedTraceOptions r = resolve_trace_options(o, 10.0);
  EXPECT_EQ(r.options.step_length, 0.5);
  EXPECT_EQ(r.options.tolerance, 1e-10);
  EXPECT_DOUBLE_EQ(r.options.min_step_length, 5e-4);
  EXPECT_EQ(r.spacing, 0.5);
  // Resolving resolved options changes nothing but the spacing's source.
  EXPECT_EQ(resolve_trace_options(r.options, 10.0).options.min_step, r.options.min_step);
}

TEST(ResolvedTraceOptions, AnInvalidOptionNamesItsKey) {
  TraceOptions o;
  o.step_length = -1;
  try {
    resolve_trace_options(o, 10.0);
    FAIL() << "a negative step length was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "step_length");
  }
  try {
    resolve_trace_options(TraceOptions{}, 1e-200);
    FAIL() << "a model of size 1e-200 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "model size");
  }
}

}  // namespace
}  // namespace ssimarch
