// Per-particle integrals: issue 5 check (b) (integrating the arc length over r and z returns the
// volume) in both formulations, plus the chord/shadow geometry against brute force.
#include "ssimarch/porosity/particle_integrals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "ssimarch/porosity/piecewise_quadrature.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

Particle make(Vec3 c, Vec3 u, double d, double l) { return make_spherocylinder(c, u, d, l); }

// Orientations named by issue 5 (a)/(b): vertical, horizontal, oblique, nearly vertical, sphere.
std::vector<Particle> catalogue() {
  std::vector<Particle> v;
  v.push_back(make({1.2, -0.4, 0.3}, {0, 0, 1}, 0.6, 1.4));          // axis vertical, off axis
  v.push_back(make({0, 0, 0.5}, {0, 0, 1}, 0.8, 1.0));               // vertical, on the z axis
  v.push_back(make({0.9, 0.7, -0.2}, {1, 0, 0}, 0.5, 2.0));          // horizontal
  v.push_back(make({-1.1, 0.3, 0.1}, {0.3, -0.7, 0.6}, 0.7, 1.3));   // oblique
  v.push_back(make({0.2, -0.1, 0.0}, {0.6, 0.8, 0.05}, 0.4, 2.5));   // nearly horizontal, crosses the axis
  v.push_back(make({1.5, 1.0, 0.0}, {1e-4, 0, 1}, 0.5, 1.0));        // nearly vertical
  v.push_back(make({-0.8, -1.3, 0.4}, {0, 0, 1}, 0.9, 0.0));         // sphere
  v.push_back(make({0.0, 0.0, 0.0}, {0.2, 0.1, 1.0}, 1.0, 0.0));     // sphere on the axis
  return v;
}

TEST(porosity_ParticleIntegrals, VolumeFromChordFormulation) {
  for (const Particle& p : catalogue()) {
    const ParticleShape s(p);
    const auto v = shell_volume(s, 0, 1e3, BedSlab{-1e3, 1e3}, 1e-11 * p.volume());
    EXPECT_NEAR(v.value, p.volume(), 1e-9 * p.volume()) << p.centre.transpose() << " | " << p.axis.transpose();
  }
}

TEST(porosity_ParticleIntegrals, VolumeFromSeedKernelOverRAndZ) {
  // Integral over z of the slice area S(z) = integral of p_i(z, r) dr: the seed kernel integrated
  // directly in both variables, breakpoints in z at the particle's extremes and junction heights.
  for (const Particle& p : catalogue()) {
    const ParticleShape s(p);
    std::vector<double> br{s.z_min(), s.z_max()};
    const double h = p.half_length(), a = p.radius();
    const double uz = std::abs(p.axis.z()), sxy = std::sqrt(std::max(0.0, 1 - uz * uz));
    for (double sg : {-1.0, 1.0})
      for (double t : {-1.0, 1.0}) {
        const double z = p.centre.z() + sg * h * p.axis.z() + t * a * sxy;  // junction circle z-extremes
        if (z > s.z_min() && z < s.z_max()) br.push_back(z);
      }
    std::sort(br.begin(), br.end());
    QuadResult total;
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
      total += integrate_sqrt_ends(
          [&](double z) { return slice_area(s, z, 1e3, 1e-13, {}, ProfileMethod::kKernel).value; }, br[k], br[k + 1],
          1e-11 * p.volume());
    EXPECT_NEAR(total.value, p.volume(), 1e-9 * p.volume()) << p.centre.transpose();
    const auto vk = shell_volume(s, 0, 1e3, BedSlab{-1e3, 1e3}, 1e-11 * p.volume(), ProfileMethod::kKernel);
    EXPECT_NEAR(vk.value, p.volume(), 1e-9 * p.volume()) << "kernel over z then r: " << p.centre.transpose();
  }
}

TEST(porosity_ParticleIntegrals, ClosedFormSliceAreaMatchesKernelAndVolume) {
  for (const Particle& p : catalogue()) {
    const ParticleShape s(p);
    std::vector<double> br{s.z_min(), s.z_max()};
    const double h = p.half_length(), a = p.radius();
    const double uz = std::abs(p.axis.z()), sxy = std::sqrt(std::max(0.0, 1 - uz * uz));
    for (double sg : {-1.0, 1.0})
      for (double t : {-1.0, 1.0}) {
        const double z = p.centre.z() + sg * h * p.axis.z() + t * a * sxy;
        if (z > s.z_min() && z < s.z_max()) br.push_back(z);
      }
    std::sort(br.begin(), br.end());
    QuadResult v;
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
      v += integrate_sqrt_ends([&](double z) { return slice_area_unclipped(p, z); }, br[k], br[k + 1], 1e-14);
    EXPECT_NEAR(v.value, p.volume(), 1e-12 * p.volume());
    for (int k = 1; k < 10; ++k) {
      const double z = s.z_min() + (s.z_max() - s.z_min()) * k / 10;
      EXPECT_NEAR(slice_area_unclipped(p, z), slice_area(s, z, 1e3, 1e-12, {}, ProfileMethod::kKernel).value, 1e-7) << z;
    }
  }
}

