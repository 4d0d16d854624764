// The k-d tree of the sampling start-point search returns what a scan returns: the nearest point,
// the lowest index among equally near ones, and never a point at infinity when a finite one exists.
#include "ssimarch/start/nearest_point_tree.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace ssimarch {
namespace {

std::size_t scan(const std::vector<Vec3>& pts, const Vec3& x) {
  std::size_t best = 0;
  double bd = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const double d = (pts[k] - x).squaredNorm();
    if (d < bd) bd = d, best = k;
  }
  return best;
}

TEST(NearestPointTree, AgreesWithAScan) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Vec3> pts;
  for (int i = 0; i < 3000; ++i) pts.emplace_back(U(rng), U(rng), 0.1 * U(rng));
  // Repeated points (a pole of a parametric sphere samples one point many times).
  for (int i = 0; i < 50; ++i) pts.emplace_back(0.5, 0.5, 0.0);
  const internal::NearestPointTree tree(pts);
  for (int q = 0; q < 2000; ++q) {
    const Vec3 x = q % 10 == 0 ? Vec3(0.5, 0.5, 0.0) : Vec3(2 * U(rng), 2 * U(rng), U(rng));
    ASSERT_EQ(tree.nearest(x), scan(pts, x)) << "query " << q;
  }
}

TEST(NearestPointTree, PointsThatAreNotFiniteAreNeverNearest) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec3> pts = {Vec3(nan, 0, 0), Vec3(5, 5, 5), Vec3(0, nan, 1), Vec3(1, 1, 1)};
  const internal::NearestPointTree tree(pts);
  EXPECT_EQ(tree.nearest(Vec3(0, 0, 0)), 3u);
  EXPECT_EQ(tree.nearest(Vec3(4, 4, 4)), 1u);
  const internal::NearestPointTree none({Vec3(nan, nan, nan)});
  EXPECT_EQ(none.nearest(Vec3(0, 0, 0)), 0u);
}

}  // namespace
}  // namespace ssimarch
