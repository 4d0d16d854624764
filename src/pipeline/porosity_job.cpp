// The porosity job (see porosity_job.hpp): validation, the packing, the container, then the bulk
// value and each requested profile in turn, timed per stage.
#include "ssimarch/pipeline/porosity_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"

namespace ssimarch {

namespace {

using Clock = std::chrono::steady_clock;

// Usable ranges (docs/porosity.md): profile points per profile and map cells; lengths. A profile
// point holds about 200 bytes while it is computed and written (1e6 radii: 0.2 GB, 1.4 s, 23 MB of
// CSV; 1e7 took 1.75 GB and 18 s, issue 29 item 4), a thousand times what a plot or a bed resolves.
constexpr int kMaxProfilePoints = 1'000'000;
constexpr double kMaxLength = 1e100, kMinLength = 1e-100;
// Overlap depth, relative to the smaller diameter, above which two particles overlap (a contact
// is not an overlap: overlaps.hpp).
constexpr double kOverlapTolerance = kOverlapRelativeTolerance;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

void require_positive_finite(double v, const char* key) {
  if (!(v > 0) || !std::isfinite(v)) throw InputError(key, "must be a finite number > 0 (got " + number(v) + ")");
}

void require_count(int n, const char* key) {
  if (n < 0) throw InputError(key, "must be a count >= 0 (got " + std::to_string(n) + ")");
  if (n > kMaxProfilePoints)
    throw InputError(key, "must be at most " + std::to_string(kMaxProfilePoints) + " (got " + std::to_string(n) +
                              "): each point integrates every particle near it, and a bed is not resolved finer");
}

// Lengths whose cubes (volumes) and squares (areas) stay normal doubles: outside, R^2 or d^3
// underflows to 0 or overflows to inf and the porosity is NaN (a container of radius 1e-300
// printed -nan) or the quadrature cannot resolve the particle (d = 1e308).
void require_length_scale(double v, const std::string& where, const char* what) {
  if (!(std::abs(v) <= kMaxLength)) throw InputError(where, std::string(what) + " " + number(v) + " is beyond +-1e100, "
                                                         "where volumes overflow double precision; rescale the packing");
  if (v != 0 && std::abs(v) < kMinLength)
    throw InputError(where, std::string(what) + " " + number(v) + " is below 1e-100, where volumes underflow double "
                                                   "precision; rescale the packing");
}

// `first`: the index of ps[0] in the whole packing (a process's share).
void require_packing_scale(std::span<const Particle> ps, const std::string& source, long first = 0) {
  auto usable = [](double v) { return std::abs(v) <= kMaxLength && (v == 0 || std::abs(v) >= kMinLength); };
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const Particle& p = ps[i];
    if (usable(p.diameter) && usable(p.length) && usable(p.centre.x()) && usable(p.centre.y()) && usable(p.centre.z()))
      continue;  // the common case: no message built
    const std::string where = source + ": particle " + std::to_string(static_cast<long>(i) + first + 1);
    require_length_scale(p.diameter, where, "diameter");
    require_length_scale(p.length, where, "length");
    for (int k = 0; k < 3; ++k) require_length_scale(p.centre[k], where, "centre coordinate");
  }
}

using Groups = std::shared_ptr<const OverlapGroupSet>;

// The profile options of one stage: the job's, reporting progress under the stage's name, with the
// overlap groups found once for the whole job.
ProfileOptions stage_options(const PorosityJob& job, const Groups& groups, std::string_view stage) {
  ProfileOptions opt = job.options;
  opt.overlap_groups = groups;
  opt.progress = nullptr;
  if (job.progress) opt.progress = [&job, stage](double f) { job.progress(stage, f); };
  return opt;
}

// The job's particles: its own, or those of its packing file (read into `storage`); `clumps` their
// clump ids (empty when they have none).
std::span<const Particle> packing_of(const PorosityJob& job, Packing& storage, bool* spherocylinders,
                                     std::span<const long>* clumps) {
  if (!job.packing.empty()) {
    *spherocylinders = std::any_of(job.packing.begin(), job.packing.end(), [](const Particle& p) { return p.length != 0; });
    if (!job.clumps.empty() && job.clumps.size() != job.packing.size())
      throw InputError("clumps", std::to_string(job.clumps.size()) + " clump ids for " +
                                     std::to_string(job.packing.size()) + " particles: one per particle");
    *clumps = job.clumps;
    return job.packing;
  }
  if (job.packing_file.empty()) throw InputError("packing", "no packing given (neither particles nor a file)");
  storage = read_packing(job.packing_file, job.input_limits, job.options.threads);
  if (storage.particles.empty()) throw InputError(job.packing_file.string(), "no particles");
  *spherocylinders = storage.spherocylinders;
  *clumps = storage.clumps;
  return storage.particles;
}

void run_radial_stages(const PorosityJob& job, const Groups& groups, std::span<const Particle> ps,
                       PorosityJobResult& out) {
  const Container& c = out.container;
  if (job.radial_points > 0 || job.bins > 0) {
    const auto t0 = Clock::now();
    const ProfileOptions opt = stage_options(job, groups, "radial");
    if (job.radial_points > 0) {
      out.radial = radial_profile(ps, c, even_radii(c.radius, job.radial_points), opt);
      out.unconverged += out.radial->stats.unconverged;
    }
    if (job.bins > 0) {
      out.bins = bin_profile(ps, c, even_edges(c.radius, job.bins), opt);
      out.unconverged += out.bins->stats.unconverged;
    }
    out.timings.radial = seconds_since(t0);
  }
  if (job.axial_slices > 0) {
    const auto t0 = Clock::now();
    out.axial = axial_profile(ps, c, slice_centres(c.slab.z_min, c.slab.z_max, job.axial_slices),
                              stage_options(job, groups, "axial"));
    out.unconverged += out.axial->stats.unconverged;
    out.timings.axial = seconds_since(t0);
  }
  if (job.map_radii > 0) {
    const auto t0 = Clock::now();
    out.map =
        porosity_map(ps, c, cell_centres(c.radius, job.map_radii),
                     slice_centres(c.slab.z_min, c.slab.z_max, job.map_heights), stage_options(job, groups, "map"));
    out.unconverged += out.map->stats.unconverged;
    out.timings.map = seconds_since(t0);
  }
}

}  // namespace

