// Seed-001 kernel against the oracle values, an independent brute force (bisection on the
// point-in-spherocylinder test), the sphere closed form, long double, and rotation invariance.
#include "ssimarch/porosity/circle_spherocylinder.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <random>

#include "porosity/brute_force.hpp"
#include "ssimarch/porosity/sphere_arc.hpp"

namespace ssimarch {
namespace {

using testing::brute_arc_length;
constexpr double kPi = std::numbers::pi;

SpherocylinderT<double> make(Vec3 c, Vec3 u, double sigma, double l) {
  SpherocylinderT<double> s;
  s.centre = c;
  s.axis = u.normalized();
  s.diameter = sigma;
  s.length = l;
  return s;
}

// Agreement required by issue 5 (a): 1e-9 relative to the length, with a floor of 1e-9 r for
// lengths near zero (where only the absolute error of the crossing angles is meaningful).
double tol_for(double value, double r) { return 1e-9 * std::max(value, r); }

// An exact tangency built in floating point is tangent only to within rounding (about eps * s^2 in
// the polynomial value), which changes the arc by up to about sqrt(eps) r: the problem's own
// conditioning, for the kernel and the brute force alike. Tests of exact tangencies use this bound.
double tangency_tol(double r) { return 4 * std::sqrt(2.220446049250313e-16) * r; }

struct OracleCase {
  const char* id;
  Vec3 c, u;
  double sigma, l, z, r, value, tol;
};

// tests/reference/oracle.json, keys s001.config.* and s001.edge_pi.* (values printed to 12 digits).
const OracleCase kOracle[] = {
    {"s001.config.1", {0, 0, 0}, {0, 0, 1}, 2.0, 3.0, 0.5, 0.7, 4.39822971503, 1e-10},
    {"s001.config.2", {0, 0, 0}, {1, 0, 0}, 1.0, 2.0, 0.2, 1.0, 1.90413527225, 1e-10},
    {"s001.config.3", {0.8, -0.3, 0.1}, {0.6, 0.48, 0.64}, 0.9, 1.5, 0.3, 1.0, 1.14218649461, 1e-10},
    {"s001.config.4", {0, 0, 0}, {1, 0, 0}, 6.0, 1.0, 0.0, 1.0, 6.28318530718, 1e-10},
    {"s001.config.5", {5, 5, 0}, {0, 1, 0}, 1.0, 1.0, 0.0, 1.0, 0.0, 1e-12},
    {"s001.config.6", {-1, 0.5, 0}, {0, 1, 0}, 1.0, 4.0, 0.0, 1.5, 3.6928782520223242, 1e-12},
    {"s001.config.7", {1, 0, 0}, {0, 0, 1}, 1.2, 0.2, 0.45, 1.0, 0.984591902089, 1e-10},
    {"s001.edge_pi.cyl_0.3", {-1.6043446944, -0.0441479769211, 0.594240108465},
     {0.00303393130666, 0.736797110261, -0.676107102146}, 0.8, 1.2, 0.2, 1.3, 0.486128571715, 1e-9},
    {"s001.edge_pi.plus", {-1.04886095969, -0.312935775065, 0.887326753296},
     {0.00303393130666, 0.736797110261, -0.676107102146}, 0.8, 1.2, 0.2, 1.3, 0.319073752452, 1e-9},
    {"s001.edge_pi.minus", {-1.55113904031, 0.312935775065, -0.487326753296},
     {0.00303393130666, 0.736797110261, -0.676107102146}, 0.8, 1.2, 0.2, 1.3, 0.215716956669, 1e-9},
    {"s001.edge_pi.cyl_0.9", {-1.60616505319, -0.486226243077, 0.999904369753},
     {0.00303393130666, 0.736797110261, -0.676107102146}, 0.8, 1.2, 0.2, 1.3, 0.0, 1e-9},
};

TEST(porosity_CircleSpherocylinder, OracleValues) {
  for (const auto& c : kOracle) {
    const auto s = make(c.c, c.u, c.sigma, c.l);
    const auto res = circle_spherocylinder(s, c.z, c.r);
    EXPECT_NEAR(res.inside_length, c.value, c.tol) << c.id << " case " << to_string(res.which);
    EXPECT_NE(res.which, ArcCase::kFallback) << c.id;
  }
}

TEST(porosity_CircleSpherocylinder, OracleCrossingCounts) {
  // s001.config.2: 4 crossings; config.3 and 7: 2; config.6: a tangency at theta = pi plus 2 (a = b = 0).
  EXPECT_EQ(circle_spherocylinder(make({0, 0, 0}, {1, 0, 0}, 1.0, 2.0), 0.2, 1.0).count, 4);
  EXPECT_EQ(circle_spherocylinder(make({0.8, -0.3, 0.1}, {0.6, 0.48, 0.64}, 0.9, 1.5), 0.3, 1.0).count, 2);
  EXPECT_EQ(circle_spherocylinder(make({1, 0, 0}, {0, 0, 1}, 1.2, 0.2), 0.45, 1.0).count, 2);
  const auto r6 = circle_spherocylinder(make({-1, 0.5, 0}, {0, 1, 0}, 1.0, 4.0), 0.0, 1.5);
  EXPECT_EQ(r6.count, 4);
  EXPECT_DOUBLE_EQ(r6.crossing_angles[3], kPi);
  EXPECT_DOUBLE_EQ(r6.crossing_angles[2], kPi);
  EXPECT_TRUE(r6.theta_m_test);
}

TEST(porosity_CircleSpherocylinder, FlowchartOmissionCaseGivesZero) {
  // s001.flowchart_omission.cyl_0.9: theta = pi lies on the infinite cylinder outside |lambda| <= l/2.
  const auto s = make({-1.60616505319, -0.486226243077, 0.999904369753},
                      {0.00303393130666, 0.736797110261, -0.676107102146}, 0.8, 1.2);
  const auto res = circle_spherocylinder(s, 0.2, 1.3);
  EXPECT_NEAR(res.inside_length, 0.0, 1e-9);
  EXPECT_NE(res.which, ArcCase::kFallback);
}

TEST(porosity_CircleSpherocylinder, RandomSweepMatchesBruteForce) {
  // Same distribution as the oracle's random sweep (s001.random_sweep), fresh seed.
  std::mt19937_64 rng(20240501);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N;
  int fallbacks = 0, crossings4 = 0;
  for (int k = 0; k < 1500; ++k) {
    const Vec3 u(N(rng), N(rng), N(rng));
    const Vec3 c(-1.5 + 3 * U(rng), -1.5 + 3 * U(rng), -1.5 + 3 * U(rng));
    const double sigma = 0.2 + 1.8 * U(rng), l = 3 * U(rng), z = -1 + 2 * U(rng), r = 0.2 + 2.3 * U(rng);
    const auto s = make(c, u, sigma, l);
    const auto res = circle_spherocylinder(s, z, r);
    const double ref = brute_arc_length(s, z, r);
    ASSERT_NEAR(res.inside_length, ref, tol_for(ref, r)) << "k=" << k << " case " << to_string(res.which);
    fallbacks += res.which == ArcCase::kFallback;
    crossings4 += res.count == 4;
  }
  EXPECT_EQ(fallbacks, 0);
  EXPECT_GT(crossings4, 0);
}

TEST(porosity_CircleSpherocylinder, AxisVerticalAndHorizontal) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (const Vec3& u : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0),
                               Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0)}) {
    for (int k = 0; k < 200; ++k) {
      const auto s = make({U(rng), U(rng), U(rng)}, u, 0.5 + 0.5 * (U(rng) + 1), 1.5 * (U(rng) + 1));
      const double z = U(rng), r = 0.1 + 1.5 * (U(rng) + 1);
      const double ref = brute_arc_length(s, z, r);
      EXPECT_NEAR(circle_spherocylinder(s, z, r).inside_length, ref, tol_for(ref, r)) << k;
    }
  }
}

