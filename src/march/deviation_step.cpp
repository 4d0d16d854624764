#include "ssimarch/march/deviation_step.hpp"

#include <cmath>

namespace ssimarch {

double stoyanov_step_length(double D, double kappa, const StepBounds& b) {
  if (!(kappa > 0)) return b.max_step;
  const double q = 1.0 / (D * D * kappa * kappa);
  return clamp_step(D * std::sqrt(2 * (1 + std::sqrt(1 + q))), b);
}

}  // namespace ssimarch
