// Overlaps between the particles of a packing. The exact porosity integrates each particle on its
// own, so a volume shared by two particles is counted twice: the porosity is then too low and may
// fall below 0 (three coincident spheres: -1.6 at their centre). A packing from a soft-sphere DEM
// has small overlaps by construction; a wrong file (diameters for radii, a repeated snapshot) has
// large ones. The porosity job reports them (docs/porosity.md, "Overlapping particles"); under MPI
// each process searches a slab of the bed (docs/scaling.md, "Overlap search").
#pragma once

#include <span>

#include "ssimarch/porosity/particle.hpp"
#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch {

/// Overlap depth, relative to the smaller diameter, above which two particles overlap: a shallower
/// contact is a contact, and its lens (volume below pi d^3 t^2 / 8 for depth t d) is far below any
/// profile's accuracy.
inline constexpr double kOverlapRelativeTolerance = 1e-9;

struct ParticleOverlaps {
  long pairs = 0;            ///< pairs of particles whose overlap depth exceeds the tolerance
  double max_depth = 0.0;    ///< largest overlap depth d_i/2 + d_j/2 - (distance of the axes), model length
  /// The pair of max_depth (0-based indices in the packing, first < second; of several pairs of
  /// equal depth the smallest (first, second)), -1 when none.
  long worst_first = -1, worst_second = -1;
  /// Volume counted twice, model length^3: exact for pairs of spheres (the lens between them), the
  /// lens of the two caps' spheres nearest each other for spherocylinders (a lower bound). A triple
  /// overlap counts each pair. Summed exactly (FixedPointSum, 96 bits below the packing's count
  /// times its largest particle volume): the same bits for any thread or process count.
  double doubled_volume = 0.0;
  /// Overlaps inside clumped particles (Packing::clumps): pairs of spheres of one particle, which
  /// overlap by design, and the volume they share. They are not in `pairs`, the worst pair or
  /// `doubled_volume`, which are between particles; the union counts their common volume once all
  /// the same.
  long clump_pairs = 0;
  double clump_doubled_volume = 0.0;
};

/// Every overlapping pair, found in O(n) expected time for particles of similar size by a
/// hierarchical grid (one level per power of two of the particle extent, each pair tested from the
/// level of its smaller particle), on `threads` workers (0: the library's thread count). A pair
/// overlaps when its depth exceeds `relative_tolerance` times the smaller diameter (contacts are
/// not overlaps). `clumps`: empty, or one clump id per particle (Packing::clumps), whose pairs
/// within one clump go to clump_pairs; std::invalid_argument when its size is neither.
ParticleOverlaps find_overlaps(std::span<const Particle> particles,
                               double relative_tolerance = kOverlapRelativeTolerance, unsigned threads = 0,
                               std::span<const long> clumps = {});

/// The same over a packing split among processes: this process holds `share`, the particles
/// first, first + 1, ... of the packing (read_packing_share). The processes exchange their
/// particles so that each holds a slab of the bed (cut at quantiles of the centres' heights) plus
/// the particles within reach of the slab from the slabs beside it; each pair is counted by the
/// process owning the particle it is tested from. Every process gets the whole result, equal to
/// find_overlaps of the whole packing. Collective: every process of `comm` must call it. `clumps`:
/// the clump ids of the share's particles (empty when the packing has none).
ParticleOverlaps find_overlaps(std::span<const Particle> share, long first, const ProfileCommunicator& comm,
                               double relative_tolerance = kOverlapRelativeTolerance, unsigned threads = 0,
                               std::span<const long> clumps = {});

/// Volume of the lens common to two balls of radii a, b whose centres are `distance` apart:
/// pi (a + b - D)^2 (D^2 + 2 D (a + b) - 3 (a - b)^2) / (12 D); the smaller ball's volume when
/// one contains the other (Weisstein, "Sphere-Sphere Intersection", MathWorld).
double sphere_lens_volume(double a, double b, double distance);

}  // namespace ssimarch
