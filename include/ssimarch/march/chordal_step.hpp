// Chordal deviation controller (docs/marching.md, "chordal"): keeps every chord's sagitta
// <= delta. A step whose measured sagitta exceeds delta is rejected and retried at
// h * max(0.2, 0.9 sqrt(delta/sagitta)). After an accepted step the next h is
// 0.9 sqrt(8 delta / kappa_hat), kappa_hat the largest of the curvature the last chord implies
// (8 sagitta / chord^2), the curvature at the new point, and (jets of order >= 3, where kappa'
// is determined) its first-order extrapolation kappa + kappa' h / 2 over the next step; at most
// 2x the last step, clamped to [L_min, L_max].
#pragma once

#include "ssimarch/march/step_rule.hpp"

namespace ssimarch {

/// L = sqrt(8 delta / kappa), the chord whose sagitta on a circle of curvature kappa is delta.
double chordal_step_length(double delta, double kappa, const StepBounds& b);

struct ChordalStep {
  StepBounds bounds;
  double delta = 1e-3;
  double h = 0.05;
  int jet_order() const { return 2; }
  double step() const { return h; }
  void start(const CurveGeometry& f);
  bool acceptable(const StepReport& r) const { return r.sagitta <= delta; }
  void accepted(const StepReport& r, const CurveGeometry& f);
  bool rejected(const StepReport* r);
};

}  // namespace ssimarch
