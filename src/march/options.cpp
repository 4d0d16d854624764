#include "ssimarch/march/options.hpp"

#include <cmath>

#include "ssimarch/march/predictor.hpp"
#include "ssimarch/march/result.hpp"

namespace ssimarch {

std::string_view to_string(PredictorKind k) {
  switch (k) {
    case PredictorKind::kTangent: return "tangent";
    case PredictorKind::kTaylor: return "taylor";
  }
  return "?";
}
std::string_view to_string(CorrectorKind k) {
  switch (k) {
    case CorrectorKind::kNewton: return "newton";
  }
  return "?";
}
std::string_view to_string(StepRule k) {
  switch (k) {
    case StepRule::kConstant: return "constant";
  }
  return "?";
}
bool parse(std::string_view s, PredictorKind* out) {
  for (auto k : {PredictorKind::kTangent, PredictorKind::kTaylor})
    if (s == to_string(k)) return *out = k, true;
  return false;
}
bool parse(std::string_view s, CorrectorKind* out) {
  for (auto k : {CorrectorKind::kNewton})
    if (s == to_string(k)) return *out = k, true;
  return false;
}
bool parse(std::string_view s, StepRule* out) {
  for (auto k : {StepRule::kConstant})
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
  if (taylor_order < 1 || taylor_order > 8) return fail("taylor_order must be between 1 and 8");
  if (!(tolerance > 0) || !std::isfinite(tolerance)) return fail("tolerance must be a finite number > 0");
  if (tolerance < 1e-15) return fail("tolerance below 1e-15 cannot be reached in double precision");
  if (max_corrector_iterations < 1 || max_corrector_iterations > 1000) return fail("max_corrector_iterations must be between 1 and 1000");
  if (!(max_turn_angle > 0 && max_turn_angle <= 3.14159)) return fail("max_turn_angle must be in (0, pi) radians");
  if (!(max_correction_ratio > 0) || !std::isfinite(max_correction_ratio)) return fail("max_correction_ratio must be a finite number > 0");
  if (max_points < 2) return fail("max_points must be at least 2");
  if (!(max_length > 0)) return fail("max_length must be > 0");
  if (start_samples < 2 || start_samples > 1000) return fail("start_samples must be between 2 and 1000");
  return true;
}

AnyPredictor make_predictor(const TraceOptions& options) {
  switch (options.predictor) {
    case PredictorKind::kTaylor: return TaylorPredictor{options.taylor_order};
    case PredictorKind::kTangent: break;
  }
  return TangentPredictor{};
}
int jet_order(const AnyPredictor& p) {
  return std::visit([](const auto& x) { return x.jet_order(); }, p);
}
VecX predict(const AnyPredictor& p, const Problem& problem, const MarchState& s, double h) {
  return std::visit([&](const auto& x) { return x.predict(problem, s, h); }, p);
}

}  // namespace ssimarch
