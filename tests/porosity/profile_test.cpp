// Whole-packing checks of issue 5: (c) (1 - bulk porosity) * container volume = particle volume
// inside the container, consistency between the radial, bin, axial and map profiles, thread-count
// independence, and (d) agreement with a Monte Carlo estimate within its statistical error.
#include "ssimarch/porosity/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ssimarch/core/error.hpp"
#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/monte_carlo.hpp"
#include "ssimarch/porosity/quadrature.hpp"
#include "testing/packed_beds.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Particle> sphere_bed() { return testing::drop_and_roll_bed(3.0, 300, 42).particles; }

std::vector<Particle> rod_bed() { return testing::rsa_bed(3.0, 0.6, 1.2, 150, 0.2, 7).particles; }

// Composite 15-point Kronrod rule on [a, b] with n panels: nodes and weights, so that a whole profile
// can be integrated from one call at all nodes.
void composite_rule(double a, double b, int n, std::vector<double>& x, std::vector<double>& w) {
  for (int k = 0; k < n; ++k) {
    const double lo = a + (b - a) * k / n, hi = a + (b - a) * (k + 1) / n, c = (lo + hi) / 2, hw = (hi - lo) / 2;
    for (int j = 0; j < 15; ++j) {
      const int m = j < 8 ? j : 14 - j;
      const double sgn = j < 7 ? -1.0 : 1.0;
      x.push_back(c + sgn * hw * internal::kXgk[m]);
      w.push_back(hw * internal::kWgk[m]);
    }
  }
}

double total_volume(const std::vector<Particle>& ps) {
  double v = 0;
  for (const auto& p : ps) v += p.volume();
  return v;
}

TEST(porosity_Profile, BulkPorosityAccountsForEveryParticleInside) {
  // Container enclosing every particle: the solid volume is the sum of the closed-form volumes.
  for (const auto& ps : {sphere_bed(), rod_bed()}) {
    double zmax = 0;
    for (const auto& p : ps) zmax = std::max(zmax, p.centre.z() + p.radius() + p.half_length());
    Container c{3.0, {0.0, zmax + 0.1}};
    const BulkPorosity b = bulk_porosity(ps, c);
    EXPECT_NEAR((1 - b.porosity) * c.volume(), total_volume(ps), 1e-9 * total_volume(ps));
    EXPECT_EQ(b.stats.particles_clipped, 0);
  }
}

TEST(porosity_Profile, BulkEqualsIntegralOfRadialProfileWhenClipped) {
  // Height range cutting through the bed and a container radius cutting the outer particles: the bulk
  // (bins formulation) must equal the integral of the radial profile (Gauss-Kronrod over r).
  for (const auto& ps : {sphere_bed(), rod_bed()}) {
    Container c{2.6, {1.3, 4.1}};
    const BulkPorosity b = bulk_porosity(ps, c);
    EXPECT_GT(b.stats.particles_clipped, 0);
    std::vector<double> x, w;
    composite_rule(0.0, 2.6, 120, x, w);
    const PorosityProfile p = radial_profile(ps, c, x);
    QuadResult q;
    for (std::size_t j = 0; j < x.size(); ++j) q.value += w[j] * (1 - p.porosity[j]) * 2 * kPi * x[j] * c.height();
    EXPECT_NEAR(q.value, b.solid_volume, 2e-6 * b.solid_volume);
  }
}

TEST(porosity_Profile, BinsAverageTheRadialProfile) {
  const auto ps = sphere_bed();
  Container c{3.0, {1.0, 4.0}};
  const auto edges = even_edges(3.0, 6);
  const PorosityProfile bins = bin_profile(ps, c, edges);
  double vol = 0;
  for (std::size_t k = 0; k < bins.porosity.size(); ++k)
    vol += (1 - bins.porosity[k]) * kPi * (edges[k + 1] * edges[k + 1] - edges[k] * edges[k]) * c.height();
  EXPECT_NEAR(vol, bulk_porosity(ps, c).solid_volume, 1e-9 * vol);
  // Bin 3 against the radial profile integrated over its annulus.
  std::vector<double> x, w;
  composite_rule(edges[3], edges[4], 40, x, w);
  const PorosityProfile p = radial_profile(ps, c, x);
  double v3 = 0;
  for (std::size_t j = 0; j < x.size(); ++j) v3 += w[j] * (1 - p.porosity[j]) * 2 * kPi * x[j] * c.height();
  EXPECT_NEAR(1 - v3 / (kPi * (edges[4] * edges[4] - edges[3] * edges[3]) * c.height()), bins.porosity[3], 2e-6);
}

