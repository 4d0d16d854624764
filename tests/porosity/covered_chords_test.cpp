// The radial profile of overlapping balls in closed form (issue 30): the half-chord primitive
// against tanh-sinh quadrature, and the union's area on a cylinder against a reference that shares
// none of the library's union code: breakpoints found by sampling the order of every chord end and
// bisecting its changes, each piece of the union's chord length integrated by tanh-sinh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "ssimarch/porosity/particle_union.hpp"
#include "ssimarch/porosity/profile.hpp"
#include "ssimarch/porosity/sphere_arc.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(porosity_HalfChordIntegral, MatchesTanhSinhQuadrature) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  boost::math::quadrature::tanh_sinh<double> ts;
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double a = 0.1 + 2 * U(gen), r = 0.05 + 3 * U(gen);
    // Balls on the axis, with the circle inside the shadow, crossing it, and a far-side tangency.
    const int kind = trial % 4;
    const double rho = kind == 0 ? 0.0 : kind == 3 ? a - r : 3 * U(gen);
    if (!(rho >= 0)) continue;
    const double A = a * a - r * r - rho * rho, B = 2 * r * rho;
    const double s = (a - r + rho) * (a + r - rho);
    if (!(s > 0)) continue;
    // Largest angle inside the shadow: pi, or where A + B cos t = 0.
    const double tmax = B > 0 && A < B ? std::acos(std::max(-1.0, -A / B)) : kPi;
    const double phi = (2 * U(gen) - 1) * tmax;
    auto h = [&](double t) { return std::sqrt(std::max(0.0, A + B * std::cos(t))); };
    const double want = phi >= 0 ? ts.integrate(h, 0.0, phi) : -ts.integrate(h, phi, 0.0);
    EXPECT_NEAR(half_chord_integral(s, 4 * r * rho, phi), want, 1e-13 * (1 + std::sqrt(s)))
        << "a " << a << " r " << r << " rho " << rho << " phi " << phi;
    // Odd in the angle; the whole shadow gives a quarter of cylinder_area_in_sphere / r.
    EXPECT_EQ(half_chord_integral(s, 4 * r * rho, -phi), -half_chord_integral(s, 4 * r * rho, phi));
    EXPECT_NEAR(4 * r * half_chord_integral(s, 4 * r * rho, tmax), cylinder_area_in_sphere(rho, a, r),
                1e-13 * (1 + a * r));
    ++checked;
  }
  EXPECT_GT(checked, 1200);
}

// Length of the union of the balls' vertical chords over (r cos t, r sin t), clipped to [z0, z1],
// and the order of the chords' ends (a label per end and whether a plane holds it): the union's
// length is analytic wherever that order does not change.
struct UnionLine {
  std::vector<Particle> balls;
  double r, z0, z1;

  double length(double t, std::vector<int>* order = nullptr) const {
    std::vector<std::pair<double, int>> ends;
    std::vector<std::pair<double, double>> chords;
    for (std::size_t k = 0; k < balls.size(); ++k) {
      const Vec3& c = balls[k].centre;
      const double dx = r * std::cos(t) - c.x(), dy = r * std::sin(t) - c.y();
      const double q = balls[k].radius() * balls[k].radius() - dx * dx - dy * dy;
      if (!(q > 0)) continue;
      const double lo = std::max(z0, c.z() - std::sqrt(q)), hi = std::min(z1, c.z() + std::sqrt(q));
      if (!(hi > lo)) continue;
      chords.push_back({lo, hi});
      // An end held by a plane of the slab is labelled apart: where a chord starts to be cut the
      // length has a kink although the ends keep their order.
      const int cut_lo = lo == z0 ? 1000 : 0, cut_hi = hi == z1 ? 1000 : 0;
      ends.push_back({lo, static_cast<int>(2 * k) + cut_lo}),
          ends.push_back({hi, static_cast<int>(2 * k + 1) + cut_hi});
    }
    if (order) {
      std::sort(ends.begin(), ends.end());
      order->clear();
      for (const auto& e : ends) order->push_back(e.second);
    }
    std::sort(chords.begin(), chords.end());
    double total = 0, reach = -1e300;
    for (const auto& [lo, hi] : chords) {
      const double from = std::max(lo, reach);
      if (hi > from) total += hi - from, reach = hi;
    }
    return total;
  }