TEST(porosity_CircleSpherocylinder, CoaxialSpecialCases) {
  // A.14: circle on the cylindrical surface; A.38: circle on a cap sphere.
  const auto s = make({0, 0, 1}, {0, 0, 1}, 2.0, 3.0);
  const auto on = circle_spherocylinder(s, 1.5, 1.0);
  EXPECT_EQ(on.which, ArcCase::kCoaxialOnSurface);
  EXPECT_NEAR(on.inside_length, 2 * kPi, 1e-14);
  // Plus cap centre (0,0,2.5), radius 1: at z = 3 the section has radius sqrt(0.75).
  const auto cap = circle_spherocylinder(s, 3.0, std::sqrt(0.75));
  EXPECT_EQ(cap.which, ArcCase::kCapSection);
  EXPECT_NEAR(cap.inside_length, 2 * kPi * std::sqrt(0.75), 1e-14);
  EXPECT_NEAR(circle_spherocylinder(s, 3.0, 0.9).inside_length, 0.0, 1e-14);
  EXPECT_NEAR(circle_spherocylinder(s, 3.0, 0.8).inside_length, 2 * kPi * 0.8, 1e-14);
}

TEST(porosity_CircleSpherocylinder, CircleTangentToCylinder) {
  // Vertical axis at distance r + sigma/2 (outside tangency) and r - sigma/2 (inside tangency), then
  // moved inwards by small offsets: the arcs grow like a square root; brute force must agree.
  const double r = 1.3, sigma = 0.6;
  for (double phi : {0.0, 1.0, kPi, -kPi / 2, 3.0}) {
    for (double rho0 : {r + sigma / 2, r - sigma / 2}) {
      for (double off : {0.0, 1e-12, 1e-9, 1e-6, 1e-3}) {
        const double rho = rho0 > r ? rho0 - off : rho0 + off;
        const auto s = make({rho * std::cos(phi), rho * std::sin(phi), 0.1}, {0, 0, 1}, sigma, 2.0);
        const double ref = brute_arc_length(s, 0.3, r);
        const auto res = circle_spherocylinder(s, 0.3, r);
        EXPECT_NEAR(res.inside_length, ref, off == 0 ? tangency_tol(r) : tol_for(ref, r))
            << phi << " " << rho0 << " " << off;
      }
    }
  }
  // Horizontal axis, circle plane touching the top line of the cylinder (and just below it).
  for (double dz : {0.0, 1e-10, 1e-6, 1e-2}) {
    const auto s = make({0.4, -0.2, 0.0}, {0.3, 1, 0}, 0.5, 6.0);
    const double z = 0.25 - dz;
    const double ref = brute_arc_length(s, z, 1.0);
    EXPECT_NEAR(circle_spherocylinder(s, z, 1.0).inside_length, ref, dz == 0 ? tangency_tol(1.0) : tol_for(ref, 1.0))
        << dz;
  }
}

