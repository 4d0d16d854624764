// Overlapping particles (porosity/overlaps.hpp): the hierarchical grid finds exactly the pairs a
// scan of all pairs finds, and the lens volume agrees with its limits and with a Monte Carlo count.
#include "ssimarch/porosity/overlaps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

#include "ssimarch/porosity/generator.hpp"
#include "thread_group.hpp"

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

// Spheres and spherocylinders of sizes over two orders of magnitude in a column 10 x 10 x 30,
// dense enough to overlap: every grid level and many slab boundaries meet overlapping pairs.
std::vector<Particle> overlapping_column(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<Particle> ps;
  for (int i = 0; i < n; ++i) {
    Particle p = sphere(10 * U(rng), 10 * U(rng), 30 * U(rng), std::pow(10.0, -1.5 + 1.8 * U(rng)));
    if (i % 4 == 0) {
      p.length = U(rng);
      p.axis = Vec3(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
    }
    ps.push_back(p);
  }
  // Two coincident copies of spheres larger than all others: two deepest pairs of equal depth 3,
  // (17, n - 2) and (5, n - 1); the tie goes to the smaller first index.
  for (int k : {17, 5}) {
    ps[static_cast<std::size_t>(k)].length = 0;
    ps[static_cast<std::size_t>(k)].diameter = 3;
    ps.push_back(ps[static_cast<std::size_t>(k)]);
  }
  return ps;
}

// find_overlaps of the packing split into n equal blocks, one per in-process rank.
std::vector<ParticleOverlaps> split_search(const std::vector<Particle>& ps, int n) {
  std::vector<ParticleOverlaps> out(static_cast<std::size_t>(n));
  testing::run_on_ranks(n, [&](const testing::ThreadGroup::Member& me, int k) {
    const std::size_t b = ps.size() * static_cast<std::size_t>(k) / static_cast<std::size_t>(n);
    const std::size_t e = ps.size() * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(n);
    const std::span<const Particle> share(ps.data() + b, e - b);
    out[static_cast<std::size_t>(k)] = find_overlaps(share, static_cast<long>(b), me, 1e-9, 2);
  });
  return out;
}

void expect_identical(const ParticleOverlaps& a, const ParticleOverlaps& b, const std::string& what) {
  EXPECT_EQ(a.pairs, b.pairs) << what;
  EXPECT_EQ(a.max_depth, b.max_depth) << what;
  EXPECT_EQ(a.worst_first, b.worst_first) << what;
  EXPECT_EQ(a.worst_second, b.worst_second) << what;
  EXPECT_EQ(a.doubled_volume, b.doubled_volume) << what;  // exact sums: the same bits
}

TEST(porosity_Overlaps, ThreadsAndRanksFindTheScansPairsWithTheSameBits) {
  const std::vector<Particle> ps = overlapping_column(3000, 11);
  // The reference: every pair, in index order, with the volume summed in long double.
  long pairs = 0;
  double worst = 0;
  long wi = -1, wj = -1;
  long double volume = 0;
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      const double d = segment_distance(ps[i].minus_cap(), ps[i].plus_cap(), ps[j].minus_cap(), ps[j].plus_cap());
      const double depth = ps[i].radius() + ps[j].radius() - d;
      if (!(depth > 1e-9 * std::min(ps[i].diameter, ps[j].diameter))) continue;
      ++pairs;
      volume += sphere_lens_volume(ps[i].radius(), ps[j].radius(), d);
      if (depth > worst) worst = depth, wi = static_cast<long>(i), wj = static_cast<long>(j);
    }
  ASSERT_GT(pairs, 200);
  ASSERT_EQ(worst, 3.0);
  ASSERT_EQ(wi, 5);
  const ParticleOverlaps one = find_overlaps(ps, 1e-9, 1);
  EXPECT_EQ(one.pairs, pairs);
  EXPECT_NEAR(one.max_depth, worst, 1e-15 * worst);
  EXPECT_EQ(one.worst_first, wi);
  EXPECT_EQ(one.worst_second, wj);
  EXPECT_NEAR(one.doubled_volume, static_cast<double>(volume), 1e-13 * static_cast<double>(volume));
  for (unsigned threads : {2u, 3u, 8u}) expect_identical(find_overlaps(ps, 1e-9, threads), one, "threads");
  for (int ranks : {1, 2, 3, 5})
    for (const ParticleOverlaps& r : split_search(ps, ranks)) expect_identical(r, one, std::to_string(ranks) + " ranks");
}

TEST(porosity_Overlaps, RanksWithoutParticlesAndAllCentresAtOneHeight) {
  // Three particles on four ranks (one rank has none), all centres at z = 1 (one histogram bin).
  const std::vector<Particle> ps = {sphere(0, 0, 1, 1), sphere(0.5, 0, 1, 1), sphere(3, 0, 1, 1)};
  const ParticleOverlaps one = find_overlaps(ps);
  ASSERT_EQ(one.pairs, 1);
  EXPECT_EQ(one.worst_first, 0);
  EXPECT_EQ(one.worst_second, 1);
  EXPECT_DOUBLE_EQ(one.max_depth, 0.5);
  for (const ParticleOverlaps& r : split_search(ps, 4)) expect_identical(r, one, "4 ranks");
}

}  // namespace
}  // namespace ssimarch
