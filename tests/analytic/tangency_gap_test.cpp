// Tangency by the gap (docs/math/closed_form_quadrics.md, "Tangency by the gap"): a plane section
// or a coaxial pair is a tangential contact when the surfaces' gap, in model units, is within
// contact_gap_tolerance (the corrector tolerance, stated here as 1e-12), and otherwise the exact
// circle however small. References: the circle of a sphere of radius R cut at depth g has radius
// sqrt(g (2R - g)); two spheres of radii R1, R2 whose centres are R1 + R2 - g apart meet in the
// radical plane in a circle of radius sqrt(R1^2 - x^2), x = (d^2 + R1^2 - R2^2) / (2d).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "ssimarch/analytic/closed_form.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 1e-12;  // model units, stated (the default is relative to the model)

ClosedFormResult solve(Surface a, Surface b) {
  const Problem problem(std::move(a), std::move(b), PairKind::kImplicitImplicit);
  TraceOptions o;
  o.tolerance = kTolerance;
  auto r = closed_form_intersection(problem, o);
  EXPECT_TRUE(r.has_value());
  return r ? *r : ClosedFormResult{};
}

// The radius of a circle computed from coefficients of size ~R^2 that carry a few eps R^2 of
// rounding: r^2 to ~1e-15 R^2, so r to ~1e-15 R^2 / (2 r) plus its own rounding (stated bound,
// about four times the rounding of the inputs).
double radius_tolerance(double R, double r) { return 1e-15 * R * R / r + 1e-15 * r; }

// A unit-radius sphere and a tilted plane (normal (1, 2, 2) / 3) at distance R - g from its
// centre: a gap of g between the plane and the parallel tangent plane.
TEST(TangencyGap, SpherePlaneNearContactIsTheExactCircle) {
  const Vec3 centre(0.3, -0.2, 1.1), n = Vec3(1, 2, 2).normalized();
  const double R = 1;
  for (double g : {1e-6, 1e-9, 1e-10}) {
    SCOPED_TRACE(g);
    const auto r = solve(Sphere(centre, R), Plane(centre - (R - g) * n, n, ParamDomain{{-3, 3}, {-3, 3}}));
    const double radius = std::sqrt(g * (2 * R - g));
    ASSERT_EQ(r.conics.size(), 1u);
    EXPECT_TRUE(r.result.isolated_points.empty());
    EXPECT_EQ(r.conics[0].type, ConicType::kCircle);
    EXPECT_NEAR(r.conics[0].a, radius, radius_tolerance(R, radius));
    EXPECT_THAT(r.conics[0].center, testing::IsNear((centre - (R - g) * n), 1e-14));
    EXPECT_TRUE(r.result.curves[0].closed);
    EXPECT_THAT(r.result.curves[0],
                testing::HasLength(2 * kPi * radius, 2 * kPi * radius_tolerance(R, radius) + 1e-9 * radius));
  }
}

TEST(TangencyGap, SpherePlaneWithinTheToleranceIsOneContactPoint) {
  const Vec3 centre(0.3, -0.2, 1.1), n = Vec3(1, 2, 2).normalized();
  // Gap 0, and half the tolerance short of the sphere: the tangent point (the surfaces are within
  // the tolerance of each other there and nowhere cross).
  for (double g : {0.0, -0.5 * kTolerance}) {
    SCOPED_TRACE(g);
    const auto r = solve(Sphere(centre, 1), Plane(centre - (1 - g) * n, n, ParamDomain{{-3, 3}, {-3, 3}}));
    EXPECT_TRUE(r.result.curves.empty());
    ASSERT_EQ(r.result.isolated_points.size(), 1u);
    EXPECT_THAT(r.result.isolated_points[0].p, testing::IsNear((centre - n), 1e-12));
  }
  // Ten tolerances short of the sphere: nothing.
  const auto miss = solve(Sphere(centre, 1), Plane(centre - (1 + 10 * kTolerance) * n, n, ParamDomain{{-3, 3}, {-3, 3}}));
  EXPECT_TRUE(miss.result.curves.empty());
  EXPECT_TRUE(miss.result.isolated_points.empty());
}

