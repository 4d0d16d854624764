// The thesis' adaptive step for the order-3 directions (thesis §4.4): the step whose order-3
// error term is delta, L = (6 delta/|alpha'''|)^(1/3) if tau != 0, (2 delta/kappa)^(1/2) if
// tau = 0, L_max if kappa = 0 too; |alpha'''| = sqrt(kappa^4 + kappa'^2 + kappa^2 tau^2).
#pragma once

#include "ssimarch/march/step_rule.hpp"

namespace ssimarch {

/// The thesis' L clamped to [L_min, L_max]. tau undetermined (NaN) counts as tau = 0.
double order3_step_length(double delta, double kappa, double kappa_prime, double tau, const StepBounds& b);

struct Order3Formula {
  static constexpr int kJetOrder = 3;
  static double length(double delta, const CurveGeometry& f, const StepBounds& b) {
    return order3_step_length(delta, f.kappa, f.kappa_prime, f.tau, b);
  }
};
using Order3Step = FormulaStep<Order3Formula>;

}  // namespace ssimarch
