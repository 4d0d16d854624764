// Profiles of a packing. Source: docs/porosity.md ("Profiles"); per-particle integrals in
// particle_integrals.cpp.
#include "ssimarch/porosity/profile.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/core/text_cat.hpp"

#include "covered_chords.hpp"
#include "parallel.hpp"

namespace ssimarch {

namespace {

constexpr int kMaxChunks = 256;

void check_container(const Container& c) {
  if (!(c.radius > 0) || !std::isfinite(c.radius))
    throw InputError("container.radius", "must be a finite number > 0 (got " + internal::cat(c.radius) + ")");
  if (!(c.slab.z_max > c.slab.z_min) || !std::isfinite(c.slab.z_min) || !std::isfinite(c.slab.z_max))
    throw InputError("container.slab", "the height range [z_min, z_max] needs finite z_min < z_max (got [" +
                                           internal::cat(c.slab.z_min) + ", " + internal::cat(c.slab.z_max) + "])");
}

// The particles that overlap the container, as indices (4 bytes each: the shapes are rebuilt where
// they are used, which costs less than holding them), and how many stick out of it.
struct Prepared {
  std::span<const Particle> particles;
  std::vector<std::uint32_t> used;
  long clipped = 0;
  std::size_t size() const { return used.size(); }
  ParticleShape shape(std::size_t k) const { return ParticleShape(particles[used[k]]); }
};

// Chunks of a parallel pass over n items that each hold m accumulators: at most kMaxChunks, and
// few enough to keep the accumulators near 500,000 values (large maps). The count depends on n and
// m only, never on the thread count.
int chunk_count(std::size_t n, std::size_t m) {
  const std::size_t mem_cap = std::max<std::size_t>(8, 500'000 / std::max<std::size_t>(1, m));
  return static_cast<int>(std::max<std::size_t>(1, std::min({static_cast<std::size_t>(kMaxChunks), n, mem_cap})));
}

// [b, e) of chunk k of `chunks` over n items.
std::pair<std::size_t, std::size_t> chunk_range(std::size_t n, int k, int chunks) {
  return {n * static_cast<std::size_t>(k) / static_cast<std::size_t>(chunks),
          n * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(chunks)};
}

Prepared prepare(std::span<const Particle> ps, const Container& c, unsigned threads) {
  if (ps.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError("packing", "more than 2^32 particles in one process: run it on more MPI ranks");
  Prepared out;
  out.particles = ps;
  const int chunks = chunk_count(ps.size(), 1);
  std::vector<std::vector<std::uint32_t>> used(static_cast<std::size_t>(chunks));
  std::vector<long> clipped(static_cast<std::size_t>(chunks), 0);
  internal::parallel_chunks(chunks, threads, [&](int k) {
    const auto [b, e] = chunk_range(ps.size(), k, chunks);
    auto& u = used[static_cast<std::size_t>(k)];
    u.reserve(e - b);
    for (std::size_t i = b; i < e; ++i) {
      const ParticleShape s(ps[i]);
      if (s.rho_min() >= c.radius || s.z_max() <= c.slab.z_min || s.z_min() >= c.slab.z_max) continue;
      if (s.rho_max() > c.radius || s.z_min() < c.slab.z_min || s.z_max() > c.slab.z_max) ++clipped[static_cast<std::size_t>(k)];
      u.push_back(static_cast<std::uint32_t>(i));
    }
  }, nullptr);
  std::size_t n = 0;
  for (const auto& u : used) n += u.size();
  out.used.reserve(n);
  for (int k = 0; k < chunks; ++k) {
    out.used.insert(out.used.end(), used[static_cast<std::size_t>(k)].begin(), used[static_cast<std::size_t>(k)].end());
    used[static_cast<std::size_t>(k)] = {};
    out.clipped += clipped[static_cast<std::size_t>(k)];
  }
  return out;
}

// Sums over this process's particles, with the quantum of each value's FixedPointSum set from its
// norm (the value a full container would reach).
ProfileSums empty_sums(std::span<const double> norm) {
  ProfileSums z;
  for (double n : norm) {
    z.solid.emplace_back(n);
    z.error.emplace_back(n);
  }
  return z;
}

// Runs per_item(i, sums) for i < n over fixed chunks and adds the chunks' exact sums: the result
// does not depend on the thread count.
template <class F>
ProfileSums chunk_sums(std::size_t n, std::span<const double> norm, const ProfileOptions& opt, F&& per_item,
                       const std::function<void(double)>& progress) {
  const int chunks = chunk_count(n, norm.size());
  std::vector<ProfileSums> res(static_cast<std::size_t>(chunks));
  internal::parallel_chunks(
      chunks, opt.threads,
      [&](int k) {
        ProfileSums& cr = res[static_cast<std::size_t>(k)];
        cr = empty_sums(norm);
        const auto [b, e] = chunk_range(n, k, chunks);
        // Ctrl-C: the rest of the chunk is skipped; parallel_chunks throws Interrupted.
        for (std::size_t i = b; i < e && !interrupt_requested(); ++i) per_item(i, cr);
      },
      progress);
  ProfileSums total = empty_sums(norm);
  for (const auto& cr : res) total += cr;
  return total;
}

// Per-particle work over this process's particles, then the sums of the other processes
// (opt.communicator): the result does not depend on threads or ranks.
template <class F>
ProfileSums run_chunks(const Prepared& prep, std::span<const double> norm, const ProfileOptions& opt,
                       F&& per_particle) {
  ProfileSums total = chunk_sums(
      prep.size(), norm, opt, [&](std::size_t i, ProfileSums& cr) { per_particle(prep.shape(i), cr); }, opt.progress);
  total.particles_used = static_cast<long>(prep.size());
  total.particles_clipped = prep.clipped;
  if (opt.communicator) opt.communicator->sum(total);
  return total;
}

// Porosities 1 - solid/norm and the statistics of the summed profile.
void finish(const ProfileSums& sums, std::span<const double> norm, std::vector<double>& porosity, ProfileStats& st) {
  porosity.resize(norm.size());
  for (std::size_t j = 0; j < norm.size(); ++j) {
    porosity[j] = 1 - sums.solid[j].value() / norm[j];
    st.max_error = std::max(st.max_error, sums.error[j].value() / norm[j]);
  }
  st.evaluations = sums.evaluations;
  st.unconverged = sums.unconverged;
  st.particles_used = sums.particles_used;
  st.particles_clipped = sums.particles_clipped;
}

// Particles touching each value, over all processes (the accuracy budget is split among them):
// each chunk marks the ends of its particles' index ranges, and a running sum turns the marks
// into counts.
template <class Range>
std::vector<long> touching(std::size_t n, std::size_t m, const ProfileOptions& opt, Range&& range_of_item) {
  const int chunks = chunk_count(n, m);
  std::vector<std::vector<long>> marks(static_cast<std::size_t>(chunks));
  internal::parallel_chunks(chunks, opt.threads, [&](int k) {
    auto& d = marks[static_cast<std::size_t>(k)];
    d.assign(m + 1, 0);
    const auto [b, e] = chunk_range(n, k, chunks);
    for (std::size_t i = b; i < e; ++i) {
      const auto [lo, hi] = range_of_item(i);
      ++d[lo];
      --d[hi];
    }
  }, nullptr);
  std::vector<long> count(m, 0);
  long run = 0;
  for (std::size_t j = 0; j < m; ++j) {
    for (const auto& d : marks) run += d[j];
    count[j] = run;
  }
  if (opt.communicator) opt.communicator->sum(count);
  return count;
}

void account(ProfileSums& cr, std::size_t j, const QuadResult& q) {
  cr.solid[j].add(q.value);
  cr.error[j].add(q.error);
  cr.evaluations += q.evaluations;
  if (q.status != QuadStatus::kConverged) ++cr.unconverged;
}

// The overlap groups whose covered parts a profile subtracts (particle_union.hpp): none when each
// particle counts on its own, the caller's when given, else found here (collectively under MPI).
std::shared_ptr<const OverlapGroupSet> groups_for(std::span<const Particle> ps, const ProfileOptions& opt) {
  if (opt.overlaps == OverlapRule::kSum) return nullptr;
  if (opt.overlap_groups) return opt.overlap_groups;
  if (opt.communicator) {
    const long first = opt.communicator->exclusive_prefix_sum(static_cast<long>(ps.size()));
    return overlap_group_set(ps, first, *opt.communicator, kOverlapRelativeTolerance, opt.threads);
  }
  return overlap_group_set(ps, kOverlapRelativeTolerance, opt.threads);
}

// Share of a value's accuracy budget given to the covered parts of overlap groups (the particles'
// own integrals keep their half; the rest is margin).
constexpr double kCoveredBudgetShare = 0.25;

// Subtracts the covered parts of the groups from `sums`: covered(g, budget, cr) adds minus the
// measure of group g's covered part to the values of cr it touches, range_of(g) is the range of
// values it can touch. Budgets are split over
// the groups touching a value, counted over all processes; sums are exact, as the particles'.
template <class Range, class Covered>
void subtract_covered(const OverlapGroupSet* groups, std::span<const double> norm, const ProfileOptions& opt,
                      Range&& range_of, Covered&& covered, ProfileSums& sums, long& group_count) {
  group_count = groups ? static_cast<long>(groups->size()) : 0;
  if (opt.communicator) opt.communicator->sum(std::span<long>(&group_count, 1));
  if (group_count == 0) return;
  const std::size_t m = norm.size(), n = groups->size();
  // The values a group touches follow from its box alone (range_of reads nothing else), so a
  // group is formed from the compact set, into per-thread storage, only where it touches one.
  auto range = [&](std::size_t i) {
    thread_local OverlapGroup box;
    box.box_lo = groups->entry(i).box_lo, box.box_hi = groups->entry(i).box_hi;
    return range_of(box);
  };
  const std::vector<long> count = touching(n, m, opt, range);
  std::vector<double> budget(m);
  for (std::size_t j = 0; j < m; ++j)
    budget[j] = kCoveredBudgetShare * opt.tolerance * norm[j] / std::max(1L, count[j]);
  ProfileSums total = chunk_sums(
      n, norm, opt,
      [&](std::size_t i, ProfileSums& cr) {
        const auto [lo, hi] = range(i);
        if (lo >= hi) return;
        thread_local OverlapGroup g;
        groups->get(i, g);
        covered(g, budget, cr);
      },
      nullptr);
  if (opt.communicator) opt.communicator->sum(total);
  sums += total;
}

// Subtracts a covered part's measure q from value j.
void subtract(ProfileSums& cr, std::size_t j, const QuadResult& q) {
  cr.solid[j].add(-q.value);
  cr.error[j].add(q.error);
  cr.evaluations += q.evaluations;
  if (q.status != QuadStatus::kConverged) ++cr.unconverged;
}

// covered(g, budget, cr) of subtract_covered for a profile whose value j of group g is
// measure(g, j, budget[j]), over the values range_of(g).
template <class Range, class Measure>
auto each_value(Range& range_of, Measure&& measure) {
  return [&range_of, measure](const OverlapGroup& g, const std::vector<double>& budget, ProfileSums& cr) {
    const auto [lo, hi] = range_of(g);
    for (std::size_t j = lo; j < hi; ++j) subtract(cr, j, measure(g, j, budget[j]));
  };
}

// Index range of sorted values v with v in [lo, hi].
std::pair<std::size_t, std::size_t> index_range(std::span<const double> v, double lo, double hi) {
  const auto b = std::lower_bound(v.begin(), v.end(), lo);
  const auto e = std::upper_bound(v.begin(), v.end(), hi);
  return {static_cast<std::size_t>(b - v.begin()), static_cast<std::size_t>(std::max(b, e) - v.begin())};
}

void require_sorted(std::span<const double> v, const char* what) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (!std::isfinite(v[k]))
      throw InputError(what, "must be finite (value " + std::to_string(k) + " is " + internal::cat(v[k]) + ")");
    if (k > 0 && !(v[k] > v[k - 1]))
      throw InputError(what, "must be strictly increasing (value " + std::to_string(k) + " is " + internal::cat(v[k]) +
                                 " after " + internal::cat(v[k - 1]) + ")");
  }
}

// Volume of a ball between two horizontal planes: integral of pi (a^2 - (z - z_c)^2) dz.
double sphere_slab_volume(const Particle& p, const BedSlab& slab) {
  const double a = p.radius();
  const double lo = std::clamp(slab.z_min - p.centre.z(), -a, a), hi = std::clamp(slab.z_max - p.centre.z(), -a, a);
  auto F = [&](double t) { return std::numbers::pi * (a * a * t - t * t * t / 3); };
  return hi > lo ? F(hi) - F(lo) : 0.0;
}

}  // namespace

double Container::volume() const { return std::numbers::pi * radius * radius * height(); }

std::vector<double> even_radii(double R, int n) {
  std::vector<double> v(n);
  for (int k = 0; k < n; ++k) v[k] = R * (k + 1) / n;
  return v;
}

std::vector<double> even_edges(double R, int n) {
  std::vector<double> v(n + 1);
  for (int k = 0; k <= n; ++k) v[k] = R * k / n;
  return v;
}

std::vector<double> slice_centres(double z0, double z1, int n) {
  std::vector<double> v(n);
  for (int k = 0; k < n; ++k) v[k] = z0 + (z1 - z0) * (k + 0.5) / n;
  return v;
}

PorosityProfile radial_profile(std::span<const Particle> particles, const Container& c, std::span<const double> radii,
                               const ProfileOptions& opt) {
  check_container(c);
  require_sorted(radii, "radii");
  for (double r : radii)
    if (!(r > 0) || r > c.radius)
      throw InputError("radii",
                       "must lie in (0, R] = (0, " + internal::cat(c.radius) + "] (got " + internal::cat(r) + ")");
  const Prepared prep = prepare(particles, c, opt.threads);
  const std::size_t m = radii.size();
  // Work proportional to the radii a particle touches: [rho_min, rho_max] located by bisection.
  auto range_of = [&](const ParticleShape& s) { return index_range(radii, s.rho_min(), s.rho_max()); };
  const std::vector<long> count = touching(prep.size(), m, opt, [&](std::size_t i) { return range_of(prep.shape(i)); });
  std::vector<double> norm(m), budget(m);
  for (std::size_t j = 0; j < m; ++j) {
    norm[j] = 2 * std::numbers::pi * radii[j] * c.height();
    budget[j] = 0.5 * opt.tolerance * norm[j] / std::max(1L, count[j]);
  }
  ProfileSums sums = run_chunks(prep, norm, opt, [&](const ParticleShape& s, ProfileSums& cr) {
    const auto [b, e] = range_of(s);
    for (std::size_t j = b; j < e; ++j)
      account(cr, j, lateral_area(s, radii[j], c.slab, budget[j], opt.method, opt.kernel));
  });
  PorosityProfile out;
  const auto groups = groups_for(particles, opt);
  auto covering = [&](const OverlapGroup& g) { return index_range(radii, g.rho_min(), g.rho_max()); };
  // A group of balls is prepared once for all the radii it reaches (covered_chords.hpp).
  auto covered = [&](const OverlapGroup& g, const std::vector<double>& share, ProfileSums& cr) {
    const auto [lo, hi] = covering(g);
    if (!g.spheres()) {
      for (std::size_t j = lo; j < hi; ++j) subtract(cr, j, covered_lateral_area(g, radii[j], c.slab, share[j]));
      return;
    }
    const internal::CoveredBallChords balls(g, c.slab);
    for (std::size_t j = lo; j < hi; ++j) subtract(cr, j, balls.lateral_area(radii[j]));
  };
  subtract_covered(groups.get(), norm, opt, covering, covered, sums, out.stats.overlap_groups);
  out.x.assign(radii.begin(), radii.end());
  finish(sums, norm, out.porosity, out.stats);
  return out;
}

PorosityProfile bin_profile(std::span<const Particle> particles, const Container& c, std::span<const double> edges,
                            const ProfileOptions& opt) {
  check_container(c);
  require_sorted(edges, "bin edges");
  if (edges.size() < 2 || edges.front() < 0 || edges.back() > c.radius)
    throw InputError("bin edges", "need at least two values within [0, R] = [0, " + internal::cat(c.radius) + "]");
  const Prepared prep = prepare(particles, c, opt.threads);
  const std::size_t m = edges.size() - 1;
  auto bins_of = [&](const ParticleShape& s) {
    // Bins k with [edges[k], edges[k+1]] overlapping [rho_min, rho_max].
    const auto ub = std::upper_bound(edges.begin(), edges.end(), s.rho_min());
    const std::size_t b = ub == edges.begin() ? 0 : static_cast<std::size_t>(ub - edges.begin()) - 1;
    const auto lb = std::lower_bound(edges.begin(), edges.end(), s.rho_max());
    const std::size_t e = std::min(m, static_cast<std::size_t>(lb - edges.begin()));
    return std::pair{b, std::max(b, e)};
  };
  const std::vector<long> count = touching(prep.size(), m, opt, [&](std::size_t i) { return bins_of(prep.shape(i)); });
  std::vector<double> norm(m), budget(m);
  for (std::size_t k = 0; k < m; ++k) {
    norm[k] = std::numbers::pi * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k]) * c.height();
    budget[k] = 0.5 * opt.tolerance * norm[k] / std::max(1L, count[k]);
  }
  ProfileSums sums = run_chunks(prep, norm, opt, [&](const ParticleShape& s, ProfileSums& cr) {
    const auto [b, e] = bins_of(s);
    const bool in_slab = s.z_min() >= c.slab.z_min && s.z_max() <= c.slab.z_max;
    for (std::size_t k = b; k < e; ++k) {
      const bool in_annulus = s.rho_min() >= edges[k] && s.rho_max() <= edges[k + 1];
      if (in_annulus && in_slab) {
        cr.solid[k].add(s.particle().volume());  // whole particle inside this annulus: closed form
        continue;
      }
      if (in_annulus && s.particle().length == 0) {
        cr.solid[k].add(sphere_slab_volume(s.particle(), c.slab));  // sphere cut by the planes: caps
        continue;
      }
      account(cr, k, shell_volume(s, edges[k], edges[k + 1], c.slab, budget[k], opt.method, opt.kernel));
    }
  });
  PorosityProfile out;
  const auto groups = groups_for(particles, opt);
  auto covering = [&](const OverlapGroup& g) {
    const auto ub = std::upper_bound(edges.begin(), edges.end(), g.rho_min());
    const std::size_t b = std::min(m, ub == edges.begin() ? 0 : static_cast<std::size_t>(ub - edges.begin()) - 1);
    const auto lb = std::lower_bound(edges.begin(), edges.end(), g.rho_max());
    return std::pair{b, std::max(b, std::min(m, static_cast<std::size_t>(lb - edges.begin())))};
  };
  subtract_covered(
      groups.get(), norm, opt, covering,
      each_value(covering, [&](const OverlapGroup& g, std::size_t k,
                               double tol) { return covered_shell_volume(g, edges[k], edges[k + 1], c.slab, tol); }),
      sums, out.stats.overlap_groups);
  out.x.assign(edges.begin(), edges.end() - 1);
  out.x_upper.assign(edges.begin() + 1, edges.end());
  finish(sums, norm, out.porosity, out.stats);
  return out;
}

