// Step rules: how far the next step goes (spec/marching-directions.md §2, §3.1, §6; formulas and
// defaults in docs/marching.md). Every rule shares the protocol
//   step()                  the next step length h (model units, arc length)
//   start(frame)            at the first point of a branch
//   acceptable(report)      the rule's own test of a corrected step (chordal: sagitta <= delta)
//   accepted(report, frame) after an accepted step, with the curve's frame at the new point
//   rejected(report)        after a rejected step (report = null for a guard or corrector
//                           failure); false once h fell below min_step (the tracer stops)
// The branch-jump guards live in the tracer and apply to every rule.
#pragma once

#include <algorithm>
#include <cmath>
#include <variant>

#include "ssimarch/march/options.hpp"
#include "ssimarch/march/predictor.hpp"

namespace ssimarch {

/// Measurements of one corrected step.
struct StepReport {
  double h = 0;           // arc length the prediction advanced (model units)
  double chord = 0;       // |p_{i+1} - p_i|
  double turn = 0;        // angle between the unit tangents at both ends (radians)
  double correction = 0;  // |corrected - predicted| (model units)
  // Chordal deviation estimate: the sagitta (chord/2) tan(turn/4) of the circular arc with this
  // chord and turning angle; exact on circles, and to leading order 1/4 of the distance the
  // tangent predictor's guess has to be corrected (kappa L^2/8 vs kappa L^2/2).
  double sagitta = 0;
  int iterations = 0;
};
StepReport make_step_report(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, const Vec3& predicted, double h,
                            int iterations);

/// Bounds shared by the rules (model units).
struct StepBounds {
  double max_step = 0.05;  // L_max (constant rule: the nominal L)
  double min_rule = 5e-5;  // L_min: smallest proposal of an adaptive rule
  double min_step = 5e-9;  // below this the tracer gives up at a point
};

/// Constant step L; halved after a rejected step, doubled back towards L after an accepted one.
struct ConstantStep {
  StepBounds bounds;
  double h = 0.05;
  int jet_order() const { return 1; }
  double step() const { return h; }
  void start(const CurveFrame&) { h = bounds.max_step; }
  bool acceptable(const StepReport&) const { return true; }
  void accepted(const StepReport&, const CurveFrame&) { h = std::min(bounds.max_step, 2 * h); }
  bool rejected(const StepReport*) {
    h *= 0.5;
    return h >= bounds.min_step;
  }
};

/// The length an adaptive rule proposes at a point: a pure function of the local geometry.
/// Barnhill-Kersey (spec/marching-directions.md §2): L = dtheta * rho = dtheta / kappa.
double angular_step_length(double turn_angle, double kappa, const StepBounds& b);
/// Stoyanov (§3.1): L = D sqrt(2 (1 + sqrt(1 + 1/(D^2 kappa^2)))), i.e. D = kappa L^2 / (2 sqrt(1 + kappa^2 L^2)).
double stoyanov_step_length(double D, double kappa, const StepBounds& b);
/// Thesis §4.4: L = (6 delta/|alpha'''|)^(1/3) if tau != 0, (2 delta/kappa)^(1/2) if tau = 0,
/// L_max if kappa = 0 too; |alpha'''| = sqrt(kappa^4 + kappa'^2 + kappa^2 tau^2). Clamped to [L_min, L_max].
double order3_step_length(double delta, double kappa, double kappa_prime, double tau, const StepBounds& b);
/// Chordal: L = sqrt(8 delta / kappa), the chord whose sagitta on a circle of curvature kappa is delta.
double chordal_step_length(double delta, double kappa, const StepBounds& b);

/// A rule given by a formula of the local geometry (angular, deviation, order3): the formula at
/// every new point, growing at most 2x per accepted step; halved after a rejection.
struct FormulaStep {
  enum class Kind { kAngular, kDeviation, kOrder3 } kind = Kind::kAngular;
  StepBounds bounds;
  double parameter = 0.1;  // turn_angle (radians) or the deviation D / delta (model units)
  double h = 0.05;
  int jet_order() const { return kind == Kind::kOrder3 ? 3 : 2; }
  double step() const { return h; }
  double proposal(const CurveFrame& f) const;
  void start(const CurveFrame& f) { h = proposal(f); }
  bool acceptable(const StepReport&) const { return true; }
  void accepted(const StepReport& r, const CurveFrame& f) { h = std::min(proposal(f), 2 * r.h); }
  bool rejected(const StepReport*) {
    h *= 0.5;
    return h >= bounds.min_step;
  }
};

/// Chordal deviation controller: keeps every chord's sagitta <= delta. A step whose measured
/// sagitta exceeds delta is rejected and retried at h * max(0.2, 0.9 sqrt(delta/sagitta)).
/// After an accepted step the next h is 0.9 sqrt(8 delta / kappa_hat), kappa_hat the largest of
/// the curvature the last chord implies (8 sagitta / chord^2), the curvature at the new point,
/// and (jets of order >= 3) its first-order extrapolation kappa + kappa' h / 2 over the next
/// step; at most 2x the last step, clamped to [L_min, L_max].
struct ChordalStep {
  StepBounds bounds;
  double delta = 1e-3;
  double h = 0.05;
  int jet_order() const { return 2; }
  double step() const { return h; }
  void start(const CurveFrame& f);
  bool acceptable(const StepReport& r) const { return r.sagitta <= delta; }
  void accepted(const StepReport& r, const CurveFrame& f);
  bool rejected(const StepReport* r);
};

using AnyStepControl = std::variant<ConstantStep, FormulaStep, ChordalStep>;

/// The rule of `options` with its bounds resolved: `step_length`, `min_step_length`, `min_step`
/// and `deviation` must already be set (Tracer resolves the automatic zeros).
AnyStepControl make_step_control(const TraceOptions& options);

}  // namespace ssimarch
