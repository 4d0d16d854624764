// The one Frenet builder (geometry/curve_geometry.hpp, docs/math/frenet.md): the twisted cubic
// (t, t^2, t^3) in its own, non-arc-length parameter against its closed forms; and the builder
// given arc-length data directly.
#include "ssimarch/geometry/curve_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ssimarch {
namespace {

// kappa(t) = 2 sqrt(A) / B^(3/2), tau(t) = 3 / A with A = 9t^4 + 9t^2 + 1, B = 1 + 4t^2 + 9t^4
// (|c1 x c2|^2 = 4A, |c1|^2 = B, (c1 x c2).c3 = 12); kappa' = (dkappa/dt) / sqrt(B).
struct TwistedCubic {
  double t;
  double a() const { return 9 * std::pow(t, 4) + 9 * t * t + 1; }
  double b() const { return 1 + 4 * t * t + 9 * std::pow(t, 4); }
  double kappa() const { return 2 * std::sqrt(a()) / std::pow(b(), 1.5); }
  double tau() const { return 3 / a(); }
  double kappa_prime() const {
    const double da = 36 * std::pow(t, 3) + 18 * t, db = 8 * t + 36 * std::pow(t, 3);
    const double dkappa =
        2 * (da / (2 * std::sqrt(a())) * std::pow(b(), -1.5) - std::sqrt(a()) * 1.5 * std::pow(b(), -2.5) * db);
    return dkappa / std::sqrt(b());
  }
};

TEST(FrenetFrame, TheTwistedCubicInItsOwnParameter) {
  for (double t : {-1.3, -0.4, 0.0, 0.25, 0.7, 2.0}) {
    const TwistedCubic c{t};
    const CurveGeometry g = frenet_from_derivatives(Vec3(1, 2 * t, 3 * t * t), Vec3(0, 2, 6 * t), Vec3(0, 0, 6));
    ASSERT_EQ(g.status, GeometryStatus::kOk) << t;
    EXPECT_NEAR(g.kappa, c.kappa(), 1e-14 * c.kappa()) << t;
    EXPECT_NEAR(g.tau, c.tau(), 1e-14 * c.tau()) << t;
    EXPECT_NEAR(g.kappa_prime, c.kappa_prime(), 1e-13 * (1 + std::fabs(c.kappa_prime()))) << t;
    // A right-handed orthonormal frame, b along c1 x c2.
    EXPECT_NEAR(g.t.norm(), 1, 1e-15);
    EXPECT_NEAR(g.n.norm(), 1, 1e-15);
    EXPECT_NEAR(g.t.dot(g.n), 0, 1e-15);
    EXPECT_NEAR(g.t.cross(g.n).dot(g.b), 1, 1e-15);
    EXPECT_GT(g.b.dot(Vec3(1, 2 * t, 3 * t * t).cross(Vec3(0, 2, 6 * t))), 0);
  }
}

TEST(FrenetFrame, ArcLengthDataGiveTheFrameAndTheThresholdIsStrict) {
  // A circle of radius 2 in the xy plane at (2, 0, 0), tangent +y: c'' = -(1/2) x, c''' = -(1/4) y.
  CurveGeometry g;
  g.t = Vec3(0, 1, 0);
  g.kappa = 0.5;
  const Vec3 third(0, -0.25, 0);
  const CurveGeometry f = frenet_frame(g, Vec3(-0.5, 0, 0), &third, 1e-12);
  EXPECT_EQ(f.status, GeometryStatus::kOk);
  EXPECT_EQ(f.n, Vec3(-1, 0, 0));
  EXPECT_EQ(f.b, Vec3(0, 0, 1));
  EXPECT_EQ(f.tau, 0.0);
  EXPECT_EQ(f.kappa_prime, 0.0);
  // Without c''' the frame is built and tau, kappa' stay undetermined (NaN, never 0).
  const CurveGeometry no_third = frenet_frame(g, Vec3(-0.5, 0, 0), nullptr, 1e-12);
  EXPECT_EQ(no_third.status, GeometryStatus::kOk);
  EXPECT_TRUE(std::isnan(no_third.tau));
  // At the threshold the curve counts as straight.
  const CurveGeometry straight = frenet_frame(g, Vec3(-0.5, 0, 0), &third, 0.5);
  EXPECT_EQ(straight.status, GeometryStatus::kZeroCurvature);
  EXPECT_FALSE(straight.has_frame());
  EXPECT_TRUE(std::isnan(straight.tau));
}

}  // namespace
}  // namespace ssimarch
