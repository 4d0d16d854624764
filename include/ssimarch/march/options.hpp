// Options of the marching tracer. Every tolerance states its unit and the inequality it enters.
#pragma once

#include <limits>
#include <string>
#include <string_view>

namespace ssimarch {

/// Where the next point is guessed (spec/marching-directions.md).
enum class PredictorKind {
  kTangent,  // P + L t (Barnhill et al.), contact order 1
  kTaylor,   // x(s) Taylor polynomial of order `taylor_order` in parameter space (implicit function theorem)
};
/// How a guess is pulled onto the curve.
enum class CorrectorKind {
  kNewton,  // Gauss-Newton with the Moore-Penrose pseudo-inverse (minimum-norm update)
};
/// How far to step.
enum class StepRule {
  kConstant,  // L, halved on a rejected step, doubled back towards L after an accepted one
};

std::string_view to_string(PredictorKind k);
std::string_view to_string(CorrectorKind k);
std::string_view to_string(StepRule k);
bool parse(std::string_view s, PredictorKind* out);
bool parse(std::string_view s, CorrectorKind* out);
bool parse(std::string_view s, StepRule* out);

struct TraceOptions {
  PredictorKind predictor = PredictorKind::kTangent;
  CorrectorKind corrector = CorrectorKind::kNewton;
  StepRule step = StepRule::kConstant;

  // Nominal step: arc length between consecutive points (model units). 0 = automatic:
  // scale() / 100, the problem's 3D extent over 100.
  double step_length = 0.0;
  // Smallest step tried before the tracer gives up at a point (model units). 0 = automatic:
  // 1e-7 * step_length.
  double min_step = 0.0;
  // Order of the Taylor predictor (1..8).
  int taylor_order = 4;

  // Corrector: a point is accepted when its distance from both surfaces (first-order estimate,
  // |H| for parametric pairs, |g|/|grad g| for implicit ones) is <= tolerance (model units).
  double tolerance = 1e-12;
  // Corrector: at most this many Newton updates per point.
  int max_corrector_iterations = 12;

  // Branch-jump guards: a step is rejected (and retried shorter) when
  //   angle(t_i, t_{i+1}) > max_turn_angle (radians), or
  //   |corrected - predicted| > max_correction_ratio * h, or
  //   the chord |p_{i+1} - p_i| is outside [0.25 h, 1.75 h].
  double max_turn_angle = 0.6;
  double max_correction_ratio = 0.5;

  // Bounds that guarantee termination.
  long max_points = 200000;  // per curve
  double max_length = std::numeric_limits<double>::infinity();  // per curve (model units)

  // Automatic start points: samples per parameter direction (parametric surfaces) or per axis
  // of the box (implicit-implicit pairs).
  int start_samples = 24;

  /// Checks every field; on failure returns false and says which field and why.
  bool is_valid(std::string* error) const;
};

}  // namespace ssimarch
