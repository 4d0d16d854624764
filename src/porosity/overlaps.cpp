// Overlapping pairs (overlaps.hpp) in one process: a hierarchical grid of cell indices, queried in
// parallel from every particle, each pair counted once from the particle first in (level, id).
#include "ssimarch/porosity/overlaps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "cell_index.hpp"
#include "overlap_search.hpp"
#include "parallel.hpp"
#include "ssimarch/porosity/generator.hpp"

namespace ssimarch {

namespace internal {

void PairTally::add(long i, long j, double d, double v) {
  ++pairs;
  volume.add(v);
  const long a = std::min(i, j), b = std::max(i, j);
  if (d > depth || (d == depth && (first < 0 || a < first || (a == first && b < second)))) {
    depth = d;
    first = a;
    second = b;
  }
}

void PairTally::merge(const PairTally& o) {
  pairs += o.pairs;
  volume += o.volume;
  if (o.first >= 0 && (first < 0 || o.depth > depth ||
                       (o.depth == depth && (o.first < first || (o.first == first && o.second < second))))) {
    depth = o.depth;
    first = o.first;
    second = o.second;
  }
}

void require_clump_per_particle(std::size_t clumps, std::size_t particles) {
  if (clumps != 0 && clumps != particles)
    throw std::invalid_argument("find_overlaps: " + std::to_string(clumps) + " clump ids for " +
                                std::to_string(particles) + " particles");
}

int overlap_level(const Particle& p) { return std::ilogb(reach(p)) + 1; }

std::map<int, GridLevel> grid_levels(std::span<const Particle> ps, std::vector<std::int16_t>* level_of) {
  std::map<int, std::vector<std::uint32_t>> members;
  std::map<int, GridLevel> levels;
  if (level_of) level_of->resize(ps.size());
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const int l = overlap_level(ps[k]);  // ilogb + 1 of a finite reach: within +-1100
    if (level_of) (*level_of)[k] = static_cast<std::int16_t>(l);
    GridLevel& L = levels[l];
    L.max_reach = std::max(L.max_reach, reach(ps[k]));
    members[l].push_back(static_cast<std::uint32_t>(k));
  }
  for (auto& [l, L] : levels)
    L.cells.emplace(2 * L.max_reach, members[l], [&](std::uint32_t m) -> const Vec3& { return ps[m].centre; });
  return levels;
}

PairOverlap pair_overlap(const Particle& a, const Particle& b) {
  const bool spheres = a.length == 0 && b.length == 0;
  const double s = a.radius() + b.radius();
  if (spheres && (a.centre - b.centre).squaredNorm() >= s * s) return {};  // the common case, no root
  const double d = spheres ? (a.centre - b.centre).norm()
                           : segment_distance(a.minus_cap(), a.plus_cap(), b.minus_cap(), b.plus_cap());
  return {s - d, d};
}

OverlapTallies search_overlaps(std::span<const Particle> ps, std::span<const long> ids, std::size_t owned,
                               double relative_tolerance, double volume_scale, unsigned threads,
                               std::span<const long> clumps) {
  auto id = [&](std::size_t k) { return ids.empty() ? static_cast<long>(k) : ids[k]; };
  std::vector<std::int16_t> level_of;
  const std::map<int, GridLevel> levels = grid_levels(ps, &level_of);
  // Each pair once: tested from the particle first in (level, id) (overlaps.hpp).
  auto before = [&](std::size_t a, std::size_t b) {
    return level_of[a] != level_of[b] ? level_of[a] < level_of[b] : id(a) < id(b);
  };
  auto test = [&](std::size_t i, std::size_t j, OverlapTallies& t) {
    const Particle &a = ps[i], &b = ps[j];
    const PairOverlap o = pair_overlap(a, b);
    if (o.depth > relative_tolerance * std::min(a.diameter, b.diameter)) {
      PairTally& to = !clumps.empty() && clumps[i] == clumps[j] ? t.within : t.between;
      to.add(id(i), id(j), o.depth, sphere_lens_volume(a.radius(), b.radius(), o.distance));
    }
  };
  // Queries in cell order, level after level: consecutive queries meet the same neighbours, which
  // stay in the cache whatever the order of the file. Chunks are ranges of that order.
  std::vector<const internal::CellIndex*> by_level;
  std::vector<std::size_t> level_start{0};
  for (const auto& [k, L] : levels) {
    by_level.push_back(&*L.cells);
    level_start.push_back(level_start.back() + L.cells->order().size());
  }
  const std::size_t nq = level_start.back();
  const int chunks = static_cast<int>(std::min<std::size_t>(kOverlapQueryChunks, std::max<std::size_t>(nq, 1)));
  const PairTally none{0, FixedPointSum(volume_scale)};
  std::vector<OverlapTallies> tally(static_cast<std::size_t>(chunks), OverlapTallies{none, none});
  internal::parallel_chunks(
      chunks, threads,
      [&](int c) {
        OverlapTallies& t = tally[static_cast<std::size_t>(c)];
        std::size_t lv = 0;
        for (std::size_t q = nq * static_cast<std::size_t>(c) / chunks; q < nq * static_cast<std::size_t>(c + 1) / chunks; ++q) {
          while (q >= level_start[lv + 1]) ++lv;
          const std::size_t i = by_level[lv]->order()[q - level_start[lv]];
          if (i >= owned) continue;  // a neighbour from another process: its own process asks
          for (auto it = levels.lower_bound(level_of[i]); it != levels.end(); ++it)
            it->second.cells->visit(ps[i].centre, reach(ps[i]) + it->second.max_reach, [&](std::uint32_t j) {
              if (before(i, j)) test(i, j, t);
            });
        }
      },
      nullptr);
  OverlapTallies out{none, none};
  for (const OverlapTallies& t : tally) {
    out.between.merge(t.between);
    out.within.merge(t.within);
  }
  return out;
}

}  // namespace internal

double sphere_lens_volume(double a, double b, double distance) {
  constexpr double pi = std::numbers::pi;
  const double s = a + b;
  if (!(distance < s)) return 0.0;
  const double small = std::min(a, b);
  if (distance <= std::abs(a - b)) return 4.0 / 3.0 * pi * small * small * small;
  const double h = s - distance;
  return pi * h * h * (distance * distance + 2 * distance * s - 3 * (a - b) * (a - b)) / (12 * distance);
}

ParticleOverlaps find_overlaps(std::span<const Particle> particles, double relative_tolerance, unsigned threads,
                               std::span<const long> clumps) {
  ParticleOverlaps out;
  if (particles.size() < 2) return out;
  internal::require_clump_per_particle(clumps.size(), particles.size());
  double vmax = 0;
  for (const Particle& p : particles) vmax = std::max(vmax, p.volume());
  const double scale = vmax > 0 ? vmax * static_cast<double>(particles.size()) : 1.0;
  const internal::OverlapTallies t =
      internal::search_overlaps(particles, {}, particles.size(), relative_tolerance, scale, threads, clumps);
  out.pairs = t.between.pairs;
  out.max_depth = t.between.depth;
  out.worst_first = t.between.first;
  out.worst_second = t.between.second;
  out.doubled_volume = t.between.volume.value();
  out.clump_pairs = t.within.pairs;
  out.clump_doubled_volume = t.within.volume.value();
  return out;
}

}  // namespace ssimarch
