// Options of the marching tracer. Every tolerance states its unit and the inequality it enters;
// docs/marching.md gives every strategy's formula and source.
#pragma once

#include <limits>
#include <string>
#include <string_view>

namespace ssimarch {

/// Where the next point is guessed (thesis ch. 4; seed 000 §3; docs/marching.md).
enum class PredictorKind {
  kTangent,           // "tangent": x + L x'(0), i.e. P + L t (Barnhill et al.); point error O(L^2)
  kCircle,            // "circle": seed 000's circular step through the last two points; O(L^2), O(L^3) where kappa' = 0
  kCircleWuAndrade,   // "circle-wu-andrade": thesis' circle, centre from three planes, angle heuristic; O(L^3)
  kParabola,          // "parabola": Stoyanov's P + L t + (L^2/2) kappa n; O(L^3)
  kPolynomial,        // "polynomial": thesis' order-3 polynomial (t, n, b, kappa, kappa', tau); O(L^4)
  kHelix,             // "helix": thesis' osculating helix (corrected); O(L^4) where kappa' = 0, else O(L^3)
  kTaylor,            // "taylor": x(s) to order taylor_order in parameter space (implicit function theorem)
};
/// How a guess is pulled onto the curve.
enum class CorrectorKind {
  kNewton,      // "newton": Gauss-Newton with the Moore-Penrose pseudo-inverse (minimum-norm update)
  kProjection,  // "projection": seed 000 section 2: nearest points, tangent-plane line, midpoint
};
/// How far to step.
enum class StepRule {
  kConstant,   // "constant": L = step_length, halved on a rejected step, doubled back after an accepted one
  kAngular,    // "angular": Barnhill-Kersey, L = turn_angle / kappa
  kDeviation,  // "deviation": Stoyanov, L = D sqrt(2 (1 + sqrt(1 + 1/(D^2 kappa^2)))), D = deviation
  kOrder3,     // "order3": thesis section 4.4, L = (6 delta/|alpha'''|)^(1/3) (tau != 0) or (2 delta/kappa)^(1/2)
  kChordal,    // "chordal": controller keeping every chord's sagitta <= deviation, with reject/retry
};

std::string_view to_string(PredictorKind k);
std::string_view to_string(CorrectorKind k);
std::string_view to_string(StepRule k);
bool parse(std::string_view s, PredictorKind* out);
bool parse(std::string_view s, CorrectorKind* out);
bool parse(std::string_view s, StepRule* out);

struct TraceOptions {
  // Defaults chosen by the comparison in docs/benchmarks.md ("Marching").
  PredictorKind predictor = PredictorKind::kTaylor;
  CorrectorKind corrector = CorrectorKind::kNewton;
  StepRule step = StepRule::kChordal;

  // Step length (model units). The constant rule's L; for the adaptive rules (angular,
  // deviation, order3, chordal) the largest step L_max. 0 = automatic: scale()/100 for the
  // constant rule, scale()/10 for the adaptive ones (scale() = diagonal of the problem's region).
  double step_length = 0.0;
  // Smallest step an adaptive rule proposes, L_min (model units); the thesis' order-3 rule
  // clamps to [0.001, 0.2]. 0 = automatic: 1e-3 * L_max. The guards may still go below it.
  double min_step_length = 0.0;
  // Smallest step tried before the tracer gives up at a point (model units). 0 = automatic:
  // 1e-7 * step_length.
  double min_step = 0.0;
  // Geometric tolerance of the adaptive rules (model units): the chordal rule keeps every
  // chord's sagitta (distance of the chord's midpoint from the curve) <= deviation; Stoyanov's
  // rule uses it as D; the order-3 rule as the thesis' delta (0.001 there).
  // 0 = automatic: 1e-4 * scale().
  double deviation = 0.0;
  // Barnhill-Kersey angular tolerance (radians): the angular rule turns the tangent by about
  // this much per step (L = turn_angle * radius of curvature).
  double turn_angle = 0.1;
  // Order of the Taylor predictor (1..8; 1..6 are tested).
  int taylor_order = 4;

  // Corrector: a point is accepted when its distance from both surfaces (first-order estimate,
  // |H| for parametric pairs, |g|/|grad g| for implicit ones) is <= tolerance (model units).
  // 0 = automatic: kAutomaticToleranceRatio * scale() (march/model_size.hpp), so that a model
  // in millimetres and the same model in metres are traced alike (issue 29).
  double tolerance = 0.0;
  // Corrector: at most this many updates (Newton steps or projection rounds) per point.
  int max_corrector_iterations = 12;

  // Branch-jump guards, on every step rule: a step is rejected (and retried shorter) when
  //   angle(t_i, t_{i+1}) > max_turn_angle (radians), or
  //   |corrected - predicted| > max_correction_ratio * h (h = the predicted arc), or
  //   the chord |p_{i+1} - p_i| is outside [0.25 h, 1.75 h].
  double max_turn_angle = 0.6;
  double max_correction_ratio = 0.5;

  // Bounds that guarantee termination.
  long max_points = 200000;  // per curve
  double max_length = std::numeric_limits<double>::infinity();  // per curve (model units)

  // Automatic start points: samples per parameter direction (parametric surfaces) or per axis
  // of the box (implicit-implicit pairs).
  int start_samples = 24;
  // Automatic start points found by the certified search (docs/topology.md) when both surfaces
  // evaluate on intervals; false: by sampling (start_samples) only.
  bool certified_start_points = true;
  // Boxes the certified search examines per square system before it reports the rest as
  // uncertain regions.
  long start_box_budget = 5000;

  /// Checks every field; on failure returns false and says which field and why.
  bool is_valid(std::string* error) const;
};

}  // namespace ssimarch
