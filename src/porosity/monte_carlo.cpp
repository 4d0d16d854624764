// Monte Carlo radial profile. Source: monte_carlo.hpp.
#include "ssimarch/porosity/monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "parallel.hpp"
#include "spatial_grid.hpp"
#include "ssimarch/porosity/circle_spherocylinder.hpp"

namespace ssimarch {

MonteCarloProfile monte_carlo_radial(std::span<const Particle> particles, const Container& c,
                                     std::span<const double> radii, const MonteCarloOptions& opt) {
  double reach = 0;
  for (const Particle& p : particles) reach = std::max(reach, p.radius() + p.half_length());
  internal::SpatialGrid grid(std::max(2 * reach, 1e-12));
  for (std::size_t i = 0; i < particles.size(); ++i) grid.insert(particles[i].centre, static_cast<int>(i));
  MonteCarloProfile out;
  out.x.assign(radii.begin(), radii.end());
  out.porosity.assign(radii.size(), 0.0);
  out.std_error.assign(radii.size(), 0.0);
  const double pi = std::numbers::pi;
  internal::parallel_chunks(
      static_cast<int>(radii.size()), opt.threads,
      [&](int j) {
        std::mt19937_64 rng(opt.seed * 1000003ULL + static_cast<std::uint64_t>(j));
        std::uniform_real_distribution<double> U(0, 1);
        long inside = 0;
        const double r = radii[j];
        for (long k = 0; k < opt.samples_per_radius; ++k) {
          const double th = 2 * pi * U(rng);
          const Vec3 q(r * std::cos(th), r * std::sin(th), c.slab.z_min + (c.slab.z_max - c.slab.z_min) * U(rng));
          bool hit = false;
          grid.visit(q, reach, [&](int i) {
            if (!hit && inside_margin(particles[i], q) >= 0) hit = true;
          });
          inside += hit;
        }
        const double M = static_cast<double>(std::max(1L, opt.samples_per_radius));
        const double eps = 1 - inside / M;
        out.porosity[j] = eps;
        out.std_error[j] = std::sqrt(std::max(eps * (1 - eps), 1.0 / M) / M);
      },
      {});
  return out;
}

}  // namespace ssimarch
