// Trace options resolved against a model: every automatic value (0 = automatic) replaced by the
// value used, once, after the options are checked (TraceOptions::is_valid) and checked against
// the model (fits_model). The tracer marches with them and the output's `options` reports them,
// so what is reported is what was used (issue 25).
#pragma once

#include "ssimarch/march/options.hpp"

namespace ssimarch {

struct ResolvedTraceOptions {
  /// No automatic value left: tolerance = kAutomaticToleranceRatio x size; step_length = size/10
  /// (adaptive rules) or size/100 (constant); min_step_length = 1e-3 step_length; min_step =
  /// 1e-7 step_length, at most min_step_length; deviation = 1e-4 size; the lengths never below
  /// step_floor (a step that cannot move the point would loop without end).
  TraceOptions options;
  /// The spacing of the sampled start points: the step length asked for, else size/100 (model
  /// units), whatever the step rule.
  double spacing = 0;
  /// The largest chord of a curve sampled without marching (a closed form's conics): the step
  /// length asked for, else size/10 whatever the step rule (the constant rule's automatic step,
  /// size/100, is a march's, not a sample's), never below step_floor. Model units.
  double chord = 0;
};

/// Checks `asked` and resolves it for a model of size `scale` (Problem::scale()). Throws
/// InputError whose `where` is the key at fault ("step_length", "tolerance", "model size", or
/// "options" for a rule between keys) with the rule and the usable range.
ResolvedTraceOptions resolve_trace_options(const TraceOptions& asked, double scale);

}  // namespace ssimarch
