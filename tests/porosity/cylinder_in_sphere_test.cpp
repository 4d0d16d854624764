// The closed form of the cylinder area inside a sphere (docs/math/cylinder_in_sphere.md) against
// adaptive quadrature of the chord over the angle (the formulation it replaced), the seed kernel
// integrated over z, limits with elementary values, and a Monte Carlo estimate; the exact,
// order-independent sums (FixedPointSum) and the split of a profile over several processes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

#include "ssimarch/porosity/fixed_point_sum.hpp"
#include "ssimarch/porosity/particle_integrals.hpp"
#include "ssimarch/porosity/profile.hpp"
#include "ssimarch/porosity/quadrature.hpp"
#include "ssimarch/porosity/sphere_arc.hpp"
#include "testing/packed_beds.hpp"
#include "thread_group.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

// L(r) by adaptive Gauss-Kronrod over the angle: r * integral of 2 sqrt(A + B cos t) over |t| < t0.
double quadrature_area(double rho, double a, double r) {
  const double A = a * a - r * r - rho * rho, B = 2 * r * rho;
  if (A + B <= 0) return 0;
  const double t0 = A - B >= 0 ? kPi : std::acos(-A / B);
  auto chord = [&](double t) { return 2 * std::sqrt(std::max(0.0, A + B * std::cos(t))); };
  return r * integrate_sqrt_ends(chord, -t0, t0, 1e-15).value;
}

TEST(porosity_CylinderInSphere, MatchesAdaptiveQuadratureOverTheAngle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int k = 0; k < 4000; ++k) {
    const double a = 0.05 + U(rng), rho = 3 * U(rng) * (k % 7 == 0 ? 1e-6 : 1);
    const double r = std::max(1e-9, rho - a + 2 * a * U(rng));  // anywhere across the shadow
    const double cf = cylinder_area_in_sphere(rho, a, r), q = quadrature_area(rho, a, r);
    const double scale = 4 * kPi * r * a;  // the largest value for this r and a
    worst = std::max(worst, std::abs(cf - q) / scale);
    ASSERT_NEAR(cf, q, 1e-12 * scale) << "rho=" << rho << " a=" << a << " r=" << r;
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
}

// The same area between the planes at `below` under and `above` over the centre, by adaptive
// quadrature of the clipped chord, split where the half-chord h(t) crosses a plane (acos).
double quadrature_area_slab(double rho, double a, double r, double below, double above) {
  const double A = a * a - r * r - rho * rho, B = 2 * r * rho;
  if (A + B <= 0) return 0;
  const double t0 = A - B >= 0 ? kPi : std::acos(-A / B);
  auto len = [&](double t) {
    const double h = std::sqrt(std::max(0.0, A + B * std::cos(t)));
    return std::max(0.0, std::min(h, above) + std::min(h, below));
  };
  std::vector<double> cuts{0.0, t0};
  for (double v : {above, below, -above, -below})
    if (v > 0 && (v * v - A) / B > -1 && (v * v - A) / B < 1 && std::acos((v * v - A) / B) < t0)
      cuts.push_back(std::acos((v * v - A) / B));
  std::sort(cuts.begin(), cuts.end());
  double total = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) total += integrate_sqrt_ends(len, cuts[k], cuts[k + 1], 1e-16).value;
  return 2 * r * total;
}

TEST(porosity_CylinderInSphere, CutByTheHeightRangeMatchesAdaptiveQuadrature) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int k = 0; k < 4000; ++k) {
    const double a = 0.05 + U(rng), rho = 3 * U(rng) * (k % 7 == 0 ? 1e-3 : 1);
    const double r = std::max(1e-9, rho - a + 2 * a * U(rng));
    // One plane, both, the centre outside the slab, a slab inside the ball, a plane at the centre.
    double below = a * (2.4 * U(rng) - 1.2), above = a * (2.4 * U(rng) - 1.2);
    if (k % 5 == 0) below = 10 * a;
    if (k % 11 == 0) above = 0;
    if (below + above <= 0) above = -below + a * (1e-3 + 0.3 * U(rng));  // the slab's height is > 0
    const double cf = cylinder_area_in_sphere_slab(rho, a, r, below, above);
    const double q = quadrature_area_slab(rho, a, r, below, above);
    const double scale = 4 * kPi * r * a;
    worst = std::max(worst, std::abs(cf - q) / scale);
    ASSERT_NEAR(cf, q, 1e-12 * scale) << "rho=" << rho << " a=" << a << " r=" << r << " below=" << below
                                      << " above=" << above;
  }
  RecordProperty("worst_relative_difference", std::to_string(worst));
  // A slab holding the whole ball is the uncut area; the two halves of a ball cut at its centre add
  // up to it.
  EXPECT_NEAR(cylinder_area_in_sphere_slab(1.2, 0.5, 1.0, 3, 3), cylinder_area_in_sphere(1.2, 0.5, 1.0), 1e-15);
  EXPECT_NEAR(cylinder_area_in_sphere_slab(1.2, 0.5, 1.0, 3, 0) + cylinder_area_in_sphere_slab(1.2, 0.5, 1.0, 0, 3),
              cylinder_area_in_sphere(1.2, 0.5, 1.0), 1e-14);
  EXPECT_NEAR(cylinder_area_in_sphere_slab(0.0, 1.0, 0.6, 0.2, 0.3), 2 * kPi * 0.6 * 0.5, 1e-15);
}

