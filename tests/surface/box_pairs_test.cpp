// Sweep and prune (surface/box_pairs.hpp) against trying every pair: random boxes of mixed sizes,
// two sets and one set, with and without slack; touching boxes meet.
#include "ssimarch/surface/box_pairs.hpp"

#include <gtest/gtest.h>

#include <random>

namespace ssimarch {
namespace {

std::vector<Box> random_boxes(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> at(-10, 10), size(0, 3);
  std::vector<Box> out;
  for (int i = 0; i < n; ++i) {
    Box b;
    for (Interval* k : {&b.x, &b.y, &b.z}) {
      const double lo = at(rng);
      *k = Interval{lo, lo + size(rng) * (i % 5 == 0 ? 0.0 : 1.0)};  // every fifth box flat
    }
    out.push_back(b);
  }
  return out;
}

bool meet(const Box& p, const Box& q, double s) {
  auto m = [s](const Interval& a, const Interval& b) { return a.lo <= b.hi + s && b.lo <= a.hi + s; };
  return m(p.x, q.x) && m(p.y, q.y) && m(p.z, q.z);
}

TEST(OverlappingBoxes, EqualsEveryPairTried) {
  std::mt19937 rng(11);
  for (double slack : {0.0, 0.25}) {
    const std::vector<Box> a = random_boxes(rng, 300), b = random_boxes(rng, 200);
    std::vector<std::pair<int, int>> two, one;
    for (int i = 0; i < 300; ++i)
      for (int j = 0; j < 200; ++j)
        if (meet(a[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(j)], slack)) two.emplace_back(i, j);
    for (int i = 0; i < 300; ++i)
      for (int j = i + 1; j < 300; ++j)
        if (meet(a[static_cast<std::size_t>(i)], a[static_cast<std::size_t>(j)], slack)) one.emplace_back(i, j);
    EXPECT_EQ(overlapping_boxes(a, b, slack), two) << slack;
    EXPECT_EQ(overlapping_boxes(a, a, slack, true), one) << slack;
    EXPECT_FALSE(two.empty());
  }
}

TEST(OverlappingBoxes, TouchingBoxesMeetAndApartOnesDoNot) {
  const Box unit{{0, 1}, {0, 1}, {0, 1}}, beside{{1, 2}, {0, 1}, {0, 1}}, above{{0, 1}, {0, 1}, {1.5, 2}};
  EXPECT_EQ(overlapping_boxes({unit}, {beside, above}, 0), (std::vector<std::pair<int, int>>{{0, 0}}));
  EXPECT_EQ(overlapping_boxes({unit}, {beside, above}, 0.5), (std::vector<std::pair<int, int>>{{0, 0}, {0, 1}}));
  EXPECT_TRUE(overlapping_boxes({}, {unit}, 0).empty());
}

}  // namespace
}  // namespace ssimarch