BulkPorosity bulk_porosity(std::span<const Particle> particles, const Container& c, const ProfileOptions& opt) {
  const std::vector<double> edges{0.0, c.radius};
  const PorosityProfile p = bin_profile(particles, c, edges, opt);
  BulkPorosity b;
  b.porosity = p.porosity[0];
  b.solid_volume = (1 - p.porosity[0]) * c.volume();
  b.stats = p.stats;
  return b;
}

PorosityProfile axial_profile(std::span<const Particle> particles, const Container& c, std::span<const double> heights,
                              const ProfileOptions& opt) {
  check_container(c);
  require_sorted(heights, "heights");
  const Prepared prep = prepare(particles, c, opt.threads);
  const std::size_t m = heights.size();
  auto range_of = [&](const ParticleShape& s) { return index_range(heights, s.z_min(), s.z_max()); };
  const std::vector<long> count = touching(prep.size(), m, opt, [&](std::size_t i) { return range_of(prep.shape(i)); });
  const double area = std::numbers::pi * c.radius * c.radius;
  std::vector<double> norm(m, area), budget(m);
  for (std::size_t j = 0; j < m; ++j) budget[j] = 0.5 * opt.tolerance * area / std::max(1L, count[j]);
  ProfileSums sums = run_chunks(prep, norm, opt, [&](const ParticleShape& s, ProfileSums& cr) {
    const auto [b, e] = range_of(s);
    for (std::size_t j = b; j < e; ++j)
      account(cr, j, slice_area(s, heights[j], c.radius, budget[j], opt.kernel, opt.method));
  });
  PorosityProfile out;
  const auto groups = groups_for(particles, opt);
  auto covering = [&](const OverlapGroup& g) { return index_range(heights, g.box_lo.z(), g.box_hi.z()); };
  subtract_covered(groups.get(), norm, opt, covering,
                   each_value(covering, [&](const OverlapGroup& g, std::size_t j,
                                            double tol) { return covered_slice_area(g, heights[j], c.radius, tol); }),
                   sums, out.stats.overlap_groups);
  out.x.assign(heights.begin(), heights.end());
  finish(sums, norm, out.porosity, out.stats);
  return out;
}

