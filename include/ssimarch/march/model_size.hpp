// What double precision supports for a model of a given size (docs/math/poles.md §3): the
// model size, the tolerance and every step length against the step floor, checked before any
// tracing (Tracer's constructor, pipeline/trace_job.cpp), and the floor the automatic step
// lengths are clamped to.
#pragma once

#include <string>

#include "ssimarch/march/options.hpp"

namespace ssimarch {

/// Model sizes (model units) whose squares and reciprocals stay normal doubles with room for
/// the products the surfaces form (a sphere of radius 1e-300 has r^2 = 0).
inline constexpr double kMinModelSize = 1e-100;
inline constexpr double kMaxModelSize = 1e100;
/// The corrector tolerance may not exceed this fraction of the model size (a tolerance larger
/// than the model makes every point of the box "on the curve").
inline constexpr double kMaxToleranceRatio = 1e-3;

/// The automatic corrector tolerance as a fraction of the model size (TraceOptions::tolerance = 0):
/// 1e-12 at the size 10 of the seeds' scenes, whose results the absolute default 1e-12 was judged
/// on, about 450 times the rounding of the coordinates (eps scale) at every size (issue 29: a
/// sphere of radius 2000 failed on the absolute default, which lay below its rounding).
inline constexpr double kAutomaticToleranceRatio = 1e-13;

/// The tolerance `options` asks for on a model of size `scale`: its own, or the automatic one.
double resolved_tolerance(const TraceOptions& options, double scale);

/// The shortest step that moves a point of a model of size `scale` traced to `tolerance` by a
/// measurable amount (model units): 8 tolerance (the chord of a step is compared with the step
/// to 1/4, and each end is known to the tolerance) or 64 eps scale (the coordinates' rounding),
/// whichever is larger. Never 0 for a valid model: the tracer's step rules never go below it.
double step_floor(double scale, double tolerance);

/// Checks `options` against a model of size `scale` (model units; Problem::scale()): the size
/// is in [kMinModelSize, kMaxModelSize], eps scale <= resolved_tolerance <= kMaxToleranceRatio
/// scale, and every length set (step_length, min_step_length, min_step,
/// max_length; 0 = automatic passes) is >= step_floor(scale, tolerance). On failure returns
/// false with the key at fault in *key ("model size", "tolerance", "step_length", ...) and the
/// rule with the usable range in *error.
bool fits_model(const TraceOptions& options, double scale, std::string* key, std::string* error);

}  // namespace ssimarch
