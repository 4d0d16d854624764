#include "ssimarch/march/options.hpp"

#include "ssimarch/march/option_ranges.hpp"
#include "ssimarch/march/result.hpp"

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
  // Every numeric field by its range (march/option_ranges.cpp, the one statement of them), then
  // the rules between fields.
  for (const TraceOptionRange& r : trace_option_ranges()) {
    const std::string why = r.range.check(r.get(*this), r.integer);
    if (!why.empty()) return fail(std::string(r.key) + " " + why);
  }
  if (step_length > 0 && min_step > step_length) return fail("min_step must not exceed step_length");
  if (step_length > 0 && min_step_length > step_length) return fail("min_step_length must not exceed step_length");
  return true;
}

}  // namespace ssimarch
