// Profiles of a packing. Source: docs/porosity.md ("Profiles"); per-particle integrals in
// particle_integrals.cpp.
#include "ssimarch/porosity/profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"

#include "parallel.hpp"

namespace ssimarch {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxChunks = 256;

std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

void check_container(const Container& c) {
  if (!(c.radius > 0) || !std::isfinite(c.radius))
    throw InputError("container.radius", "must be a finite number > 0 (got " + number(c.radius) + ")");
  if (!(c.slab.z_max > c.slab.z_min) || !std::isfinite(c.slab.z_min) || !std::isfinite(c.slab.z_max))
    throw InputError("container.slab", "the height range [z_min, z_max] needs finite z_min < z_max (got [" +
                                           number(c.slab.z_min) + ", " + number(c.slab.z_max) + "])");
}

struct Prepared {
  std::vector<ParticleShape> shapes;
  long clipped = 0;
};

// Shapes of the particles that overlap the container; counts those sticking out of it.
Prepared prepare(std::span<const Particle> ps, const Container& c) {
  Prepared out;
  out.shapes.reserve(ps.size());
  for (const Particle& p : ps) {
    ParticleShape s(p);
    if (s.rho_min() >= c.radius || s.z_max() <= c.slab.z_min || s.z_min() >= c.slab.z_max) continue;
    if (s.rho_max() > c.radius || s.z_min() < c.slab.z_min || s.z_max() > c.slab.z_max) ++out.clipped;
    out.shapes.push_back(std::move(s));
  }
  return out;
}

struct ChunkResult {
  std::vector<double> sum, err;
  long evals = 0, unconverged = 0;
};

// Runs per-particle work over fixed chunks and reduces in chunk order (thread-count independent).
template <class F>
std::vector<ChunkResult> run_chunks(const std::vector<ParticleShape>& shapes, std::size_t nvalues,
                                    const ProfileOptions& opt, F&& per_particle) {
  const int n = static_cast<int>(shapes.size());
  // Each chunk holds its own accumulators: cap their memory at about 32 MB for large maps.
  const int mem_cap = static_cast<int>(std::max<std::size_t>(8, 2'000'000 / std::max<std::size_t>(1, nvalues)));
  const int chunks = std::max(1, std::min({kMaxChunks, n, mem_cap}));
  std::vector<ChunkResult> res(chunks);
  internal::parallel_chunks(
      chunks, opt.threads,
      [&](int k) {
        ChunkResult& cr = res[k];
        cr.sum.assign(nvalues, 0.0);
        cr.err.assign(nvalues, 0.0);
        const int b = static_cast<int>(static_cast<long>(n) * k / chunks);
        const int e = static_cast<int>(static_cast<long>(n) * (k + 1) / chunks);
        // Ctrl-C: the rest of the chunk is skipped; parallel_chunks throws Interrupted.
        for (int i = b; i < e && !interrupt_requested(); ++i) per_particle(shapes[i], cr);
      },
      opt.progress);
  return res;
}

void reduce(const std::vector<ChunkResult>& res, std::vector<double>& sum, std::vector<double>& err,
            ProfileStats& st) {
  for (const auto& cr : res) {
    for (std::size_t j = 0; j < sum.size(); ++j) {
      sum[j] += cr.sum[j];
      err[j] += cr.err[j];
    }
    st.evaluations += cr.evals;
    st.unconverged += cr.unconverged;
  }
}

void account(ChunkResult& cr, std::size_t j, const QuadResult& q) {
  cr.sum[j] += q.value;
  cr.err[j] += q.error;
  cr.evals += q.evaluations;
  if (q.status != QuadStatus::kConverged) ++cr.unconverged;
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
      throw InputError(what, "must be finite (value " + std::to_string(k) + " is " + number(v[k]) + ")");
    if (k > 0 && !(v[k] > v[k - 1]))
      throw InputError(what, "must be strictly increasing (value " + std::to_string(k) + " is " + number(v[k]) +
                                 " after " + number(v[k - 1]) + ")");
  }
}

