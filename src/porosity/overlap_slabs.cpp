// The overlap search over processes (overlaps.hpp, docs/scaling.md "Overlap search"): the bed is
// cut into horizontal slabs holding equal numbers of particle centres (quantiles of a histogram
// of the centres' heights, added over the processes); every particle is sent to the process of
// its slab and, as a neighbour, to the processes whose slabs lie within twice the largest reach of
// it. Each process then counts the pairs tested from the particles of its slab; a pair is tested
// from the particle first in (level, index), so it is counted by exactly one process.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "overlap_search.hpp"
#include "ssimarch/porosity/overlaps.hpp"

namespace ssimarch {

namespace {

// Histogram bins of the heights per process: the slabs' counts differ by at most a bin's.
constexpr long kBinsPerProcess = 1024;

// The slabs: process r owns the centres in bins [cut[r], cut[r + 1]) of `bins` equal bins of
// [z0, z0 + bins w]. Every process computes the same bins from the same doubles.
struct Slabs {
  double z0 = 0, w = 1;
  long bins = 1;
  std::vector<long> cut;
  long bin(double z) const {
    const double b = std::floor((z - z0) / w);
    return static_cast<long>(std::clamp(b, 0.0, static_cast<double>(bins - 1)));
  }
  int owner(double z) const {
    return static_cast<int>(std::upper_bound(cut.begin(), cut.end(), bin(z)) - cut.begin()) - 1;
  }
  double lower(int r) const { return z0 + w * static_cast<double>(cut[static_cast<std::size_t>(r)]); }
  double upper(int r) const { return z0 + w * static_cast<double>(cut[static_cast<std::size_t>(r) + 1]); }
};

Slabs make_slabs(std::span<const Particle> share, long total, const ProfileCommunicator& comm) {
  Slabs s;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Particle& p : share) lo = std::min(lo, p.centre.z()), hi = std::max(hi, p.centre.z());
  comm.min_max(lo, hi);
  const int n = comm.size();
  s.bins = kBinsPerProcess * n;
  s.z0 = lo;
  s.w = hi > lo ? (hi - lo) / static_cast<double>(s.bins) : 1.0;
  std::vector<long> hist(static_cast<std::size_t>(s.bins), 0);
  for (const Particle& p : share) ++hist[static_cast<std::size_t>(s.bin(p.centre.z()))];
  comm.sum(hist);
  // cut[r]: the first bin before which at least r/n of the centres lie.
  s.cut.assign(static_cast<std::size_t>(n) + 1, s.bins);
  s.cut[0] = 0;
  long below = 0;
  int r = 1;
  for (long b = 0; b < s.bins && r < n; ++b) {
    while (r < n && below * n >= total * r) s.cut[static_cast<std::size_t>(r++)] = b;
    below += hist[static_cast<std::size_t>(b)];
  }
  return s;
}

// A particle, its index in the packing and its clump id (0 when the packing has none) as bytes:
// centre, diameter, index and clump (48 bytes) when every particle is a sphere, with the axis and
// length as well (80 bytes) when not.
struct Record {
  double x, y, z, diameter;
  long id, clump;
};
struct RodRecord {
  Record r;
  double ux, uy, uz, length;
};

std::size_t record_size(bool rods) { return rods ? sizeof(RodRecord) : sizeof(Record); }

void put(char* at, const Particle& p, long id, long clump, bool rods) {
  const RodRecord rec{
      {p.centre.x(), p.centre.y(), p.centre.z(), p.diameter, id, clump}, p.axis.x(), p.axis.y(), p.axis.z(), p.length};
  std::memcpy(at, &rec, record_size(rods));
}

Particle particle_at(const char* at, bool rods, long& id, long& clump) {
  RodRecord rec{{0, 0, 0, 0, 0, 0}, 0, 0, 1, 0};
  std::memcpy(&rec, at, record_size(rods));
  Particle p;
  p.centre = Vec3(rec.r.x, rec.r.y, rec.r.z);
  p.diameter = rec.r.diameter;
  p.axis = Vec3(rec.ux, rec.uy, rec.uz);
  p.length = rec.length;
  id = rec.r.id;
  clump = rec.r.clump;
  return p;
}

// The particles for each process, one message after the other: each particle to its slab's
// process and to those within `margin` of it. Two passes: the counts, then the bytes.
std::string route(std::span<const Particle> share, std::span<const long> clumps, long first, const Slabs& s,
                  double margin, int n, bool rods, std::vector<std::size_t>& counts) {
  auto each_destination = [&](std::size_t k, auto&& f) {
    const double z = share[k].centre.z();
    const int o = s.owner(z);
    f(o);
    for (int q = o - 1; q >= 0 && z < s.upper(q) + margin; --q) f(q);
    for (int q = o + 1; q < n && z >= s.lower(q) - margin; ++q) f(q);
  };
  counts.assign(static_cast<std::size_t>(n), 0);
  for (std::size_t k = 0; k < share.size(); ++k)
    each_destination(k, [&](int q) { counts[static_cast<std::size_t>(q)] += record_size(rods); });
  std::vector<std::size_t> at(static_cast<std::size_t>(n), 0);
  for (std::size_t q = 1; q < at.size(); ++q) at[q] = at[q - 1] + counts[q - 1];
  std::string bytes(at.back() + counts.back(), '\0');
  for (std::size_t k = 0; k < share.size(); ++k)
    each_destination(k, [&](int q) {
      put(bytes.data() + at[static_cast<std::size_t>(q)], share[k], first + static_cast<long>(k),
          clumps.empty() ? 0 : clumps[k], rods);
      at[static_cast<std::size_t>(q)] += record_size(rods);
    });
  return bytes;
}

}  // namespace