TEST(porosity_Profile, AxialProfileIntegratesToBulk) {
  for (const auto& ps : {sphere_bed(), rod_bed()}) {
    Container c{3.0, {1.0, 3.0}};
    std::vector<double> x, w;
    composite_rule(1.0, 3.0, 100, x, w);
    const PorosityProfile p = axial_profile(ps, c, x);
    QuadResult q;
    for (std::size_t j = 0; j < x.size(); ++j) q.value += w[j] * (1 - p.porosity[j]) * kPi * 9.0;
    EXPECT_NEAR(q.value, bulk_porosity(ps, c).solid_volume, 2e-6 * q.value);
  }
}

TEST(porosity_Profile, MapAveragedOverHeightApproachesRadialProfile) {
  const auto ps = rod_bed();
  Container c{3.0, {1.0, 3.0}};
  const std::vector<double> rr{0.7, 1.9};
  const auto zs = slice_centres(1.0, 3.0, 400);
  const PorosityMap m = porosity_map(ps, c, rr, zs);
  const PorosityProfile p = radial_profile(ps, c, rr);
  for (std::size_t ir = 0; ir < rr.size(); ++ir) {
    double mean = 0;
    for (std::size_t iz = 0; iz < zs.size(); ++iz) mean += m.porosity[iz * rr.size() + ir];
    mean /= static_cast<double>(zs.size());
    EXPECT_NEAR(mean, p.porosity[ir], 2e-3);  // midpoint rule in z with square-root kinks
  }
}

TEST(porosity_Profile, ChordAndKernelMethodsAgree) {
  const auto ps = rod_bed();
  Container c{3.0, {1.0, 3.0}};
  const std::vector<double> rr{0.35, 1.1, 2.2, 2.9};
  ProfileOptions k;
  k.method = ProfileMethod::kKernel;
  const PorosityProfile a = radial_profile(ps, c, rr), b = radial_profile(ps, c, rr, k);
  for (std::size_t j = 0; j < rr.size(); ++j) EXPECT_NEAR(a.porosity[j], b.porosity[j], 2e-8) << rr[j];
}

TEST(porosity_Profile, ResultDoesNotDependOnThreadCount) {
  const auto ps = sphere_bed();
  Container c{3.0, {1.0, 4.0}};
  const auto rr = even_radii(3.0, 30);
  ProfileOptions one, four;
  one.threads = 1;
  four.threads = 4;
  const PorosityProfile a = radial_profile(ps, c, rr, one), b = radial_profile(ps, c, rr, four);
  for (std::size_t j = 0; j < rr.size(); ++j) EXPECT_EQ(a.porosity[j], b.porosity[j]);
}

TEST(porosity_Profile, MonteCarloAgreesWithinStatisticalError) {
  for (const auto& ps : {sphere_bed(), rod_bed()}) {
    Container c{3.0, {1.0, 4.0}};
    const auto rr = even_radii(3.0, 12);
    const PorosityProfile exact = radial_profile(ps, c, rr);
    MonteCarloOptions mo;
    mo.samples_per_radius = 40000;
    mo.seed = 12345;
    const MonteCarloProfile mc = monte_carlo_radial(ps, c, rr, mo);
    int outside_2sigma = 0;
    for (std::size_t j = 0; j < rr.size(); ++j) {
      // 4.5 sigma: the chance that any of the 12 values lies further out by chance is below 1e-4.
      EXPECT_NEAR(mc.porosity[j], exact.porosity[j], 4.5 * mc.std_error[j]) << "r=" << rr[j];
      outside_2sigma += std::abs(mc.porosity[j] - exact.porosity[j]) > 2 * mc.std_error[j];
    }
    EXPECT_LE(outside_2sigma, 4);
  }
}

TEST(porosity_Profile, WallPorosityIsOneForSpheresTouchingTheWall) {
  // Spheres touch the wall in single points: the lateral surface r = R holds no solid.
  const auto ps = sphere_bed();
  Container c{3.0, {1.0, 4.0}};
  const std::vector<double> rr{3.0};
  EXPECT_NEAR(radial_profile(ps, c, rr).porosity[0], 1.0, 1e-8);
}

TEST(porosity_Profile, InvalidArgumentsAreRejected) {
  const auto ps = sphere_bed();
  const std::vector<double> bad_r{0.0, 1.0};
  EXPECT_THROW(radial_profile(ps, Container{3.0, {0, 1}}, bad_r), InputError);
  EXPECT_THROW(radial_profile(ps, Container{-1.0, {0, 1}}, even_radii(1, 3)), InputError);
  EXPECT_THROW(radial_profile(ps, Container{3.0, {1, 1}}, even_radii(1, 3)), InputError);
  const std::vector<double> unsorted{2.0, 1.0};
  EXPECT_THROW(bin_profile(ps, Container{3.0, {0, 1}}, unsorted), InputError);
  try {
    radial_profile(ps, Container{-1.0, {0, 1}}, even_radii(1, 3));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "container.radius");
  }
  try {
    bin_profile(ps, Container{3.0, {0, 1}}, unsorted);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "bin edges");
    EXPECT_NE(std::string(e.what()).find("strictly increasing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ssimarch