// Volume of a ball between two horizontal planes: integral of pi (a^2 - (z - z_c)^2) dz.
double sphere_slab_volume(const Particle& p, const BedSlab& slab) {
  const double a = p.radius();
  const double lo = std::clamp(slab.z_min - p.centre.z(), -a, a), hi = std::clamp(slab.z_max - p.centre.z(), -a, a);
  auto F = [&](double t) { return kPi * (a * a * t - t * t * t / 3); };
  return hi > lo ? F(hi) - F(lo) : 0.0;
}

}  // namespace

double Container::volume() const { return kPi * radius * radius * height(); }

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
      throw InputError("radii", "must lie in (0, R] = (0, " + number(c.radius) + "] (got " + number(r) + ")");
  const Prepared prep = prepare(particles, c);
  const std::size_t m = radii.size();
  // Particles touching each radius, to split the accuracy budget.
  std::vector<long> count(m, 0);
  for (const auto& s : prep.shapes) {
    const auto [b, e] = index_range(radii, s.rho_min(), s.rho_max());
    for (std::size_t j = b; j < e; ++j) ++count[j];
  }
  std::vector<double> budget(m);
  for (std::size_t j = 0; j < m; ++j)
    budget[j] = 0.5 * opt.tolerance * 2 * kPi * radii[j] * c.height() / std::max(1L, count[j]);
  auto res = run_chunks(prep.shapes, m, opt, [&](const ParticleShape& s, ChunkResult& cr) {
    const auto [b, e] = index_range(radii, s.rho_min(), s.rho_max());
    for (std::size_t j = b; j < e; ++j)
      account(cr, j, lateral_area(s, radii[j], c.slab, budget[j], opt.method, opt.kernel));
  });
  PorosityProfile out;
  out.x.assign(radii.begin(), radii.end());
  std::vector<double> sum(m, 0.0), err(m, 0.0);
  reduce(res, sum, err, out.stats);
  out.porosity.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    const double norm = 2 * kPi * radii[j] * c.height();
    out.porosity[j] = 1 - sum[j] / norm;
    out.stats.max_error = std::max(out.stats.max_error, err[j] / norm);
  }
  out.stats.particles_used = static_cast<long>(prep.shapes.size());
  out.stats.particles_clipped = prep.clipped;
  return out;
}

