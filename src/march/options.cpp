#include "ssimarch/march/options.hpp"

#include <cmath>

#include "ssimarch/march/result.hpp"
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

std::string_view to_string(PredictorKind k) {
  switch (k) {
    case PredictorKind::kTangent: return "tangent";
    case PredictorKind::kCircle: return "circle";
    case PredictorKind::kCircleWuAndrade: return "circle-wu-andrade";
    case PredictorKind::kParabola: return "parabola";
    case PredictorKind::kPolynomial: return "polynomial";
    case PredictorKind::kHelix: return "helix";
    case PredictorKind::kTaylor: return "taylor";
  }
  return "?";
}
std::string_view to_string(CorrectorKind k) {
  switch (k) {
    case CorrectorKind::kNewton: return "newton";
    case CorrectorKind::kProjection: return "projection";
  }
  return "?";
}
std::string_view to_string(StepRule k) {
  switch (k) {
    case StepRule::kConstant: return "constant";
    case StepRule::kAngular: return "angular";
    case StepRule::kDeviation: return "deviation";
    case StepRule::kOrder3: return "order3";
    case StepRule::kChordal: return "chordal";
  }
  return "?";
}
bool parse(std::string_view s, PredictorKind* out) {
  for (auto k : {PredictorKind::kTangent, PredictorKind::kCircle, PredictorKind::kCircleWuAndrade, PredictorKind::kParabola,
                 PredictorKind::kPolynomial, PredictorKind::kHelix, PredictorKind::kTaylor})
    if (s == to_string(k)) return *out = k, true;
  return false;
}
bool parse(std::string_view s, CorrectorKind* out) {
  for (auto k : {CorrectorKind::kNewton, CorrectorKind::kProjection})
    if (s == to_string(k)) return *out = k, true;
  return false;
}
bool parse(std::string_view s, StepRule* out) {
  for (auto k : {StepRule::kConstant, StepRule::kAngular, StepRule::kDeviation, StepRule::kOrder3, StepRule::kChordal})
    if (s == to_string(k)) return *out = k, true;
  return false;
}

std::string_view to_string(Termination t) {
  switch (t) {
    case Termination::kClosedLoop: return "closed_loop";
    case Termination::kLeftDomain: return "domain_edge";
    case Termination::kSingularPoint: return "singular_point";
    case Termination::kStepUnderflow: return "step_underflow";
    case Termination::kMaxPoints: return "max_points";
    case Termination::kMaxLength: return "max_length";
    case Termination::kReachedTracedCurve: return "traced_curve";
  }
  return "?";
}

TraceStats& TraceStats::operator+=(const TraceStats& o) {
  points += o.points;
  rejected_steps += o.rejected_steps;
  for (std::size_t i = 0; i < iterations.size(); ++i) iterations[i] += o.iterations[i];
  linearizations += o.linearizations;
  jet_evaluations += o.jet_evaluations;
  corrector_failures += o.corrector_failures;
  surface_evaluations[0] += o.surface_evaluations[0];
  surface_evaluations[1] += o.surface_evaluations[1];
  predictor_fallbacks += o.predictor_fallbacks;
  time_ms += o.time_ms;
  return *this;
}

bool TraceOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (!(step_length >= 0) || !std::isfinite(step_length)) return fail("step_length must be a finite number >= 0 (0 = automatic)");
  if (!(min_step >= 0) || !std::isfinite(min_step)) return fail("min_step must be a finite number >= 0 (0 = automatic)");
  if (step_length > 0 && min_step > step_length) return fail("min_step must not exceed step_length");
  if (!(min_step_length >= 0) || !std::isfinite(min_step_length)) return fail("min_step_length must be a finite number >= 0 (0 = automatic)");
  if (step_length > 0 && min_step_length > step_length) return fail("min_step_length must not exceed step_length");
  if (!(deviation >= 0) || !std::isfinite(deviation)) return fail("deviation must be a finite number >= 0 (0 = automatic)");
  if (!(turn_angle > 0 && turn_angle <= 1.5)) return fail("turn_angle must be in (0, 1.5] radians");
  if (taylor_order < 1 || taylor_order > kMaxCurveJetOrder) return fail("taylor_order must be between 1 and " + std::to_string(kMaxCurveJetOrder));
  if (!(tolerance > 0) || !std::isfinite(tolerance)) return fail("tolerance must be a finite number > 0");
  if (tolerance < 1e-15) return fail("tolerance below 1e-15 cannot be reached in double precision");
  if (max_corrector_iterations < 1 || max_corrector_iterations > 1000) return fail("max_corrector_iterations must be between 1 and 1000");
  if (!(max_turn_angle > 0 && max_turn_angle <= 3.14159)) return fail("max_turn_angle must be in (0, pi) radians");
  if (!(max_correction_ratio > 0) || !std::isfinite(max_correction_ratio)) return fail("max_correction_ratio must be a finite number > 0");
  if (max_points < 2) return fail("max_points must be at least 2");
  if (!(max_length > 0)) return fail("max_length must be > 0");
  if (start_samples < 2 || start_samples > 200) return fail("start_samples must be between 2 and 200");
  if (start_box_budget < 1) return fail("start_box_budget must be at least 1");
  return true;
}

}  // namespace ssimarch