TEST(porosity_ParticleIntegrals, ChordAndKernelLateralAreasAgree) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(0, 1);
  for (const Particle& p : catalogue()) {
    const ParticleShape s(p);
    for (int k = 0; k < 25; ++k) {
      const double r = s.rho_min() + (s.rho_max() - s.rho_min()) * U(rng);
      if (!(r > 0)) continue;
      const BedSlab slab{-1e3, 1e3};
      const auto c = lateral_area(s, r, slab, 1e-13, ProfileMethod::kChord);
      const auto q = lateral_area(s, r, slab, 1e-13, ProfileMethod::kKernel);
      EXPECT_NEAR(c.value, q.value, 1e-10 * std::max(1.0, c.value)) << "r=" << r << " " << p.axis.transpose();
    }
  }
}

TEST(porosity_ParticleIntegrals, VerticalChordMatchesBisection) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  for (const Particle& p : catalogue()) {
    const ParticleShape s(p);
    for (int k = 0; k < 200; ++k) {
      const double x = p.centre.x() + 2 * U(rng), y = p.centre.y() + 2 * U(rng);
      const Chord c = s.vertical_chord(x, y);
      // The line meets the particle exactly when (x, y) is in its shadow.
      EXPECT_EQ(!c.empty(), s.shadow_contains(x, y)) << x << " " << y;
      if (c.empty() || c.length() < 1e-9) continue;
      // Both ends lie on the surface and the midpoint inside.
      EXPECT_NEAR(inside_margin(p, Vec3(x, y, c.lo)), 0.0, 1e-12);
      EXPECT_NEAR(inside_margin(p, Vec3(x, y, c.hi)), 0.0, 1e-12);
      EXPECT_GT(inside_margin(p, Vec3(x, y, (c.lo + c.hi) / 2)), -1e-12);
    }
  }
}

TEST(porosity_ParticleIntegrals, SlabClippedSphereMatchesCapFormula) {
  const Particle p = make({2.0, 1.0, 0.3}, {0, 0, 1}, 1.0, 0.0);
  const ParticleShape s(p);
  const BedSlab slab{0.1, 0.6};
  // Ball between planes: pi [a^2 t - t^3/3] evaluated from t0 = -0.2 to t1 = 0.3.
  auto F = [](double t) { return kPi * (0.25 * t - t * t * t / 3); };
  const double exact = F(0.3) - F(-0.2);
  EXPECT_NEAR(shell_volume(s, 0, 10, slab, 1e-13).value, exact, 1e-11);
  EXPECT_NEAR(shell_volume(s, 0, 10, slab, 1e-12, ProfileMethod::kKernel).value, exact, 1e-10);
}

TEST(porosity_Quadrature, GaussKronrodIsExactForDegree22) {
  // QK15 integrates polynomials up to degree 22 exactly; the Gauss part (degree 13) is the estimate.
  for (int deg : {0, 5, 13, 22}) {
    const auto q = integrate([deg](double x) { return std::pow(x, deg); }, -1.0, 2.0, 1e-300, 0);
    EXPECT_NEAR(q.value, (std::pow(2.0, deg + 1) - std::pow(-1.0, deg + 1)) / (deg + 1), 1e-12 * std::pow(2.0, deg));
  }
}

TEST(porosity_Quadrature, SqrtEndpointsConvergeFast) {
  // Integral of sqrt(1 - x^2) over [-1, 1] = pi/2 (square-root behaviour at both ends).
  const auto q = integrate_sqrt_ends([](double x) { return std::sqrt(std::max(0.0, 1 - x * x)); }, -1.0, 1.0, 1e-14);
  EXPECT_NEAR(q.value, kPi / 2, 1e-14);
  EXPECT_EQ(q.status, QuadStatus::kConverged);
  EXPECT_LE(q.evaluations, 100);
}

TEST(porosity_Quadrature, PiecewiseFindsHiddenBreakpoints) {
  // |x - 0.3137| has its kink between coarse samples; the signature sign(x - 0.3137) exposes it.
  const double x0 = 0.3137;
  const auto q = integrate_piecewise([&](double x) { return std::sqrt(std::abs(x - x0)); },
                                     [&](double x) { return static_cast<long>(x > x0); }, 0.0, 1.0, 1e-13);
  const double exact = 2.0 / 3 * (std::pow(x0, 1.5) + std::pow(1 - x0, 1.5));
  EXPECT_NEAR(q.value, exact, 1e-12);
}

}  // namespace
}  // namespace ssimarch
