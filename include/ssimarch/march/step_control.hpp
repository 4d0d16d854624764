// The choice of step rule, which decides how far the next step goes (one file per rule;
// formulas, sources and defaults in docs/marching.md, "Step rules"; protocol in step_rule.hpp).
#pragma once

#include <variant>

#include "ssimarch/march/angular_step.hpp"
#include "ssimarch/march/chordal_step.hpp"
#include "ssimarch/march/constant_step.hpp"
#include "ssimarch/march/deviation_step.hpp"
#include "ssimarch/march/options.hpp"
#include "ssimarch/march/order3_step.hpp"
#include "ssimarch/march/step_rule.hpp"

namespace ssimarch {

using AnyStepControl = std::variant<ConstantStep, AngularStep, DeviationStep, Order3Step, ChordalStep>;

/// The rule of `options` with its bounds resolved: `step_length`, `min_step_length`, `min_step`
/// and `deviation` must already be set (Tracer resolves the automatic zeros).
AnyStepControl make_step_control(const TraceOptions& options);

}  // namespace ssimarch