TEST(porosity_CylinderInSphere, ElementaryLimits) {
  // Centre on the axis: the chord 2 sqrt(a^2 - r^2) all around.
  EXPECT_NEAR(cylinder_area_in_sphere(0.0, 1.0, 0.6), 2 * kPi * 0.6 * 2 * 0.8, 1e-15);
  EXPECT_NEAR(cylinder_area_in_sphere(1e-12, 1.0, 0.6), 2 * kPi * 0.6 * 2 * 0.8, 1e-11);
  // Circles tangent to the shadow from outside (r = rho + a) or inside (r = rho - a): area 0.
  EXPECT_EQ(cylinder_area_in_sphere(2.0, 0.5, 2.5), 0.0);
  EXPECT_EQ(cylinder_area_in_sphere(2.0, 0.5, 1.5), 0.0);
  // The circle through the sphere's centre's axis-opposite point (r + rho = a): both branches meet;
  // the value is 8 r sqrt(s) E(1) = 8 r sqrt(s) with s = a^2 - (r - rho)^2.
  const double rho = 0.3, a = 1.0, r = 0.7, s = a * a - (r - rho) * (r - rho);
  EXPECT_NEAR(cylinder_area_in_sphere(rho, a, r), 8 * r * std::sqrt(s), 1e-14);
  EXPECT_NEAR(cylinder_area_in_sphere(rho, a, r * (1 + 1e-12)), 8 * r * std::sqrt(s), 1e-10);
  EXPECT_NEAR(cylinder_area_in_sphere(rho, a, r * (1 - 1e-12)), 8 * r * std::sqrt(s), 1e-10);
  // Integral over r of L(r) is the sphere's volume (shells of radius r, thickness dr).
  const double rc = 1.7, ac = 0.45;
  const double vol = integrate_sqrt_ends([&](double x) { return cylinder_area_in_sphere(rc, ac, x); }, rc - ac, rc + ac,
                                         1e-14).value;
  EXPECT_NEAR(vol, 4 * kPi * ac * ac * ac / 3, 1e-12);
}

TEST(porosity_CylinderInSphere, MatchesSeedKernelIntegratedOverHeight) {
  Particle p;
  p.centre = Vec3(1.3, -0.4, 2.0);
  p.diameter = 0.9;
  const ParticleShape s(p);
  const BedSlab slab{-10, 10};
  for (int k = 1; k < 20; ++k) {
    const double r = s.rho_min() + (s.rho_max() - s.rho_min()) * k / 20;
    const QuadResult closed = lateral_area(s, r, slab, 1e-13, ProfileMethod::kChord);
    const QuadResult kernel = lateral_area(s, r, slab, 1e-13, ProfileMethod::kKernel);
    EXPECT_EQ(closed.evaluations, 1);  // the closed form, not a quadrature
    EXPECT_NEAR(closed.value, kernel.value, 1e-10) << r;
  }
}

TEST(porosity_CylinderInSphere, MatchesMonteCarlo) {
  // Uniform points on the cylinder patch |t| <= pi, |z - c_z| <= a: area times the fraction inside.
  const double rho = 0.8, a = 0.6, r = 1.1;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> T(-kPi, kPi), Z(-a, a);
  const int n = 2'000'000;
  long in = 0;
  for (int k = 0; k < n; ++k) {
    const double t = T(rng), z = Z(rng), x = r * std::cos(t) - rho, y = r * std::sin(t);
    in += x * x + y * y + z * z <= a * a;
  }
  const double patch = 2 * kPi * r * 2 * a, f = static_cast<double>(in) / n;
  const double sigma = patch * std::sqrt(f * (1 - f) / n);
  EXPECT_NEAR(cylinder_area_in_sphere(rho, a, r), patch * f, 4 * sigma);
}

