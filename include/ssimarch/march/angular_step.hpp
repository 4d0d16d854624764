// Barnhill & Kersey's angular step (thesis §4.1.1, eq 4.1): L = dtheta * rho = dtheta / kappa,
// so that the tangent turns by about dtheta per step; kappa exact from the curve's jet.
#pragma once

#include "ssimarch/march/step_rule.hpp"

namespace ssimarch {

/// dtheta / kappa clamped to [L_min, L_max]; L_max where kappa = 0.
double angular_step_length(double turn_angle, double kappa, const StepBounds& b);

struct AngularFormula {
  static constexpr int kJetOrder = 2;
  static double length(double turn_angle, const CurveGeometry& f, const StepBounds& b) {
    return angular_step_length(turn_angle, f.kappa, b);
  }
};
using AngularStep = FormulaStep<AngularFormula>;

}  // namespace ssimarch