void validate(const PorosityJob& job) {
  require_positive_finite(job.container_radius, "container_radius");
  require_length_scale(job.container_radius, "container_radius", "the radius");
  require_positive_finite(job.options.tolerance, "options.tolerance");
  require_count(job.radial_points, "radial_points");
  require_count(job.bins, "bins");
  require_count(job.axial_slices, "axial_slices");
  require_count(job.map_radii, "map_radii");
  require_count(job.map_heights, "map_heights");
  if (static_cast<double>(job.map_radii) * job.map_heights > kMaxProfilePoints)
    throw InputError("map_radii", "a map of at most " + std::to_string(kMaxProfilePoints) + " cells (got " +
                                      std::to_string(job.map_radii) + " x " + std::to_string(job.map_heights) + ")");
  if ((job.map_radii > 0) != (job.map_heights > 0))
    throw InputError("map_radii", "a map needs both counts > 0 (got " + std::to_string(job.map_radii) + " x " +
                                      std::to_string(job.map_heights) + ")");
  if (job.height_range) {
    const BedSlab& s = *job.height_range;
    if (!(s.z_max > s.z_min) || !std::isfinite(s.z_min) || !std::isfinite(s.z_max))
      throw InputError("height_range", "needs finite z_min < z_max (got [" + number(s.z_min) + ", " +
                                           number(s.z_max) + "])");
    require_length_scale(s.z_min, "height_range", "the height");
    require_length_scale(s.z_max, "height_range", "the height");
    require_length_scale(s.z_max - s.z_min, "height_range", "the height range");
  }
}

