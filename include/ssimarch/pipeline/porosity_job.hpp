// A whole porosity run as one typed job: a packing (a file or particles in memory), a cylindrical
// container, the profiles wanted with their resolutions, and the accuracy; the result holds every
// profile and summary the CLI prints or writes. The library's own entry point for `ssimarch
// porosity`, the Python module and batch/MPI drivers (issue 9); formulas in
// include/ssimarch/porosity/profile.hpp and docs/porosity.md.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/porosity/overlaps.hpp"
#include "ssimarch/porosity/packing.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch {

/// The defaults of a porosity run, shared by `ssimarch porosity` and the Python module
/// (docs/porosity.md, docs/python.md): one place, so that the two front ends agree.
struct PorosityDefaults {
  /// Radii of eps(r) on (0, R]: the CLI's profile when no other is asked for, Python's `points`.
  static constexpr int kRadialPoints = 200;
  /// Slices of eps(z): Python's `slices` (the CLI's --axial has no default: it asks for the profile).
  static constexpr int kAxialSlices = 100;
  /// Cells of eps(r, z) per direction: Python's map `radii` and `heights`.
  static constexpr int kMapCells = 50;
  /// Absolute accuracy of every porosity value (dimensionless): ProfileOptions::tolerance.
  static constexpr double kTolerance = kPorosityTolerance;
};

/// What to compute. Counts of 0 mean "not wanted"; at least one profile or only the bulk value.
struct PorosityJob {
  /// The packing: read from `packing_file` (CSV or LAMMPS dump, read_packing) when `packing` is empty.
  std::filesystem::path packing_file;
  std::vector<Particle> packing;
  /// With `packing`: empty, or the clump id of each of its particles (Packing::clumps). A packing
  /// file brings its own.
  std::vector<long> clumps;
  /// How much of the packing file is read before it is rejected as too large.
  InputLimits input_limits;
  double container_radius = 0.0;      ///< R > 0, packing units
  std::optional<BedSlab> height_range;   ///< default: the packing's vertical extent
  int radial_points = 0;              ///< eps(r) at N radii evenly on (0, R]
  int bins = 0;                       ///< N equal annular bins on [0, R]
  int axial_slices = 0;               ///< eps(z) at the centres of N equal slices of the height range
  int map_radii = 0, map_heights = 0; ///< eps(r, z) at NR x NZ cell centres (both > 0 or both 0)
  /// Accuracy, threads and integral formulation; its `progress` is replaced by the one below.
  ProfileOptions options;
  /// Look for overlapping particles (PorosityJobResult::overlaps): O(n) for similar sizes.
  bool find_overlaps = true;
  /// Return the particles read (PorosityJobResult::packing), for a front end that shows the bed
  /// (the viewer page); not with a packing file shared over processes.
  bool keep_particles = false;
  /// Called with the stage ("bulk", "radial", "axial", "map") and the fraction of it done.
  std::function<void(std::string_view stage, double fraction)> progress;
};

/// Wall-clock seconds per stage ("radial" covers points and bins); a stage that did not run stays unset.
struct PorosityTimings {
  std::optional<double> bulk, radial, axial, map;
};

struct PorosityJobResult {
  long particles = 0;  ///< rows of the packing (spheres or spherocylinders)
  /// Particles those rows form when the packing has clump ids (Packing::clumps): the distinct ids;
  /// 0 when it has none (each row is a particle).
  long clumped_particles = 0;
  bool spherocylinders = false;   ///< the file had axis and length columns (particles given: any l > 0)
  Container container;            ///< with the height range actually used
  BulkPorosity bulk;
  std::optional<PorosityProfile> radial;  ///< radial_points > 0
  std::optional<PorosityProfile> bins;    ///< bins > 0
  std::optional<PorosityProfile> axial;   ///< axial_slices > 0
  std::optional<PorosityMap> map;         ///< map_radii > 0
  /// Pairs of particles that overlap: their common volume is counted twice, so porosities are too
  /// low (below 0 where three or more overlap). Empty when find_overlaps is false.
  ParticleOverlaps overlaps;
  /// Per-particle integrals that missed the tolerance, over the bulk value and every profile.
  long unconverged = 0;
  PorosityTimings timings;
  /// The packing's particles, when PorosityJob::keep_particles asked for them.
  std::vector<Particle> packing;
};

/// How a front end names what the overlap report mentions.
struct OverlapWording {
  int first_index = 1;                           ///< particles numbered from 1 (file rows) or 0 (array rows)
  std::string_view sum_rule = "--overlaps sum";  ///< how the user asks for OverlapRule::kSum
};

/// The overlap report of a run with overlapping particles (empty when none overlap): the count, the
/// worst pair and the volume they share, how it was counted (`rule`) and, under the sum rule, how
/// many values left [0, 1] because of it. The CLI prints it on stderr, Python raises it as a
/// RuntimeWarning, `ssimarch porosity --strict` fails with it.
std::string describe_overlaps(const PorosityJobResult& r, OverlapRule rule, const OverlapWording& wording = {});
/// The overlaps inside clumped particles (ParticleOverlaps::clump_pairs; empty when none): spheres of
/// one particle overlap by design, so this is information, never a reason for --strict to fail.
std::string describe_clump_overlaps(const PorosityJobResult& r, OverlapRule rule);

/// Throws InputError, located by the job field's name (e.g. "container_radius"), for an impossible
/// job: lengths outside [1e-100, 1e100] (volumes leave double precision), more than 1e7 points in
/// a profile or cells in a map. Called by run_porosity_job; exposed so that front ends can check before reading the packing.
void validate(const PorosityJob& job);

/// Runs the job. Throws InputError for an invalid job or packing (the packing file's errors are
/// located by file:line[:column]) and when the packing has no particles.
PorosityJobResult run_porosity_job(const PorosityJob& job);

/// Vertical extent of the particles: the default height range.
BedSlab vertical_extent(std::span<const Particle> particles);

/// Radii of the map's cell centres: R (k + 1/2) / N, k = 0..N-1.
std::vector<double> cell_centres(double R, int n);

}  // namespace ssimarch