namespace internal {

SlabShare gather_slab(std::span<const Particle> share, long first, const ProfileCommunicator& comm,
                      std::span<const long> clumps) {
  SlabShare out;
  out.total = static_cast<long>(share.size());
  comm.sum(std::span<long>(&out.total, 1));
  if (out.total < 2) return out;
  double unused = 0, vmax = 0, rmax = 0;
  for (const Particle& p : share) vmax = std::max(vmax, p.volume()), rmax = std::max(rmax, p.half_length() + p.radius());
  comm.min_max(unused, vmax);
  comm.min_max(unused, rmax);
  out.volume_scale = vmax > 0 ? vmax * static_cast<double>(out.total) : 1.0;
  const Slabs slabs = make_slabs(share, out.total, comm);
  // Two particles that overlap have centres closer than the sum of their reaches; a bin's width
  // more absorbs the rounding of the slab bounds.
  const double margin = 2 * rmax + slabs.w;
  bool rods = false;
  for (const Particle& p : share) rods = rods || p.length != 0;
  rods = comm.any(rods);
  const bool clumped = comm.any(!clumps.empty());
  std::vector<std::size_t> counts;
  std::string bytes = route(share, clumps, first, slabs, margin, comm.size(), rods, counts);
  bytes = comm.exchange(std::move(bytes), counts);
  // This slab's particles first, then the neighbours'.
  const std::size_t size = record_size(rods), n = bytes.size() / size;
  out.local.reserve(n);
  out.ids.reserve(n);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t k = 0; k < n; ++k) {
      long id = 0, clump = 0;
      const Particle p = particle_at(bytes.data() + k * size, rods, id, clump);
      if ((slabs.owner(p.centre.z()) == comm.rank()) != (pass == 0)) continue;
      out.local.push_back(p);
      out.ids.push_back(id);
      if (clumped) out.clumps.push_back(clump);
    }
  while (out.owned < out.local.size() && slabs.owner(out.local[out.owned].centre.z()) == comm.rank()) ++out.owned;
  return out;
}

}  // namespace internal

ParticleOverlaps find_overlaps(std::span<const Particle> share, long first, const ProfileCommunicator& comm,
                               double relative_tolerance, unsigned threads, std::span<const long> clumps) {
  ParticleOverlaps out;
  internal::require_clump_per_particle(clumps.size(), share.size());
  const internal::SlabShare slab = internal::gather_slab(share, first, comm, clumps);
  if (slab.total < 2) return out;
  const double scale = slab.volume_scale;
  double unused = 0;
  const internal::OverlapTallies both =
      internal::search_overlaps(slab.local, slab.ids, slab.owned, relative_tolerance, scale, threads, slab.clumps);
  const internal::PairTally& t = both.between;
  // Totals: the counts and the exact volume sums in one reduction; the deepest pair by its depth,
  // then the smallest first index, then the smallest second.
  ProfileSums sums;
  sums.solid.push_back(t.volume);
  sums.solid.push_back(both.within.volume);
  sums.error.emplace_back(scale);
  sums.error.emplace_back(scale);
  sums.evaluations = t.pairs;
  comm.sum(sums);
  long within = both.within.pairs;
  comm.sum(std::span<long>(&within, 1));
  out.pairs = sums.evaluations;
  out.doubled_volume = sums.solid[0].value();
  out.clump_pairs = within;
  out.clump_doubled_volume = sums.solid[1].value();
  double depth = t.depth;
  comm.min_max(unused, depth);
  const long none = std::numeric_limits<long>::max();
  const bool deepest = t.first >= 0 && t.depth == depth;
  const long f = -comm.max(-(deepest ? t.first : none));
  const long g = -comm.max(-(deepest && t.first == f ? t.second : none));
  if (out.pairs > 0) out.max_depth = depth, out.worst_first = f, out.worst_second = g;
  return out;
}

}  // namespace ssimarch