// Issue 26: a plane that cuts the sphere by a gap within the tolerance but above rounding meets it
// in a circle of radius sqrt(g (2R - g)), here 1e-6 to 1.4e-6: a million tolerances, not a point.
// Its radius comes from coefficients of size ~R^2 whose rounding is ~1e-14, a few per cent of
// g: the circle's points are within the tolerance of both surfaces all the same.
TEST(TangencyGap, ACutWithinTheToleranceIsTheCircleItCuts) {
  const Vec3 centre(0.3, -0.2, 1.1), n = Vec3(1, 2, 2).normalized();
  for (double g : {0.5 * kTolerance, kTolerance}) {
    SCOPED_TRACE(g);
    const Sphere sphere(centre, 1);
    const Plane plane(centre - (1 - g) * n, n, ParamDomain{{-3, 3}, {-3, 3}});
    const auto r = solve(sphere, plane);
    EXPECT_TRUE(r.result.isolated_points.empty());
    ASSERT_EQ(r.conics.size(), 1u);
    EXPECT_EQ(r.conics[0].type, ConicType::kCircle);
    const double radius = std::sqrt(g * (2 - g));
    EXPECT_NEAR(r.conics[0].a, radius, 0.05 * radius);
    ASSERT_EQ(r.result.curves.size(), 1u);
    EXPECT_TRUE(r.result.curves[0].closed);
    for (const CurvePoint& p : r.result.curves[0].points) {
      EXPECT_LE(std::fabs((p.p - centre).norm() - 1), kTolerance);
      EXPECT_LE(std::fabs((p.p - (centre - (1 - g) * n)).dot(n)), kTolerance);
    }
  }
}

// The same criterion for two spheres (the coaxial closed form): a gap of 1e-10 is a circle of the
// exact radius, a gap of 0 the contact point.
TEST(TangencyGap, TwoSpheresDecideContactByTheSameGap) {
  const double R1 = 1, R2 = 0.5;
  const Vec3 axis = Vec3(2, -1, 2).normalized(), c1(0.1, 0.2, 0.3);
  for (double g : {1e-6, 1e-9, 1e-10}) {
    SCOPED_TRACE(g);
    const double d = R1 + R2 - g, x = (d * d + R1 * R1 - R2 * R2) / (2 * d);
    const double radius = std::sqrt((R1 - x) * (R1 + x));
    const auto r = solve(Sphere(c1, R1), Sphere(c1 + d * axis, R2));
    ASSERT_EQ(r.conics.size(), 1u);
    EXPECT_EQ(r.pair, "coaxial");
    EXPECT_EQ(r.conics[0].type, ConicType::kCircle);
    EXPECT_NEAR(r.conics[0].a, radius, radius_tolerance(R1, radius));
  }
  const auto touch = solve(Sphere(c1, R1), Sphere(c1 + (R1 + R2) * axis, R2));
  EXPECT_TRUE(touch.result.curves.empty());
  ASSERT_EQ(touch.result.isolated_points.size(), 1u);
  EXPECT_THAT(touch.result.isolated_points[0].p, testing::IsNear((c1 + R1 * axis), 1e-12));
}

// A sphere in a coaxial cylinder 1e-10 narrower than it: two circles 2 sqrt(2 R g) apart, not the
// double circle of the equal cylinder (a gap across the circle, in model units).
TEST(TangencyGap, SphereInANarrowerCylinderIsTwoCircles) {
  const double R = 2, g = 1e-10;
  const auto r = solve(Sphere(Vec3::Zero(), R), Cylinder(Vec3::Zero(), Vec3::UnitZ(), R - g, {-3, 3}));
  ASSERT_EQ(r.conics.size(), 2u);
  for (const Conic& c : r.conics) {
    EXPECT_EQ(c.contact, Contact::kTransversal);
    EXPECT_NEAR(std::fabs(c.center.z()), std::sqrt(g * (2 * R - g)), radius_tolerance(R, std::sqrt(2 * R * g)));
  }
  // The equal cylinder (and one narrower by less than rounding): the double circle of contact.
  for (double d : {0.0, 1e-15}) {
    const auto equal = solve(Sphere(Vec3::Zero(), R), Cylinder(Vec3::Zero(), Vec3::UnitZ(), R - d, {-3, 3}));
    ASSERT_EQ(equal.conics.size(), 1u) << d;
    EXPECT_EQ(equal.conics[0].contact, Contact::kTangential) << d;
  }
  // Issue 26: half a tolerance narrower, the cylinder still cuts the sphere in two circles
  // 2 sqrt(2 R g) = 2.8e-6 apart, a million tolerances: two circles, as the geometry says.
  const double half = 0.5 * kTolerance;
  const auto close = solve(Sphere(Vec3::Zero(), R), Cylinder(Vec3::Zero(), Vec3::UnitZ(), R - half, {-3, 3}));
  ASSERT_EQ(close.conics.size(), 2u);
  for (const Conic& c : close.conics) EXPECT_EQ(c.contact, Contact::kTransversal);
  EXPECT_NEAR(std::fabs(close.conics[0].center.z() - close.conics[1].center.z()), 2 * std::sqrt(half * (2 * R - half)),
              0.05 * std::sqrt(half * R));
}

}  // namespace
}  // namespace ssimarch
