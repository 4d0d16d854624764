// Monte Carlo reference for the radial profile: eps(r) is the fraction of the cylinder surface
// x^2 + y^2 = r^2, z in [z_min, z_max], outside all particles; it is estimated from M uniform random
// points on that surface with the point-in-spherocylinder test, with standard error
// sqrt(eps (1 - eps) / M) (binomial). Used by the tests (issue 5, check d) and by the benchmark as the
// "sampling" competitor of the exact method.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ssimarch/porosity/profile.hpp"

namespace ssimarch {

struct MonteCarloOptions {
  long samples_per_radius = 10000;
  std::uint64_t seed = 1;
  unsigned threads = 0;  ///< 0 = hardware concurrency
};

struct MonteCarloProfile {
  std::vector<double> x, porosity, std_error;
};

MonteCarloProfile monte_carlo_radial(std::span<const Particle> particles, const Container& c,
                                     std::span<const double> radii, const MonteCarloOptions& opt = {});

}  // namespace ssimarch