TEST(porosity_FixedPointSum, SameBitsInAnyOrderAndCloseToTheLongDoubleSum) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<double> terms(100000);
  for (double& t : terms) t = std::pow(U(rng), 8) * 3.7;
  long double exact = 0;
  for (double t : terms) exact += t;
  FixedPointSum forward(1e5), shuffled(1e5), left(1e5), right(1e5);
  for (double t : terms) forward.add(t);
  std::shuffle(terms.begin(), terms.end(), rng);
  for (double t : terms) shuffled.add(t);
  for (std::size_t k = 0; k < terms.size(); ++k) (k < 777 ? left : right).add(terms[k]);
  left += right;
  EXPECT_EQ(forward.value(), shuffled.value());
  EXPECT_EQ(forward.value(), left.value());
  EXPECT_NEAR(forward.value(), static_cast<double>(exact), 1e-15 * forward.value());
  // Negative terms and the word round trip (two's complement across the 64-bit boundary).
  FixedPointSum neg(1.0), back(1.0);
  neg.add(-0.375);
  std::uint64_t w[2];
  neg.words(w);
  back.set_words(w);
  EXPECT_EQ(back.value(), -0.375);
  std::uint64_t a[2], b[2];
  FixedPointSum p(1.0);
  p.add(0.5);
  p.words(a);
  neg.words(b);
  add_fixed_point_words(a, b);
  back.set_words(b);
  EXPECT_EQ(back.value(), 0.125);
}

TEST(porosity_ProfileSplit, SameBitsForOneTwoAndThreeProcessesAndARankWithNothing) {
  // Spheres and spherocylinders (quadrature: the accuracy budget needs the global counts).
  for (const auto& ps : {testing::drop_and_roll_bed(3.0, 300, 42).particles, testing::rsa_bed(3.0, 0.6, 1.2, 60, 0.2, 7).particles}) {
    double zmax = 0;
    for (const auto& p : ps) zmax = std::max(zmax, p.centre.z() + p.radius() + p.half_length());
    const Container c{2.8, {0.2, zmax - 0.3}};
    const auto radii = even_radii(c.radius, 40);
    const auto heights = slice_centres(c.slab.z_min, c.slab.z_max, 20);
    const PorosityProfile radial1 = radial_profile(ps, c, radii);
    const PorosityProfile axial1 = axial_profile(ps, c, heights);
    const BulkPorosity bulk1 = bulk_porosity(ps, c);
    for (int n : {2, 3, 4}) {
      testing::ThreadGroup group(n);
      std::vector<PorosityProfile> radial(n), axial(n);
      std::vector<BulkPorosity> bulk(n);
      std::vector<std::thread> ranks;
      for (int k = 0; k < n; ++k)
        ranks.emplace_back([&, k] {
          testing::ThreadGroup::Member me(group, k);
          ProfileOptions opt;
          opt.threads = 1;
          opt.communicator = &me;
          // Rank n-1 of 4 gets no particles; the others split the rest unevenly.
          const std::size_t parts = n == 4 ? 3 : n;
          const std::size_t b = k < static_cast<int>(parts) ? ps.size() * k * k / (parts * parts) : ps.size();
          const std::size_t e = k < static_cast<int>(parts) ? ps.size() * (k + 1) * (k + 1) / (parts * parts) : ps.size();
          const std::span<const Particle> mine(ps.data() + b, e - b);
          radial[k] = radial_profile(mine, c, radii, opt);
          axial[k] = axial_profile(mine, c, heights, opt);
          bulk[k] = bulk_porosity(mine, c, opt);
        });
      for (auto& t : ranks) t.join();
      for (int k = 0; k < n; ++k) {
        EXPECT_EQ(radial[k].porosity, radial1.porosity) << n << " ranks, rank " << k;
        EXPECT_EQ(axial[k].porosity, axial1.porosity) << n << " ranks, rank " << k;
        EXPECT_EQ(bulk[k].porosity, bulk1.porosity);
        EXPECT_EQ(radial[k].stats.max_error, radial1.stats.max_error);
        EXPECT_EQ(radial[k].stats.particles_used, radial1.stats.particles_used);
      }
    }
  }
}

}  // namespace
}  // namespace ssimarch
