#include "ssimarch/march/angular_step.hpp"

namespace ssimarch {

double angular_step_length(double turn_angle, double kappa, const StepBounds& b) {
  if (!(kappa > 0)) return b.max_step;
  return clamp_step(turn_angle / kappa, b);
}

}  // namespace ssimarch
