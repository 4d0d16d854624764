// Exact nearest neighbour among fixed points of space: a k-d tree (Bentley, "Multidimensional
// binary search trees used for associative searching", CACM 18(9), 1975). Built in O(m log m),
// a query costs O(log m) on well-spread points (the samples of a surface), so pairing n^2 samples of
// one surface with n^2 of the other costs O(n^2 log n) instead of the O(n^4) of a scan. Used by the
// sampling start-point search.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch::internal {

class NearestPointTree {
 public:
  explicit NearestPointTree(std::vector<Vec3> points) : points_(std::move(points)), order_(points_.size()) {
    // A point that is not finite (a surface evaluated outside its formula's domain) is never the
    // nearest; at infinity it keeps the ordering of the build total.
    for (Vec3& p : points_)
      if (!p.allFinite()) p.setConstant(std::numeric_limits<double>::infinity());
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    build(0, order_.size(), 0);
  }

  /// Index of the point nearest to x; of several equally near, the lowest index (as a scan in
  /// index order with a strict comparison would pick); 0 when none is at a finite distance.
  std::size_t nearest(const Vec3& x) const {
    Best best;
    search(0, order_.size(), 0, x, &best);
    return best.index < points_.size() ? best.index : 0;
  }

 private:
  struct Best {
    double d2 = std::numeric_limits<double>::infinity();
    std::size_t index = std::numeric_limits<std::size_t>::max();
  };

  // order_[lo, hi) is a subtree: its median (by coordinate `axis`) at mid, the halves beside it.
  void build(std::size_t lo, std::size_t hi, int axis) {
    if (hi - lo <= 1) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(lo),
                     order_.begin() + static_cast<std::ptrdiff_t>(mid),
                     order_.begin() + static_cast<std::ptrdiff_t>(hi),
                     [&](std::size_t a, std::size_t b) { return points_[a][axis] < points_[b][axis]; });
    build(lo, mid, (axis + 1) % 3);
    build(mid + 1, hi, (axis + 1) % 3);
  }

  void search(std::size_t lo, std::size_t hi, int axis, const Vec3& x, Best* best) const {
    if (lo >= hi) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    const std::size_t k = order_[mid];
    const double d2 = (points_[k] - x).squaredNorm();
    if (d2 < best->d2 || (d2 == best->d2 && k < best->index)) *best = {d2, k};
    const double gap = x[axis] - points_[k][axis];
    const int next = (axis + 1) % 3;
    // Near side first; the far side only when the splitting plane is not farther than the best
    // (<=, so that an equally near point of lower index is still found).
    if (gap < 0) {
      search(lo, mid, next, x, best);
      if (gap * gap <= best->d2) search(mid + 1, hi, next, x, best);
    } else {
      search(mid + 1, hi, next, x, best);
      if (gap * gap <= best->d2) search(lo, mid, next, x, best);
    }
  }

  std::vector<Vec3> points_;
  std::vector<std::size_t> order_;
};

}  // namespace ssimarch::internal