PorosityMap porosity_map(std::span<const Particle> particles, const Container& c, std::span<const double> radii,
                         std::span<const double> heights, const ProfileOptions& opt) {
  check_container(c);
  require_sorted(radii, "radii");
  require_sorted(heights, "heights");
  for (double r : radii)
    if (!(r > 0)) throw InputError("map radii", "must be > 0 (got " + internal::cat(r) + ")");
  const Prepared prep = prepare(particles, c, opt.threads);
  const std::size_t nr = radii.size(), nz = heights.size();
  std::vector<double> norm(nr * nz);
  for (std::size_t iz = 0; iz < nz; ++iz)
    for (std::size_t ir = 0; ir < nr; ++ir) norm[iz * nr + ir] = 2 * std::numbers::pi * radii[ir];
  ProfileSums sums = run_chunks(prep, norm, opt, [&](const ParticleShape& s, ProfileSums& cr) {
    const auto [zb, ze] = index_range(heights, s.z_min(), s.z_max());
    const auto [rb, re] = index_range(radii, s.rho_min(), s.rho_max());
    for (std::size_t iz = zb; iz < ze; ++iz)
      for (std::size_t ir = rb; ir < re; ++ir) {
        cr.solid[iz * nr + ir].add(arc_length(s.particle(), heights[iz], radii[ir], opt.kernel));
        ++cr.evaluations;
      }
  });
  PorosityMap out;
  // Point values: the covered arcs are closed forms, no budget.
  const auto groups = groups_for(particles, opt);
  subtract_covered(
      groups.get(), norm, opt,
      [&](const OverlapGroup& g) {
        const auto [zb, ze] = index_range(heights, g.box_lo.z(), g.box_hi.z());
        return std::pair{zb * nr, ze * nr};
      },
      [&](const OverlapGroup& g, const std::vector<double>&, ProfileSums& cr) {
        const auto [zb, ze] = index_range(heights, g.box_lo.z(), g.box_hi.z());
        const auto [rb, re] = index_range(radii, g.rho_min(), g.rho_max());
        for (std::size_t iz = zb; iz < ze; ++iz)
          for (std::size_t ir = rb; ir < re; ++ir) {
            cr.solid[iz * nr + ir].add(-covered_arc_length(g, heights[iz], radii[ir]));
            ++cr.evaluations;
          }
      },
      sums, out.stats.overlap_groups);
  out.r.assign(radii.begin(), radii.end());
  out.z.assign(heights.begin(), heights.end());
  finish(sums, norm, out.porosity, out.stats);
  return out;
}

}  // namespace ssimarch
