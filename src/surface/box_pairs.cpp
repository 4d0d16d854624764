#include "ssimarch/surface/box_pairs.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace ssimarch {

namespace {

const Interval& along(const Box& b, int axis) { return axis == 0 ? b.x : (axis == 1 ? b.y : b.z); }

bool meet(const Interval& p, const Interval& q, double slack) { return p.lo <= q.hi + slack && q.lo <= p.hi + slack; }

// The axis on which the boxes' centres spread most: the fewest intervals overlap there.
int sweep_axis(const std::vector<Box>& a, const std::vector<Box>& b) {
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const std::vector<Box>* set : {&a, &b})
    for (const Box& box : *set)
      for (int k = 0; k < 3; ++k) {
        const double c = 0.5 * (along(box, k).lo + along(box, k).hi);
        lo[static_cast<std::size_t>(k)] = std::min(lo[static_cast<std::size_t>(k)], c);
        hi[static_cast<std::size_t>(k)] = std::max(hi[static_cast<std::size_t>(k)], c);
      }
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[static_cast<std::size_t>(k)] - lo[static_cast<std::size_t>(k)] >
        hi[static_cast<std::size_t>(best)] - lo[static_cast<std::size_t>(best)])
      best = k;
  return best;
}

}  // namespace

std::vector<std::pair<int, int>> overlapping_boxes(const std::vector<Box>& a, const std::vector<Box>& b, double slack,
                                                   bool same_set) {
  const int axis = sweep_axis(a, b);
  // Every box once (b's only when it is another set), by where it starts on the axis.
  struct Entry {
    double start;
    int set, index;
  };
  std::vector<Entry> order;
  for (int i = 0; i < static_cast<int>(a.size()); ++i)
    order.push_back({along(a[static_cast<std::size_t>(i)], axis).lo, 0, i});
  if (!same_set)
    for (int j = 0; j < static_cast<int>(b.size()); ++j)
      order.push_back({along(b[static_cast<std::size_t>(j)], axis).lo, 1, j});
  std::sort(order.begin(), order.end(), [](const Entry& p, const Entry& q) {
    return p.start != q.start ? p.start < q.start : (p.set != q.set ? p.set < q.set : p.index < q.index);
  });
  auto box = [&](const Entry& e) -> const Box& {
    return e.set == 0 ? a[static_cast<std::size_t>(e.index)] : b[static_cast<std::size_t>(e.index)];
  };
  std::vector<std::pair<int, int>> out;
  std::vector<Entry> open;  // boxes whose interval on the axis may still meet a later start
  for (const Entry& e : order) {
    const Box& be = box(e);
    std::erase_if(open, [&](const Entry& o) { return along(box(o), axis).hi + slack < along(be, axis).lo; });
    for (const Entry& o : open) {
      if (!same_set && o.set == e.set) continue;
      const Box& bo = box(o);
      if (!(meet(bo.x, be.x, slack) && meet(bo.y, be.y, slack) && meet(bo.z, be.z, slack))) continue;
      if (same_set)
        out.emplace_back(std::min(o.index, e.index), std::max(o.index, e.index));
      else
        out.emplace_back(e.set == 0 ? e.index : o.index, e.set == 0 ? o.index : e.index);
    }
    open.push_back(e);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ssimarch
