// Uniform hash grid of particle indices (internal to porosity): neighbour queries for the generators
// and the Monte Carlo reference.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "ssimarch/porosity/particle.hpp"

namespace ssimarch::internal {

class SpatialGrid {
 public:
  explicit SpatialGrid(double cell) : cell_(cell) {}
  double cell() const { return cell_; }
  /// The cell index of a coordinate, clamped to +-2^60 (far coordinates share a cell rather than
  /// overflow the conversion; the key hashes only the low 21 bits anyway).
  long index(double v) const {
    const double q = std::floor(v / cell_);
    constexpr double kLimit = 1152921504606846976.0;  // 2^60
    return static_cast<long>(std::clamp(q, -kLimit, kLimit));
  }
  static std::int64_t key(long i, long j, long k) {
    return (static_cast<std::int64_t>(i & 0x1FFFFF) << 42) | (static_cast<std::int64_t>(j & 0x1FFFFF) << 21) |
           static_cast<std::int64_t>(k & 0x1FFFFF);
  }
  void insert(const Vec3& p, int id) { cells_[key(index(p.x()), index(p.y()), index(p.z()))].push_back(id); }
  /// Calls f(id) for every id stored in cells overlapping the box [p - reach, p + reach].
  template <class F>
  void visit(const Vec3& p, double reach, F&& f) const {
    const long i0 = index(p.x() - reach), i1 = index(p.x() + reach);
    const long j0 = index(p.y() - reach), j1 = index(p.y() + reach);
    const long k0 = index(p.z() - reach), k1 = index(p.z() + reach);
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j)
        for (long k = k0; k <= k1; ++k) {
          const auto it = cells_.find(key(i, j, k));
          if (it == cells_.end()) continue;
          for (int id : it->second) f(id);
        }
  }
  /// Same for the cells in layer k only (the generators' top-down fall search).
  template <class F>
  void visit_layer(double x, double y, double reach, long k, F&& f) const {
    for (long i = index(x - reach); i <= index(x + reach); ++i)
      for (long j = index(y - reach); j <= index(y + reach); ++j) {
        const auto it = cells_.find(key(i, j, k));
        if (it == cells_.end()) continue;
        for (int id : it->second) f(id);
      }
  }

 private:
  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace ssimarch::internal