namespace {

void run_stages(const PorosityJob& job, const Groups& groups, std::span<const Particle> ps, PorosityJobResult& out) {
  const auto t0 = Clock::now();
  out.bulk = bulk_porosity(ps, out.container, stage_options(job, groups, "bulk"));
  out.unconverged = out.bulk.stats.unconverged;
  out.timings.bulk = seconds_since(t0);
  run_radial_stages(job, groups, ps, out);
}

// A packing file on several processes (MPI, docs/scaling.md): each reads and integrates its share
// of the file; counts, the height range and the profiles are combined over the processes.
PorosityJobResult run_shared_porosity_job(const PorosityJob& job, const ProfileCommunicator& comm) {
  PorosityJobResult out;
  const Packing share = read_packing_share(job.packing_file, job.input_limits, &comm, job.options.threads);
  const std::span<const Particle> ps = share.particles;
  long count = static_cast<long>(ps.size());
  const long first = comm.exclusive_prefix_sum(count);
  comm.sum(std::span<long>(&count, 1));
  out.particles = count;
  out.spherocylinders = comm.any(share.spherocylinders);
  if (count == 0) throw InputError(job.packing_file.string(), "no particles");
  std::string problem;
  try {
    require_packing_scale(ps, job.packing_file.string(), first);
  } catch (const InputError& e) {
    problem = e.where() + '\x1f' + e.message();
  }
  if (problem = comm.first_error(problem); !problem.empty())
    throw InputError(problem.substr(0, problem.find('\x1f')), problem.substr(problem.find('\x1f') + 1));
  // The overlap search moves the particles into slabs of the bed, with their neighbours from the
  // slabs beside (overlaps.hpp, docs/scaling.md): each pair is counted once, by one process.
  if (comm.any(!share.clumps.empty())) out.clumped_particles = distinct_count(share.clumps, comm);
  if (job.find_overlaps)
    out.overlaps = find_overlaps(ps, first, comm, kOverlapTolerance, job.options.threads, share.clumps);
  // The union's overlap groups, found once for every stage (each process: those of its slab).
  Groups groups = job.options.overlap_groups;
  if (job.options.overlaps == OverlapRule::kUnion && !groups)
    groups = overlap_group_set(ps, first, comm, kOverlapTolerance, job.options.threads);
  out.container.radius = job.container_radius;
  if (job.height_range) {
    out.container.slab = *job.height_range;
  } else {
    out.container.slab = vertical_extent(ps);
    comm.min_max(out.container.slab.z_min, out.container.slab.z_max);
  }
  run_stages(job, groups, ps, out);
  return out;
}

}  // namespace

PorosityJobResult run_porosity_job(const PorosityJob& job) {
  validate(job);
  const ProfileCommunicator* comm = job.options.communicator;
  if (comm && comm->size() > 1 && job.packing.empty()) return run_shared_porosity_job(job, *comm);
  PorosityJobResult out;
  Packing read;
  std::span<const long> clumps;
  const std::span<const Particle> all = packing_of(job, read, &out.spherocylinders, &clumps);
  out.particles = static_cast<long>(all.size());
  if (!clumps.empty()) out.clumped_particles = distinct_count(clumps);
  require_packing_scale(all, job.packing.empty() ? job.packing_file.string() : "packing");
  // Particles in memory on several processes: each integrates its block, and the profile
  // functions add the blocks' exact sums, so every process gets the single-process result.
  std::span<const Particle> ps = all;
  if (comm && comm->size() > 1) {
    const std::size_t n = all.size(), k = static_cast<std::size_t>(comm->rank()), p = static_cast<std::size_t>(comm->size());
    ps = all.subspan(n * k / p, n * (k + 1) / p - n * k / p);
  }
  if (job.find_overlaps && (!comm || comm->rank() == 0))
    out.overlaps = find_overlaps(all, kOverlapTolerance, job.options.threads, clumps);
  out.container.radius = job.container_radius;
  out.container.slab = job.height_range ? *job.height_range : vertical_extent(all);
  // The union's overlap groups, found once for every stage; with the particles split over
  // processes, the first process subtracts them all (the others none).
  Groups groups = job.options.overlap_groups;
  if (job.options.overlaps == OverlapRule::kUnion && !groups)
    groups = comm && comm->rank() != 0 ? std::make_shared<const OverlapGroupSet>()
                                       : overlap_group_set(all, kOverlapTolerance, job.options.threads);
  run_stages(job, groups, ps, out);
  if (job.keep_particles) out.packing.assign(all.begin(), all.end());
  return out;
}

