// The overlap search of overlaps.hpp on one process's particles (internal to porosity): the
// particles are numbered by `ids` (their indices in the whole packing), and only pairs tested
// from the first `owned` of them are counted; the others are neighbours from other processes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "cell_index.hpp"

#include "ssimarch/porosity/fixed_point_sum.hpp"
#include "ssimarch/porosity/particle.hpp"
#include "ssimarch/porosity/particle_union.hpp"
#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch::internal {

// Chunks of the queries of the overlap search and of the overlap groups: a fixed count, so the
// work splits the same way for any thread count (the tally is exact anyway: integer counts and
// sums, a total order on the worst pair).
constexpr int kOverlapQueryChunks = 256;

/// Overlapping pairs found so far: count, doubled volume, and the deepest pair (ties: smallest ids).
struct PairTally {
  long pairs = 0;
  FixedPointSum volume;
  double depth = 0.0;
  long first = -1, second = -1;

  /// A pair of depth `d` between the particles numbered i and j, lens volume v.
  void add(long i, long j, double d, double v);
  void merge(const PairTally& o);
};

/// Throws std::invalid_argument unless `clumps` is empty or has one id per particle (find_overlaps).
void require_clump_per_particle(std::size_t clumps, std::size_t particles);

/// Grid level of a particle: the power of two above its reach (centre to farthest point).
int overlap_level(const Particle& p);

/// Reach of a particle: half its length plus its radius (centre to farthest point).
inline double reach(const Particle& p) { return p.half_length() + p.radius(); }

/// One level of the hierarchical grid: its particles (reach in (2^(k-1), 2^k]) in cells of twice
/// their largest reach, so that a query from a particle no larger meets at most 3 x 3 x 3 cells.
struct GridLevel {
  double max_reach = 0.0;
  std::optional<CellIndex> cells;
};

/// The levels of the particles, by overlap_level; `level_of` (when given) receives each particle's.
std::map<int, GridLevel> grid_levels(std::span<const Particle> particles,
                                     std::vector<std::int16_t>* level_of = nullptr);

/// How deep two particles overlap: depth = sum of the radii - distance of their axis segments
/// (centres, for spheres), and that distance. Two spheres farther apart than the sum of their
/// radii are rejected without a square root: depth 0.
struct PairOverlap {
  double depth = 0.0, distance = 0.0;
};
PairOverlap pair_overlap(const Particle& a, const Particle& b);

/// Pairs (a, b) with a among the first `owned` particles, (level, id) of a before that of b, and
/// depth above relative_tolerance times the smaller diameter. `ids` empty: particle k is numbered k.
/// The doubled volume is summed with the quantum of FixedPointSum(volume_scale). With `clumps`
/// (one id per particle, Packing::clumps), pairs within one clump are tallied apart.
struct OverlapTallies {
  PairTally between;  ///< pairs of different particles
  PairTally within;   ///< pairs of spheres of one clumped particle
};
OverlapTallies search_overlaps(std::span<const Particle> particles, std::span<const long> ids, std::size_t owned,
                               double relative_tolerance, double volume_scale, unsigned threads,
                               std::span<const long> clumps = {});

/// The particles one process searches (overlap_slabs.cpp): those of its slab of the bed, then its
/// neighbours from the slabs beside, each with its index in the packing.
struct SlabShare {
  std::vector<Particle> local;
  std::vector<long> ids;
  std::vector<long> clumps;   ///< clump id of each of local (Packing::clumps); empty when the packing has none
  std::size_t owned = 0;      ///< local[0, owned) lie in this process's slab
  long total = 0;             ///< particles over all processes
  double volume_scale = 1.0;  ///< largest particle volume times total (the quantum of volume sums)
};

/// Moves the particles of `share` (indices first, first + 1, ...) to the processes of their slabs
/// and of the slabs within reach, with their clump ids when `clumps` (one per particle of the share)
/// is given on any process. Collective.
SlabShare gather_slab(std::span<const Particle> share, long first, const ProfileCommunicator& comm,
                      std::span<const long> clumps = {});

/// The overlap groups (particle_union.hpp) of the first `owned` particles: for each, the
/// particles with a smaller id that overlap it, split into components by their lenses' boxes;
/// members index `particles`, which the set holds when `held` is given (moved in).
OverlapGroupSet groups_of(std::span<const Particle> particles, std::span<const long> ids, std::size_t owned,
                          double relative_tolerance, unsigned threads, std::vector<Particle>* held = nullptr);

}  // namespace ssimarch::internal
