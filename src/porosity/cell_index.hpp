// Particles of one grid level sorted by cubic cell (internal to porosity: the overlap search).
// Where the level's bounding box holds few enough cells (at most 4 per particle, plus 4096), the
// cells are a dense array of offsets (a counting sort; a query reads one contiguous run per row of
// cells along z); otherwise an open-addressing table maps each occupied cell, keyed like
// SpatialGrid (21 bits per axis: far cells may share a key, which only adds candidates, never
// loses one), to its run. Built once, then read by any number of threads.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "spatial_grid.hpp"

namespace ssimarch::internal {

class CellIndex {
 public:
  /// The particles `members` (indices for `centre_of`) in cells of side `cell`.
  template <class CentreOf>
  CellIndex(double cell, std::span<const std::uint32_t> members, CentreOf&& centre_of) : grid_(cell) {
    for (int a = 0; a < 3; ++a) lo_[a] = members.empty() ? 0 : grid_.index(centre_of(members[0])[a]), hi_[a] = lo_[a];
    for (std::uint32_t m : members)
      for (int a = 0; a < 3; ++a) {
        const long c = grid_.index(centre_of(m)[a]);
        lo_[a] = std::min(lo_[a], c);
        hi_[a] = std::max(hi_[a], c);
      }
    double cells = 1;
    for (int a = 0; a < 3; ++a) cells *= static_cast<double>(hi_[a] - lo_[a] + 1);
    dense_ = cells <= 4.0 * static_cast<double>(members.size()) + 4096 && cells < 2147483648.0;
    if (dense_)
      build_dense(members, centre_of);
    else
      build_table(members, centre_of);
  }

  /// The members sorted by cell: neighbours in space are near each other in this order.
  std::span<const std::uint32_t> order() const { return order_; }

  /// Calls f(member) for every member in a cell overlapping the box [p - reach, p + reach].
  template <class F>
  void visit(const Vec3& p, double reach, F&& f) const {
    long b[3], e[3];
    for (int a = 0; a < 3; ++a) {
      b[a] = grid_.index(p[a] - reach);
      e[a] = grid_.index(p[a] + reach);
    }
    if (dense_) {
      for (int a = 0; a < 3; ++a) b[a] = std::max(b[a], lo_[a]), e[a] = std::min(e[a], hi_[a]);
      if (b[2] > e[2]) return;
      for (long i = b[0]; i <= e[0]; ++i)
        for (long j = b[1]; j <= e[1]; ++j) {
          const std::size_t row = linear(i, j, 0);
          const std::uint32_t from = start_[row + static_cast<std::size_t>(b[2] - lo_[2])];
          const std::uint32_t to = start_[row + static_cast<std::size_t>(e[2] - lo_[2]) + 1];
          for (std::uint32_t m = from; m < to; ++m) f(order_[m]);
        }
      return;
    }
    for (long i = b[0]; i <= e[0]; ++i)
      for (long j = b[1]; j <= e[1]; ++j)
        for (long k = b[2]; k <= e[2]; ++k) {
          const Slot* s = find(SpatialGrid::key(i, j, k));
          if (!s) continue;
          for (std::uint32_t m = s->begin; m < s->end; ++m) f(order_[m]);
        }
  }

 private:
  struct Slot {
    std::int64_t key = -1;  // keys are >= 0: -1 marks an empty slot
    std::uint32_t begin = 0, end = 0;
  };

  // Index of cell (i, j, k0 + k) in the dense array: z fastest.
  std::size_t linear(long i, long j, long k) const {
    const auto ny = static_cast<std::size_t>(hi_[1] - lo_[1] + 1), nz = static_cast<std::size_t>(hi_[2] - lo_[2] + 1);
    return (static_cast<std::size_t>(i - lo_[0]) * ny + static_cast<std::size_t>(j - lo_[1])) * nz +
           static_cast<std::size_t>(k);
  }

  template <class CentreOf>
  void build_dense(std::span<const std::uint32_t> members, CentreOf& centre_of) {
    const std::size_t cells = linear(hi_[0], hi_[1], hi_[2] - lo_[2]) + 1;
    std::vector<std::uint32_t> cell_of(members.size());
    start_.assign(cells + 1, 0);
    for (std::size_t k = 0; k < members.size(); ++k) {
      const Vec3& c = centre_of(members[k]);
      cell_of[k] = static_cast<std::uint32_t>(linear(grid_.index(c.x()), grid_.index(c.y()), grid_.index(c.z()) - lo_[2]));
      ++start_[cell_of[k] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    // start_[c + 1] is now the end of cell c; placing the members backwards moves it to the cell's
    // beginning (members stay in their order within a cell), and one shift restores start_[c].
    order_.resize(members.size());
    for (std::size_t k = members.size(); k-- > 0;) order_[--start_[cell_of[k] + 1]] = members[k];
    start_.erase(start_.begin());
    start_.push_back(static_cast<std::uint32_t>(members.size()));
  }

  template <class CentreOf>
  void build_table(std::span<const std::uint32_t> members, CentreOf& centre_of) {
    std::vector<std::pair<std::int64_t, std::uint32_t>> keyed;
    keyed.reserve(members.size());
    for (std::uint32_t m : members) {
      const Vec3& c = centre_of(m);
      keyed.emplace_back(SpatialGrid::key(grid_.index(c.x()), grid_.index(c.y()), grid_.index(c.z())), m);
    }
    std::sort(keyed.begin(), keyed.end());
    std::size_t runs = 0;
    for (std::size_t k = 0; k < keyed.size(); ++k) runs += k == 0 || keyed[k].first != keyed[k - 1].first;
    std::size_t size = 16;
    while (size < 2 * runs) size *= 2;
    slots_.assign(size, Slot{});
    mask_ = size - 1;
    order_.resize(keyed.size());
    for (std::size_t k = 0, b = 0; k < keyed.size(); ++k) {
      order_[k] = keyed[k].second;
      if (k + 1 == keyed.size() || keyed[k + 1].first != keyed[k].first) {
        insert(keyed[k].first, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(k + 1));
        b = k + 1;
      }
    }
  }

  static std::size_t hash(std::int64_t key) {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ull) >> 20);
  }
  void insert(std::int64_t key, std::uint32_t b, std::uint32_t e) {
    std::size_t h = hash(key) & mask_;
    while (slots_[h].key >= 0) h = (h + 1) & mask_;
    slots_[h] = {key, b, e};
  }
  const Slot* find(std::int64_t key) const {
    for (std::size_t h = hash(key) & mask_;; h = (h + 1) & mask_) {
      if (slots_[h].key == key) return &slots_[h];
      if (slots_[h].key < 0) return nullptr;
    }
  }

  SpatialGrid grid_;
  bool dense_ = false;
  long lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};  // the members' cells (dense array bounds)
  std::vector<std::uint32_t> start_;             // dense: start_[c] .. start_[c + 1] in order_
  std::vector<std::uint32_t> order_;
  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
};

}  // namespace ssimarch::internal
