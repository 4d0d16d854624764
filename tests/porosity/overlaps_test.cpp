// Overlapping particles (porosity/overlaps.hpp): the hierarchical grid finds exactly the pairs a
// scan of all pairs finds, and the lens volume agrees with its limits and with a Monte Carlo count.
#include "ssimarch/porosity/overlaps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ssimarch/porosity/generator.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

Particle sphere(double x, double y, double z, double d) {
  Particle p;
  p.centre = Vec3(x, y, z);
  p.diameter = d;
  return p;
}

TEST(porosity_Overlaps, LensVolumeLimitsAndMonteCarlo) {
  EXPECT_DOUBLE_EQ(sphere_lens_volume(1, 1, 2), 0.0);               // touching
  EXPECT_DOUBLE_EQ(sphere_lens_volume(1, 0.5, 0.2), kPi / 6);        // the small ball inside the big one
  // Equal balls at distance r: the lens is 5 pi r^3 / 12 (two caps of height r/2).
  EXPECT_NEAR(sphere_lens_volume(1, 1, 1), 5 * kPi / 12, 1e-14);
  // Unequal balls against a Monte Carlo count of points in both (4e6 samples: about 0.1 %).
  const double a = 1.0, b = 0.6, D = 1.2;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  long inside = 0;
  const long n = 4'000'000;
  for (long k = 0; k < n; ++k) {
    const Vec3 p(b * U(rng) + D, b * U(rng), b * U(rng));  // the box around the small ball
    inside += (p - Vec3(D, 0, 0)).squaredNorm() <= b * b && p.squaredNorm() <= a * a;
  }
  const double box = 8 * b * b * b;
  EXPECT_NEAR(sphere_lens_volume(a, b, D), box * inside / n, 3e-3 * box);
}

TEST(porosity_Overlaps, TheGridFindsTheSamePairsAsAScan) {
  // Sizes over three orders of magnitude, so that several grid levels meet.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Particle> ps;
  for (int i = 0; i < 600; ++i) {
    Particle p = sphere(10 * U(rng), 10 * U(rng), 10 * U(rng), std::pow(10.0, -2 + 2.5 * U(rng)));
    if (i % 3 == 0) {
      p.length = 2 * U(rng);
      p.axis = Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
    }
    ps.push_back(p);
  }
  long pairs = 0;
  double worst = 0;
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      const double d = segment_distance(ps[i].minus_cap(), ps[i].plus_cap(), ps[j].minus_cap(), ps[j].plus_cap());
      const double depth = ps[i].radius() + ps[j].radius() - d;
      if (depth > 1e-9 * std::min(ps[i].diameter, ps[j].diameter)) ++pairs, worst = std::max(worst, depth);
    }
  ASSERT_GT(pairs, 10);  // the set must have overlaps for the comparison to mean something
  const ParticleOverlaps o = find_overlaps(ps);
  EXPECT_EQ(o.pairs, pairs);
  EXPECT_DOUBLE_EQ(o.max_depth, worst);
}

TEST(porosity_Overlaps, ThreeCoincidentSpheresAndAContact) {
  const std::vector<Particle> three = {sphere(0, 0, 0, 1), sphere(0, 0, 0, 1), sphere(0, 0, 0, 1)};
  const ParticleOverlaps o = find_overlaps(three);
  EXPECT_EQ(o.pairs, 3);
  EXPECT_DOUBLE_EQ(o.max_depth, 1.0);
  EXPECT_NEAR(o.doubled_volume, 3 * kPi / 6, 1e-14);
  const std::vector<Particle> touching = {sphere(0, 0, 0, 1), sphere(1, 0, 0, 1)};
  EXPECT_EQ(find_overlaps(touching).pairs, 0);
}

}  // namespace
}  // namespace ssimarch