TEST(porosity_CircleSpherocylinder, CapTouchingCircle) {
  // The top point of the plus cap on the circle, and the cap sphere tangent to the circle sideways.
  const double r = 0.9, sigma = 0.5, l = 1.0;
  for (double phi : {0.3, kPi, -2.0}) {
    const Vec3 c(r * std::cos(phi), r * std::sin(phi), 0.0);
    const auto s = make(c, {0, 0, 1}, sigma, l);
    for (double dz : {0.0, 1e-12, 1e-8, 1e-4}) {
      const double z = l / 2 + sigma / 2 - dz;
      const double ref = brute_arc_length(s, z, r);
      EXPECT_NEAR(circle_spherocylinder(s, z, r).inside_length, ref, dz == 0 ? tangency_tol(r) : tol_for(ref, r))
          << phi << " " << dz;
    }
    // Tilted axis; circle at the height of the plus cap centre, sphere externally tangent.
    const Vec3 u = Vec3(0.3, -0.4, 0.866).normalized();
    for (double off : {0.0, 1e-9, 1e-5}) {
      const double rho = r + sigma / 2 - off;
      const Vec3 cap(rho * std::cos(phi), rho * std::sin(phi), 0.2);
      const auto t = make(cap - l / 2 * u, u, sigma, l);
      const double ref = brute_arc_length(t, 0.2, r);
      EXPECT_NEAR(circle_spherocylinder(t, 0.2, r).inside_length, ref, off == 0 ? tangency_tol(r) : tol_for(ref, r))
          << phi << " " << off;
    }
  }
}

