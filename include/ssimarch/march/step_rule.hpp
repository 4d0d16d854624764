// What every step rule shares (docs/marching.md, "Step rules"). A rule is a small value with
//   step()                  the next step length h (model units, arc length)
//   start(frame)            at the first point of a branch
//   acceptable(report)      the rule's own test of a corrected step (chordal: sagitta <= delta)
//   accepted(report, frame) after an accepted step, with the curve's frame at the new point
//   rejected(report)        after a rejected step (report = null for a guard or corrector
//                           failure); false once h fell below min_step (the tracer stops)
// The frame is the curve's Frenet data from its jet (geometry/curve_geometry.hpp,
// frenet_from_jet: NaN where undetermined). The branch-jump guards live in the tracer and apply
// to every rule.
#pragma once

#include <algorithm>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/geometry/curve_geometry.hpp"

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

/// L clamped to [L_min, L_max]; L_max where L is NaN (no usable geometry; the guards follow).
double clamp_step(double L, const StepBounds& b);

/// A rule given by a formula of the local geometry (angular, deviation, order3): the formula at
/// every new point, growing at most 2x per accepted step; halved after a rejection. `Formula`
/// supplies kJetOrder and length(parameter, frame, bounds).
template <class Formula>
struct FormulaStep {
  StepBounds bounds;
  double parameter = 0.1;  // turn_angle (radians) or the deviation D / delta (model units)
  double h = 0.05;
  int jet_order() const { return Formula::kJetOrder; }
  double step() const { return h; }
  double proposal(const CurveGeometry& f) const { return Formula::length(parameter, f, bounds); }
  void start(const CurveGeometry& f) { h = proposal(f); }
  bool acceptable(const StepReport&) const { return true; }
  void accepted(const StepReport& r, const CurveGeometry& f) { h = std::min(proposal(f), 2 * r.h); }
  bool rejected(const StepReport*) {
    h *= 0.5;
    return h >= bounds.min_step;
  }
};

}  // namespace ssimarch
