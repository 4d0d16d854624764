// Overlap groups (particle_union.hpp): for every particle, the earlier particles overlapping it,
// found on a hierarchical grid as the overlap search finds pairs (overlaps.cpp), and split into
// components whose covered parts lie apart. Source: docs/math/particle_union.md.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>

#include "overlap_search.hpp"
#include "parallel.hpp"
#include "ssimarch/porosity/particle_union.hpp"

namespace ssimarch {

namespace {

// Axis-aligned box of a spherocylinder: the segment's box grown by the radius.
void particle_box(const Particle& p, Vec3& lo, Vec3& hi) {
  const Vec3 ext = p.half_length() * p.axis.cwiseAbs() + Vec3::Constant(p.radius());
  lo = p.centre - ext;
  hi = p.centre + ext;
}

// A box holding P n Q: the two particles' boxes intersected, and for two spheres meeting in a
// circle also the box of a ball holding their lens (centre on the circle's plane, radius from the
// circle's radius and the taller cap's height).
void lens_box(const Particle& p, const Particle& q, Vec3& lo, Vec3& hi) {
  Vec3 lq, hq;
  particle_box(p, lo, hi);
  particle_box(q, lq, hq);
  lo = lo.cwiseMax(lq);
  hi = hi.cwiseMin(hq);
  if (p.length != 0 || q.length != 0) return;
  const Vec3 d = q.centre - p.centre;
  const double D = d.norm(), a = p.radius(), b = q.radius();
  if (!(D > std::abs(a - b)) || !(D < a + b)) return;
  const double t = (D * D + a * a - b * b) / (2 * D);
  if (t < 0 || t > D) return;  // a centre beyond the circle's plane: the caps are not the bound used
  const double rho2 = std::max(0.0, (a - t) * (a + t)), cap = std::max(a - t, b - (D - t));
  const double R = std::sqrt(rho2 + cap * cap);
  const Vec3 c = p.centre + (t / D) * d;
  lo = lo.cwiseMax(c - Vec3::Constant(R));
  hi = hi.cwiseMin(c + Vec3::Constant(R));
}

bool boxes_meet(const Vec3& alo, const Vec3& ahi, const Vec3& blo, const Vec3& bhi) {
  return (alo.array() <= bhi.array()).all() && (blo.array() <= ahi.array()).all();
}

bool overlapping(const Particle& a, const Particle& b, double relative_tolerance) {
  return internal::pair_overlap(a, b).depth > relative_tolerance * std::min(a.diameter, b.diameter);
}

// The groups found by one chunk of queries: entries whose members index its own member list.
struct ChunkGroups {
  std::vector<OverlapGroupSet::Entry> entries;
  std::vector<std::uint32_t> members;
};

// The groups of particle i with its earlier neighbours `nb` (sorted by id): components of the
// graph whose edges join neighbours with meeting lens boxes.
void split_groups(std::span<const Particle> ps, std::uint32_t i, const std::vector<std::uint32_t>& nb,
                  ChunkGroups& out) {
  const std::size_t n = nb.size();
  const Particle& p = ps[i];
  if (n == 1) {  // one lens: no components to find
    OverlapGroupSet::Entry& e = out.entries.emplace_back();
    lens_box(p, ps[nb[0]], e.box_lo, e.box_hi);
    e.first = static_cast<std::uint32_t>(out.members.size()), e.count = 2;
    out.members.push_back(i), out.members.push_back(nb[0]);
    return;
  }
  // Per thread, reused across the particles of a chunk.
  thread_local std::vector<Vec3> lo, hi;
  thread_local std::vector<std::size_t> root;
  lo.resize(n), hi.resize(n), root.resize(n);
  for (std::size_t k = 0; k < n; ++k) lens_box(p, ps[nb[k]], lo[k], hi[k]);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](std::size_t k) {
    while (root[k] != k) k = root[k] = root[root[k]];
    return k;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (boxes_meet(lo[a], hi[a], lo[b], hi[b])) root[find(b)] = find(a);
  for (std::size_t a = 0; a < n; ++a) {
    if (find(a) != a) continue;
    OverlapGroupSet::Entry& e = out.entries.emplace_back();
    e.box_lo = lo[a], e.box_hi = hi[a];
    e.first = static_cast<std::uint32_t>(out.members.size());
    out.members.push_back(i);
    for (std::size_t b = 0; b < n; ++b)
      if (find(b) == a) {
        out.members.push_back(nb[b]);
        e.box_lo = e.box_lo.cwiseMin(lo[b]);
        e.box_hi = e.box_hi.cwiseMax(hi[b]);
      }
    e.count = static_cast<std::uint32_t>(out.members.size()) - e.first;
  }
}

}  // namespace

namespace internal {

OverlapGroupSet groups_of(std::span<const Particle> ps, std::span<const long> ids, std::size_t owned,
                          double relative_tolerance, unsigned threads, std::vector<Particle>* held) {
  auto id = [&](std::size_t k) { return ids.empty() ? static_cast<long>(k) : ids[k]; };
  // The overlap search's hierarchical grid (overlaps.cpp), queried in its cells' order as the
  // search does: consecutive queries meet the same neighbours, which stay in the cache whatever the
  // order of the file (the groups' order does not matter: the profiles' sums are exact).
  const std::map<int, GridLevel> levels = grid_levels(ps);
  std::vector<const std::uint32_t*> order;
  std::vector<std::size_t> level_start{0};
  for (const auto& [k, L] : levels) {
    order.push_back(L.cells->order().data());
    level_start.push_back(level_start.back() + L.cells->order().size());
  }
  const std::size_t nq = level_start.back();
  const int chunks = static_cast<int>(std::min<std::size_t>(kOverlapQueryChunks, std::max<std::size_t>(nq, 1)));
  std::vector<ChunkGroups> found(static_cast<std::size_t>(chunks));
  parallel_chunks(
      chunks, threads,
      [&](int c) {
        std::vector<std::uint32_t> nb;
        std::size_t lv = 0;
        for (std::size_t q = nq * static_cast<std::size_t>(c) / chunks;
             q < nq * static_cast<std::size_t>(c + 1) / chunks; ++q) {
          while (q >= level_start[lv + 1]) ++lv;
          const std::size_t i = order[lv][q - level_start[lv]];
          if (i >= owned) continue;  // a neighbour from another process: its own process asks
          nb.clear();
          // Every level, so that each particle sees all its earlier neighbours on this process.
          for (const auto& [k, L] : levels)
            L.cells->visit(ps[i].centre, reach(ps[i]) + L.max_reach, [&](std::uint32_t j) {
              if (id(j) < id(i) && overlapping(ps[i], ps[j], relative_tolerance)) nb.push_back(j);
            });
          if (nb.empty()) continue;
          std::sort(nb.begin(), nb.end(), [&](std::uint32_t a, std::uint32_t b) { return id(a) < id(b); });
          split_groups(ps, static_cast<std::uint32_t>(i), nb, found[static_cast<std::size_t>(c)]);
        }
      },
      nullptr);
  // The chunks' lists joined, each allocated once: every page a growing vector touches costs a
  // page fault, and a DEM bed has three groups per particle.
  std::size_t ne = 0, nm = 0;
  for (const ChunkGroups& f : found) ne += f.entries.size(), nm += f.members.size();
  std::vector<OverlapGroupSet::Entry> entries;
  std::vector<std::uint32_t> members;
  entries.reserve(ne), members.reserve(nm);
  for (ChunkGroups& f : found) {
    const auto shift = static_cast<std::uint32_t>(members.size());
    for (OverlapGroupSet::Entry e : f.entries) {
      e.first += shift;
      entries.push_back(e);
    }
    members.insert(members.end(), f.members.begin(), f.members.end());
    f = ChunkGroups{};
  }
  std::vector<Particle> kept;
  if (held && !entries.empty()) kept = std::move(*held);
  const std::span<const Particle> at = kept.empty() ? ps : std::span<const Particle>(kept);
  return OverlapGroupSet(at, std::move(kept), std::move(entries), std::move(members));
}

}  // namespace internal

OverlapGroupSet::OverlapGroupSet(std::span<const Particle> particles, std::vector<Particle> held,
                                 std::vector<Entry> entries, std::vector<std::uint32_t> members)
    : held_(std::move(held)),
      particles_(held_.empty() ? particles : std::span<const Particle>(held_)),
      entries_(std::move(entries)),
      members_(std::move(members)) {}

void OverlapGroupSet::get(std::size_t k, OverlapGroup& g) const {
  const Entry& e = entries_[k];
  g.particle = particles_[members_[e.first]];
  g.earlier.clear();
  for (std::uint32_t m = e.first + 1; m < e.first + e.count; ++m) g.earlier.push_back(particles_[members_[m]]);
  g.box_lo = e.box_lo, g.box_hi = e.box_hi;
}

std::vector<OverlapGroup> OverlapGroupSet::all() const {
  std::vector<OverlapGroup> out(size());
  for (std::size_t k = 0; k < size(); ++k) get(k, out[k]);
  return out;
}

std::shared_ptr<const OverlapGroupSet> overlap_group_set(std::span<const Particle> particles, double relative_tolerance,
                                                         unsigned threads) {
  return std::make_shared<const OverlapGroupSet>(
      internal::groups_of(particles, {}, particles.size(), relative_tolerance, threads));
}

std::shared_ptr<const OverlapGroupSet> overlap_group_set(std::span<const Particle> share, long first,
                                                         const ProfileCommunicator& comm, double relative_tolerance,
                                                         unsigned threads) {
  internal::SlabShare slab = internal::gather_slab(share, first, comm);
  if (slab.total < 2) return std::make_shared<const OverlapGroupSet>();
  return std::make_shared<const OverlapGroupSet>(
      internal::groups_of(slab.local, slab.ids, slab.owned, relative_tolerance, threads, &slab.local));
}

std::vector<OverlapGroup> overlap_groups(std::span<const Particle> particles, double relative_tolerance,
                                         unsigned threads) {
  return overlap_group_set(particles, relative_tolerance, threads)->all();
}

std::vector<OverlapGroup> overlap_groups(std::span<const Particle> share, long first, const ProfileCommunicator& comm,
                                         double relative_tolerance, unsigned threads) {
  return overlap_group_set(share, first, comm, relative_tolerance, threads)->all();
}

}  // namespace ssimarch
