#include "ssimarch/porosity/overlaps.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "spatial_grid.hpp"
#include "ssimarch/porosity/generator.hpp"

namespace ssimarch {

namespace {

// Extent of a particle from its centre: half its length plus its radius.
double reach(const Particle& p) { return p.half_length() + p.radius(); }

// Distance between the axes (segments; points for spheres): the particles overlap by the sum of the
// radii minus it.
double axis_distance(const Particle& a, const Particle& b) {
  if (a.length == 0 && b.length == 0) return (a.centre - b.centre).norm();
  return segment_distance(a.minus_cap(), a.plus_cap(), b.minus_cap(), b.plus_cap());
}

}  // namespace

double sphere_lens_volume(double a, double b, double distance) {
  constexpr double pi = std::numbers::pi;
  const double s = a + b;
  if (!(distance < s)) return 0.0;
  const double small = std::min(a, b);
  if (distance <= std::abs(a - b)) return 4.0 / 3.0 * pi * small * small * small;
  const double h = s - distance;
  return pi * h * h * (distance * distance + 2 * distance * s - 3 * (a - b) * (a - b)) / (12 * distance);
}

ParticleOverlaps find_overlaps(std::span<const Particle> particles, double relative_tolerance) {
  ParticleOverlaps out;
  if (particles.size() < 2) return out;
  // Level k holds the particles of reach in (2^(k-1), 2^k]; its cells have side 2^(k+1), so a
  // particle of level k meets the particles of level >= k in the 27 or so cells around it.
  std::map<int, internal::SpatialGrid> levels;
  std::vector<int> level_of(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const int k = std::ilogb(reach(particles[i])) + 1;
    level_of[i] = k;
    auto it = levels.try_emplace(k, std::ldexp(1.0, k + 1)).first;
    it->second.insert(particles[i].centre, static_cast<int>(i));
  }
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle& a = particles[i];
    for (auto it = levels.lower_bound(level_of[i]); it != levels.end(); ++it) {
      const double level_reach = std::ldexp(1.0, it->first);
      it->second.visit(a.centre, reach(a) + level_reach, [&](int j) {
        const auto ju = static_cast<std::size_t>(j);
        // Each pair once: from the lower level, or from the lower index within one level.
        if (level_of[ju] == level_of[i] && ju <= i) return;
        const Particle& b = particles[ju];
        const double d = axis_distance(a, b);
        const double depth = a.radius() + b.radius() - d;
        if (!(depth > relative_tolerance * std::min(a.diameter, b.diameter))) return;
        ++out.pairs;
        out.doubled_volume += sphere_lens_volume(a.radius(), b.radius(), d);
        if (depth > out.max_depth) {
          out.max_depth = depth;
          out.worst_first = static_cast<long>(std::min(i, ju));
          out.worst_second = static_cast<long>(std::max(i, ju));
        }
      });
    }
  }
  return out;
}

}  // namespace ssimarch
