// The one Frenet builder from a curve jet: its values on a circle agree with the general
// formulas, and what it cannot determine is NaN (never 0): the frame of a straight line, and
// torsion and kappa' from a jet of order 2.
#include <gtest/gtest.h>

#include <cmath>

#include "testing/matchers.hpp"
#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/surface/plane.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {
namespace {

const ParamDomain kWide{{-3, 3}, {-3, 3}};

TEST(FrenetFromJet, CircleOfRadiusTwoAgreesWithTheGeneralFormulas) {
  // Sphere radius 2 cut by the plane z = 0: the circle of radius 2, kappa = 1/2, tau = kappa' = 0.
  const Problem P(Sphere(Vec3::Zero(), 2.0), Plane(Vec3::Zero(), Vec3::UnitZ(), kWide), PairKind::kImplicitImplicit);
  const Vec3 x(2, 0, 0);
  const DynamicCurveJet jet = curve_jet_dynamic(P, x, 3);
  const CurveGeometry f = frenet_from_jet(jet, P.scale());
  ASSERT_EQ(f.status, GeometryStatus::kOk);
  EXPECT_TRUE(f.has_frame());
  EXPECT_NEAR(f.kappa, 0.5, 1e-14);
  EXPECT_NEAR(f.tau, 0.0, 1e-14);
  EXPECT_NEAR(f.kappa_prime, 0.0, 1e-14);
  EXPECT_THAT(f.n, testing::IsNear(Vec3(-1, 0, 0), 1e-14));
  const CurveGeometry g = frenet_from_derivatives(jet.alpha[1], 2.0 * jet.alpha[2], 6.0 * jet.alpha[3]);
  EXPECT_NEAR(f.kappa, g.kappa, 1e-14);
  EXPECT_THAT(f.n, testing::IsNear(g.n, 1e-14));
  EXPECT_THAT(f.b, testing::IsNear(g.b, 1e-14));
}

TEST(FrenetFromJet, AnOrder2JetLeavesTorsionAndKappaPrimeUndetermined) {
  const Problem P(Sphere(Vec3::Zero(), 2.0), Plane(Vec3::Zero(), Vec3::UnitZ(), kWide), PairKind::kImplicitImplicit);
  const CurveGeometry f = frenet_from_jet(curve_jet_dynamic(P, Vec3(2, 0, 0), 2), P.scale());
  EXPECT_TRUE(f.has_frame());
  EXPECT_NEAR(f.kappa, 0.5, 1e-14);
  EXPECT_TRUE(std::isnan(f.tau));
  EXPECT_TRUE(std::isnan(f.kappa_prime));
}

TEST(FrenetFromJet, AStraightLineHasNoFrameNaNNotZero) {
  // The planes y = 0 and z = 0 meet in the x axis.
  const Problem P(Plane(Vec3::Zero(), Vec3::UnitY(), kWide), Plane(Vec3::Zero(), Vec3::UnitZ(), kWide),
                  PairKind::kImplicitImplicit);
  const CurveGeometry f = frenet_from_jet(curve_jet_dynamic(P, Vec3(0.5, 0, 0), 3), P.scale());
  EXPECT_EQ(f.status, GeometryStatus::kZeroCurvature);
  EXPECT_NEAR(std::fabs(f.t.x()), 1.0, 1e-15);
  EXPECT_LE(f.kappa * P.scale(), kStraightCurvature);
  EXPECT_FALSE(f.has_frame());
  EXPECT_TRUE(f.n.array().isNaN().all());
  EXPECT_TRUE(f.b.array().isNaN().all());
  EXPECT_TRUE(std::isnan(f.tau));
  EXPECT_TRUE(std::isnan(f.kappa_prime));
}

TEST(FrenetFromJet, ASingularJetGivesOnlyThePoint) {
  // Two spheres of radius 1 touching at the origin: no tangent there.
  const Problem P(Sphere(Vec3(-1, 0, 0), 1.0), Sphere(Vec3(1, 0, 0), 1.0), PairKind::kImplicitImplicit);
  const CurveGeometry f = frenet_from_jet(curve_jet_dynamic(P, Vec3::Zero(), 3), P.scale());
  EXPECT_EQ(f.status, GeometryStatus::kSingular);
  EXPECT_FALSE(f.has_tangent());
  EXPECT_EQ(f.point.norm(), 0.0);
}

}  // namespace
}  // namespace ssimarch