TEST(porosity_CircleSpherocylinder, ThetaNearPi) {
  // Rotating a configuration about the z axis by beta shifts every crossing by beta and keeps the
  // length. Choose beta so that a crossing lands at pi - eps, pi, -pi + eps.
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N;
  int tested = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 u(N(rng), N(rng), N(rng));
    const Vec3 c(-1.5 + 3 * U(rng), -1.5 + 3 * U(rng), -1.5 + 3 * U(rng));
    const auto s = make(c, u, 0.2 + 1.8 * U(rng), 3 * U(rng));
    const double z = -1 + 2 * U(rng), r = 0.2 + 2.3 * U(rng);
    const auto base = circle_spherocylinder(s, z, r);
    if (base.count == 0) continue;
    for (double eps : {0.0, 1e-14, 1e-11, 1e-8, -1e-14, -1e-11, -1e-8}) {
      const double beta = kPi - eps - base.crossing_angles[0];
      const Eigen::Matrix3d R = Eigen::AngleAxisd(beta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      const auto rs = make(R * s.centre, R * s.axis, s.diameter, s.length);
      const auto res = circle_spherocylinder(rs, z, r);
      const double ref = brute_arc_length(rs, z, r);
      EXPECT_NEAR(res.inside_length, ref, tol_for(ref, r)) << k << " eps " << eps;
      EXPECT_NEAR(res.inside_length, base.inside_length, tol_for(ref, r)) << k << " eps " << eps;
      ++tested;
    }
  }
  EXPECT_GT(tested, 500);
}

TEST(porosity_CircleSpherocylinder, ZeroLengthMatchesSphereClosedForm) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 c(2 * U(rng), 2 * U(rng), U(rng));
    const double d = 0.2 + 1.5 * (U(rng) + 1), z = U(rng), r = 0.05 + 1.5 * (U(rng) + 1);
    const auto s = make(c, {U(rng), U(rng), U(rng) + 0.01}, d, 0.0);
    const double closed = circle_sphere_arc(c, d, z, r);
    EXPECT_NEAR(circle_spherocylinder(s, z, r).inside_length, closed, tol_for(closed, r)) << k;
  }
}

TEST(porosity_CircleSpherocylinder, LongDoubleChoosesTheSameCase) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N;
  for (int k = 0; k < 1000; ++k) {
    const Vec3 u = Vec3(N(rng), N(rng), N(rng)).normalized();
    const Vec3 c(-1.5 + 3 * U(rng), -1.5 + 3 * U(rng), -1.5 + 3 * U(rng));
    const double sigma = 0.2 + 1.8 * U(rng), l = 3 * U(rng), z = -1 + 2 * U(rng), r = 0.2 + 2.3 * U(rng);
    const auto d = circle_spherocylinder(make(c, u, sigma, l), z, r);
    SpherocylinderT<long double> sl;
    sl.centre = c.cast<long double>();
    sl.axis = u.cast<long double>();
    sl.diameter = sigma;
    sl.length = l;
    const auto q = circle_spherocylinder<long double>(sl, z, r);
    EXPECT_EQ(d.which, q.which) << k;
    EXPECT_EQ(d.count, q.count) << k;
    EXPECT_EQ(d.theta_m_test, q.theta_m_test) << k;
    EXPECT_NEAR(d.inside_length, static_cast<double>(q.inside_length), 1e-12 * std::max(1.0, d.inside_length)) << k;
  }
}

}  // namespace
}  // namespace ssimarch
