// Stoyanov's deviation step (thesis §4.1.2): the step whose parabola deviates by D from its
// chord, D = kappa L^2 / (2 sqrt(1 + kappa^2 L^2)), i.e. L = D sqrt(2 (1 + sqrt(1 + 1/(D^2 kappa^2)))).
#pragma once

#include "ssimarch/march/step_rule.hpp"

namespace ssimarch {

/// Stoyanov's L clamped to [L_min, L_max]; L_max where kappa = 0.
double stoyanov_step_length(double D, double kappa, const StepBounds& b);

struct DeviationFormula {
  static constexpr int kJetOrder = 2;
  static double length(double D, const CurveGeometry& f, const StepBounds& b) {
    return stoyanov_step_length(D, f.kappa, b);
  }
};
using DeviationStep = FormulaStep<DeviationFormula>;

}  // namespace ssimarch