namespace {

// Values of every profile outside [0, 1] (the sum rule pushes them below 0 where particles overlap).
long values_outside_unit_interval(const PorosityJobResult& r) {
  long n = !(r.bulk.porosity >= 0 && r.bulk.porosity <= 1);
  auto count = [&n](const std::vector<double>& v) {
    for (double x : v) n += !(x >= 0 && x <= 1);
  };
  if (r.radial) count(r.radial->porosity);
  if (r.bins) count(r.bins->porosity);
  if (r.axial) count(r.axial->porosity);
  if (r.map) count(r.map->porosity);
  return n;
}

}  // namespace

std::string describe_clump_overlaps(const PorosityJobResult& r, OverlapRule rule) {
  const ParticleOverlaps& o = r.overlaps;
  if (o.clump_pairs <= 0) return {};
  std::ostringstream m;
  m.precision(6);
  m << o.clump_pairs << " pair" << (o.clump_pairs == 1 ? "" : "s")
    << " of spheres overlap inside their clumped particles (" << r.clumped_particles << " particles of " << r.particles
    << " spheres), sharing a volume of " << o.clump_doubled_volume;
  m << (rule == OverlapRule::kUnion
            ? ", counted once (the union)"
            : ", counted once per sphere holding it (the sum rule): the porosities are too low");
  return m.str();
}

std::string describe_overlaps(const PorosityJobResult& r, OverlapRule rule, const OverlapWording& wording) {
  const ParticleOverlaps& o = r.overlaps;
  if (o.pairs <= 0) return {};
  std::ostringstream m;
  m.precision(6);
  m << o.pairs << " pair" << (o.pairs == 1 ? "" : "s") << " of " << (r.clumped_particles > 0 ? "clumped " : "")
    << "particles overlap (worst: " << (r.clumped_particles > 0 ? "rows " : "particles ")
    << o.worst_first + wording.first_index << " and " << o.worst_second + wording.first_index
    << (wording.first_index == 0 ? ", 0-based," : "") << " by " << o.max_depth << "); their common volume ("
    << o.doubled_volume << ")";
  if (rule == OverlapRule::kUnion) {
    m << " is counted once: the porosities are those of the union of the particles";
    return m.str();
  }
  m << " is counted once per particle holding it (" << wording.sum_rule << "), so the porosities are too low";
  if (const long bad = values_outside_unit_interval(r); bad > 0)
    m << " (" << bad << " value" << (bad == 1 ? " is" : "s are") << " outside [0, 1] for this reason)";
  return m.str();
}

BedSlab vertical_extent(std::span<const Particle> particles) {
  double z0 = std::numeric_limits<double>::infinity(), z1 = -z0;
  for (const auto& p : particles) {
    const double ext = std::abs(p.axis.z()) * p.half_length() + p.radius();
    z0 = std::min(z0, p.centre.z() - ext);
    z1 = std::max(z1, p.centre.z() + ext);
  }
  return {z0, z1};
}

std::vector<double> cell_centres(double R, int n) {
  std::vector<double> rs(static_cast<std::size_t>(std::max(n, 0)));
  for (int k = 0; k < n; ++k) rs[static_cast<std::size_t>(k)] = R * (k + 0.5) / n;
  return rs;
}

}  // namespace ssimarch
