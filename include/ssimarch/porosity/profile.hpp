// Porosity profiles of a packing in a cylindrical container x^2 + y^2 <= R^2, z in [z_min, z_max]:
//   radial  eps(r)       = 1 - sum_i L_i(r) / (2 pi r H)                 at given radii
//   bins    eps_k        = 1 - sum_i V_i(r_k, r_k+1) / (pi (r_k+1^2 - r_k^2) H)   annular bins
//   axial   eps(z)       = 1 - sum_i S_i(z) / (pi R^2)                   at given heights
//   map     eps(r, z)    = 1 - sum_i p_i(z, r) / (2 pi r)                 azimuthal average on a grid
//   bulk    eps          = 1 - sum_i V_i(0, R) / (pi R^2 H)
// with H = z_max - z_min and the per-particle integrals of particle_integrals.hpp, minus, for
// overlapping particles, the parts covered by earlier ones (particle_union.hpp), so that the solid
// is the union of the particles. Only the parts of
// particles inside the container count (particles sticking out are clipped, not moved or dropped).
// Work is split over std::thread workers in fixed chunks; every sum is a FixedPointSum, so results
// have the same bits for any thread count and any split of the particles over MPI ranks. Source: seed 001 (thesis
// Appendix A, the kernel), docs/math/circle_spherocylinder.md §2, docs/porosity.md.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "ssimarch/porosity/particle_integrals.hpp"
#include "ssimarch/porosity/particle_union.hpp"
#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch {

struct Container {
  double radius = 1.0;  ///< R > 0, model length
  BedSlab slab;            ///< height range, z_max > z_min
  double height() const { return slab.z_max - slab.z_min; }
  double volume() const;
};

/// The default absolute accuracy of every porosity value (dimensionless), the CLI's and Python's
/// (docs/porosity.md, "Accuracy").
inline constexpr double kPorosityTolerance = 1e-8;

struct ProfileOptions {
  /// Target absolute accuracy of every porosity value (dimensionless). The budget is split evenly
  /// over the particles contributing to a value (errors summed linearly).
  double tolerance = kPorosityTolerance;
  /// Worker threads; 0 = std::thread::hardware_concurrency().
  unsigned threads = 0;
  ProfileMethod method = ProfileMethod::kChord;
  KernelTolerances kernel;
  /// Called on the calling thread with the fraction done (0..1), about every 0.1 s, if set.
  std::function<void(double)> progress;
  /// Set when this process holds only its share of the particles (MPI, profile_communicator.hpp):
  /// counts and sums are added over all processes, and every process gets the whole profile.
  const ProfileCommunicator* communicator = nullptr;
  /// How a volume shared by overlapping particles counts (particle_union.hpp): once, as the union
  /// of the particles (default), or once per particle holding it.
  OverlapRule overlaps = OverlapRule::kUnion;
  /// The overlap groups of this process's particles, when the caller found them once for several
  /// profiles (overlap_group_set; under a communicator, the collective form). Null: each profile
  /// function finds them (collectively under a communicator).
  std::shared_ptr<const OverlapGroupSet> overlap_groups;
};

struct ProfileStats {
  long evaluations = 0;        ///< integrand evaluations (chords or kernel calls)
  long unconverged = 0;        ///< per-particle integrals that hit the quadrature depth limit
  double max_error = 0.0;      ///< largest estimated absolute error of a porosity value
  long particles_used = 0;     ///< particles overlapping the container
  long particles_clipped = 0;  ///< of those, particles sticking out of the container (counted partially)
  long overlap_groups = 0;     ///< overlap groups whose covered part was subtracted (OverlapRule::kUnion)
};

struct PorosityProfile {
  std::vector<double> x;         ///< radii, inner bin edges or heights
  std::vector<double> x_upper;   ///< outer bin edges (bins only)
  std::vector<double> porosity;
  ProfileStats stats;
};

struct PorosityMap {
  std::vector<double> r, z;
  std::vector<double> porosity;  ///< row-major: porosity[iz * r.size() + ir]
  ProfileStats stats;
};

struct BulkPorosity {
  double porosity = 1.0;
  double solid_volume = 0.0;  ///< particle volume inside the container, model length^3
  ProfileStats stats;
};

/// Every function below throws InputError for an invalid container ("container.radius",
/// "container.slab") or abscissae ("radii", "bin edges", "heights", "map radii"): not finite, not
/// increasing, or out of range.
/// eps(r) at the given radii (each in (0, R]).
PorosityProfile radial_profile(std::span<const Particle> particles, const Container& c, std::span<const double> radii,
                       const ProfileOptions& opt = {});
/// Annular bins between consecutive `edges` (increasing, within [0, R]).
PorosityProfile bin_profile(std::span<const Particle> particles, const Container& c, std::span<const double> edges,
                    const ProfileOptions& opt = {});
/// eps(z) at the given heights.
PorosityProfile axial_profile(std::span<const Particle> particles, const Container& c, std::span<const double> heights,
                      const ProfileOptions& opt = {});
/// eps(r, z) on the grid r x z (point values of the azimuthal average; radii > 0).
PorosityMap porosity_map(std::span<const Particle> particles, const Container& c, std::span<const double> radii,
                         std::span<const double> heights, const ProfileOptions& opt = {});
/// Bulk porosity of the container.
BulkPorosity bulk_porosity(std::span<const Particle> particles, const Container& c, const ProfileOptions& opt = {});

/// N radii evenly on (0, R]: R k / N, k = 1..N.
std::vector<double> even_radii(double R, int n);
/// N + 1 edges of N equal-width annular bins on [0, R].
std::vector<double> even_edges(double R, int n);
/// N heights at the centres of N equal slices of [z_min, z_max].
std::vector<double> slice_centres(double z_min, double z_max, int n);

}  // namespace ssimarch
