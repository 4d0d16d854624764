// The automatic trace options resolved against the model (see resolved_options.hpp).
#include "ssimarch/march/resolved_options.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include "ssimarch/core/error.hpp"
#include "ssimarch/march/model_size.hpp"
#include "ssimarch/march/option_ranges.hpp"

namespace ssimarch {

namespace {

// The key an invalid option's error names: the first field out of its range (a subnormal
// step_length names step_length), else "options" for a rule between fields.
std::string_view invalid_option_key(const TraceOptions& o) {
  for (const TraceOptionRange& r : trace_option_ranges())
    if (!r.range.check(r.get(o), r.integer).empty()) return r.key;
  return "options";
}

}  // namespace

ResolvedTraceOptions resolve_trace_options(const TraceOptions& asked, double scale) {
  std::string error, key;
  if (!asked.is_valid(&error)) throw InputError(std::string(invalid_option_key(asked)), error);
  if (!fits_model(asked, scale, &key, &error)) throw InputError(key, error);
  ResolvedTraceOptions r{asked, 0, 0};
  TraceOptions& o = r.options;
  o.tolerance = resolved_tolerance(asked, scale);
  const bool adaptive = o.step != StepRule::kConstant;
  const double floor = step_floor(scale, o.tolerance);
  r.spacing = o.step_length > 0 ? o.step_length : std::max(scale / 100.0, floor);
  r.chord = o.step_length > 0 ? o.step_length : std::max(scale / 10.0, floor);
  if (o.step_length == 0) o.step_length = std::max(scale / (adaptive ? 10.0 : 100.0), floor);
  if (o.min_step_length == 0) o.min_step_length = std::max(1e-3 * o.step_length, floor);
  if (o.min_step == 0) o.min_step = std::max(1e-7 * o.step_length, floor);
  o.min_step = std::min(o.min_step, o.min_step_length);
  if (o.deviation == 0) o.deviation = 1e-4 * scale;
  return r;
}

}  // namespace ssimarch
