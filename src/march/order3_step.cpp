#include "ssimarch/march/order3_step.hpp"

#include <cmath>

namespace ssimarch {

namespace {
// The thesis' "tau = 0": |tau| <= kPlanarTorsion * (kappa + |kappa'|^(1/2) + 1), i.e. torsion at
// rounding level for the curve's own scales (dimensionless factor). A NaN tau (undetermined:
// straight curve or a jet of order 2) fails the test below and takes the planar branch.
constexpr double kPlanarTorsion = 1e-9;
}  // namespace

double order3_step_length(double delta, double kappa, double kappa_prime, double tau, const StepBounds& b) {
  if (std::fabs(tau) > kPlanarTorsion * (kappa + std::sqrt(std::fabs(kappa_prime)) + 1)) {
    const double a3 = std::sqrt(std::pow(kappa, 4) + kappa_prime * kappa_prime + kappa * kappa * tau * tau);
    return a3 > 0 ? clamp_step(std::cbrt(6 * delta / a3), b) : b.max_step;
  }
  if (!(kappa > 0)) return b.max_step;
  return clamp_step(std::sqrt(2 * delta / kappa), b);
}

}  // namespace ssimarch