PorosityProfile bin_profile(std::span<const Particle> particles, const Container& c, std::span<const double> edges,
                    const ProfileOptions& opt) {
  check_container(c);
  require_sorted(edges, "bin edges");
  if (edges.size() < 2 || edges.front() < 0 || edges.back() > c.radius)
    throw InputError("bin edges", "need at least two values within [0, R] = [0, " + number(c.radius) + "]");
  const Prepared prep = prepare(particles, c);
  const std::size_t m = edges.size() - 1;
  std::vector<long> count(m, 0);
  auto bins_of = [&](const ParticleShape& s) {
    // Bins k with [edges[k], edges[k+1]] overlapping [rho_min, rho_max].
    const auto ub = std::upper_bound(edges.begin(), edges.end(), s.rho_min());
    const std::size_t b = ub == edges.begin() ? 0 : static_cast<std::size_t>(ub - edges.begin()) - 1;
    const auto lb = std::lower_bound(edges.begin(), edges.end(), s.rho_max());
    const std::size_t e = std::min(m, static_cast<std::size_t>(lb - edges.begin()));
    return std::pair{b, std::max(b, e)};
  };
  for (const auto& s : prep.shapes) {
    const auto [b, e] = bins_of(s);
    for (std::size_t k = b; k < e; ++k) ++count[k];
  }
  std::vector<double> norm(m), budget(m);
  for (std::size_t k = 0; k < m; ++k) {
    norm[k] = kPi * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k]) * c.height();
    budget[k] = 0.5 * opt.tolerance * norm[k] / std::max(1L, count[k]);
  }
  auto res = run_chunks(prep.shapes, m, opt, [&](const ParticleShape& s, ChunkResult& cr) {
    const auto [b, e] = bins_of(s);
    const bool in_slab = s.z_min() >= c.slab.z_min && s.z_max() <= c.slab.z_max;
    for (std::size_t k = b; k < e; ++k) {
      const bool in_annulus = s.rho_min() >= edges[k] && s.rho_max() <= edges[k + 1];
      if (in_annulus && in_slab) {
        cr.sum[k] += s.particle().volume();  // whole particle inside this annulus: closed form
        continue;
      }
      if (in_annulus && s.particle().length == 0) {
        cr.sum[k] += sphere_slab_volume(s.particle(), c.slab);  // sphere cut by the planes: caps
        continue;
      }
      account(cr, k, shell_volume(s, edges[k], edges[k + 1], c.slab, budget[k], opt.method, opt.kernel));
    }
  });
  PorosityProfile out;
  out.x.assign(edges.begin(), edges.end() - 1);
  out.x_upper.assign(edges.begin() + 1, edges.end());
  std::vector<double> sum(m, 0.0), err(m, 0.0);
  reduce(res, sum, err, out.stats);
  out.porosity.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    out.porosity[k] = 1 - sum[k] / norm[k];
    out.stats.max_error = std::max(out.stats.max_error, err[k] / norm[k]);
  }
  out.stats.particles_used = static_cast<long>(prep.shapes.size());
  out.stats.particles_clipped = prep.clipped;
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
  const Prepared prep = prepare(particles, c);
  const std::size_t m = heights.size();
  std::vector<long> count(m, 0);
  for (const auto& s : prep.shapes) {
    const auto [b, e] = index_range(heights, s.z_min(), s.z_max());
    for (std::size_t j = b; j < e; ++j) ++count[j];
  }
  const double area = kPi * c.radius * c.radius;
  std::vector<double> budget(m);
  for (std::size_t j = 0; j < m; ++j) budget[j] = 0.5 * opt.tolerance * area / std::max(1L, count[j]);
  auto res = run_chunks(prep.shapes, m, opt, [&](const ParticleShape& s, ChunkResult& cr) {
    const auto [b, e] = index_range(heights, s.z_min(), s.z_max());
    for (std::size_t j = b; j < e; ++j) account(cr, j, slice_area(s, heights[j], c.radius, budget[j], opt.kernel, opt.method));
  });
  PorosityProfile out;
  out.x.assign(heights.begin(), heights.end());
  std::vector<double> sum(m, 0.0), err(m, 0.0);
  reduce(res, sum, err, out.stats);
  out.porosity.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    out.porosity[j] = 1 - sum[j] / area;
    out.stats.max_error = std::max(out.stats.max_error, err[j] / area);
  }
  out.stats.particles_used = static_cast<long>(prep.shapes.size());
  out.stats.particles_clipped = prep.clipped;
  return out;
}

PorosityMap porosity_map(std::span<const Particle> particles, const Container& c, std::span<const double> radii,
                         std::span<const double> heights, const ProfileOptions& opt) {
  check_container(c);
  require_sorted(radii, "radii");
  require_sorted(heights, "heights");
  for (double r : radii)
    if (!(r > 0)) throw InputError("map radii", "must be > 0 (got " + number(r) + ")");
  const Prepared prep = prepare(particles, c);
  const std::size_t nr = radii.size(), nz = heights.size();
  PorosityMap out;
  out.r.assign(radii.begin(), radii.end());
  out.z.assign(heights.begin(), heights.end());
  auto res = run_chunks(prep.shapes, nr * nz, opt, [&](const ParticleShape& s, ChunkResult& cr) {
    const auto [zb, ze] = index_range(heights, s.z_min(), s.z_max());
    const auto [rb, re] = index_range(radii, s.rho_min(), s.rho_max());
    for (std::size_t iz = zb; iz < ze; ++iz)
      for (std::size_t ir = rb; ir < re; ++ir) {
        cr.sum[iz * nr + ir] += arc_length(s.particle(), heights[iz], radii[ir], opt.kernel);
        ++cr.evals;
      }
  });
  std::vector<double> sum(nr * nz, 0.0), err(nr * nz, 0.0);
  reduce(res, sum, err, out.stats);
  out.porosity.resize(nr * nz);
  for (std::size_t iz = 0; iz < nz; ++iz)
    for (std::size_t ir = 0; ir < nr; ++ir)
      out.porosity[iz * nr + ir] = 1 - sum[iz * nr + ir] / (2 * kPi * radii[ir]);
  out.stats.particles_used = static_cast<long>(prep.shapes.size());
  out.stats.particles_clipped = prep.clipped;
  return out;
}

}  // namespace ssimarch