  // r times the integral of the union's length over the circle.
  double area(int n = 65536) const {
    std::vector<double> br{-kPi};
    std::vector<int> left, right, mid;
    for (int k = 1; k <= n; ++k) {
      const double a = -kPi + 2 * kPi * (k - 1) / n, b = -kPi + 2 * kPi * k / n;
      length(a, &left);
      length(b, &right);
      if (left != right) {
        double lo = a, hi = b;
        for (int it = 0; it < 60; ++it) {
          const double m = (lo + hi) / 2;
          length(m, &mid);
          (mid == left ? lo : hi) = m;
        }
        br.push_back((lo + hi) / 2);
      }
    }
    br.push_back(kPi);
    boost::math::quadrature::tanh_sinh<double> ts;
    double total = 0;
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
      total += ts.integrate([&](double t) { return length(t); }, br[k], br[k + 1]);
    return r * total;
  }
};

// The union's area on the cylinder of radius r from the radial profile (tolerance 1e-13).
double profile_area(const std::vector<Particle>& balls, double R, double r, double z0, double z1) {
  Container c;
  c.radius = R;
  c.slab = {z0, z1};
  ProfileOptions opt;
  opt.tolerance = 1e-13;
  opt.threads = 1;
  const std::vector<double> radii{r};
  const PorosityProfile p = radial_profile(balls, c, radii, opt);
  EXPECT_EQ(p.stats.unconverged, 0);
  return (1 - p.porosity[0]) * 2 * kPi * r * (z1 - z0);
}

void expect_union_area(const std::vector<Particle>& balls, double r, double z0, double z1, const char* what) {
  const UnionLine line{balls, r, z0, z1};
  EXPECT_NEAR(profile_area(balls, 20.0, r, z0, z1), line.area(), 1e-10) << what << ", r = " << r;
}

TEST(porosity_CoveredBallChords, UnionAreaOnACylinderMatchesSampledBreakpointsAndTanhSinh) {
  // A DEM contact: two balls of diameter 1 grown 0.5 %, 5 from the axis, the lens 0.1 wide; the
  // radii cross the lens, its rim and its edge.
  const Vec3 c0(5.0, 0.3, 1.0), n = Vec3(0.3, 0.8, 0.52).normalized();
  const std::vector<Particle> dem{make_sphere(c0, 1.005), make_sphere(c0 + n, 1.005)};
  const double rl = std::hypot(5.0 + 0.5 * 0.3 / 1.0, 0.3 + 0.4);  // about the lens's centre
  for (double dr : {-0.04, -0.01, 0.0, 0.013, 0.035}) expect_union_area(dem, rl + dr, -5, 5, "DEM lens");
  // The same lens cut by the slab's top plane.
  const double zl = 1.0 + 0.5 * n.z();
  expect_union_area(dem, rl, -5, zl + 0.01, "lens cut by the slab");
  // A clump around the axis: one ball centred on it, the circles inside shadows and crossing them.
  const std::vector<Particle> clump{make_sphere({0, 0, 0}, 1.2), make_sphere({0.5, 0.1, 0.2}, 1.0),
                                    make_sphere({-0.2, 0.45, -0.3}, 0.9)};
  for (double r : {0.05, 0.3, 0.62, 0.95}) expect_union_area(clump, r, -5, 5, "clump on the axis");
  expect_union_area(clump, 0.4, -0.25, 0.3, "clump in a thin slab");
  // A ball inside another, and three coincident balls.
  expect_union_area({make_sphere({1, 1, 0}, 2.0), make_sphere({1.2, 0.9, 0.1}, 0.6)}, 1.3, -5, 5, "ball inside");
  expect_union_area({make_sphere({0.7, 0, 0}, 1), make_sphere({0.7, 0, 0}, 1), make_sphere({0.7, 0, 0}, 1)}, 0.6, -5, 5,
                    "coincident balls");
}

TEST(porosity_CoveredBallChords, RandomClumpsMatchTheReference) {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const double R0 = trial < 4 ? 0.3 * U(gen) : 1 + 4 * U(gen);
    const Vec3 base(R0, 0, 0);
    std::vector<Particle> balls;
    for (int k = 0; k < 2 + trial % 3; ++k)
      balls.push_back(make_sphere(base + 0.6 * Vec3(U(gen) - 0.5, U(gen) - 0.5, U(gen) - 0.5), 0.6 + 0.8 * U(gen)));
    for (double f : {0.2, 0.5, 0.8}) {
      const double r = std::max(0.02, R0 - 0.7 + 1.4 * f);
      expect_union_area(balls, r, -0.4 + 0.1 * (trial % 2), 5, "random clump");
    }
  }
}

}  // namespace
}  // namespace ssimarch
