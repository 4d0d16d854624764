// Closed-form sections (docs/math/closed_form_quadrics.md) against closed-form lengths, radii and
// points worked out by hand, with every output point on both surfaces to 1e-12.
#include "ssimarch/analytic/closed_form.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "ssimarch/analytic/conic_pieces.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

Plane big_plane(const Vec3& point, const Vec3& normal) { return Plane(point, normal, ParamDomain{{-6, 6}, {-6, 6}}); }

ClosedFormResult solve(Surface a, Surface b) {
  const Problem problem(std::move(a), std::move(b), PairKind::kImplicitImplicit);
  TraceOptions options;
  auto r = closed_form_intersection(problem, options);
  EXPECT_TRUE(r.has_value());
  if (!r) return {};
  // Every point exactly on both surfaces (first-order distance, model units).
  for (const TracedCurve& c : r->result.curves)
    for (const CurvePoint& p : c.points) EXPECT_LE(problem.linearize(p.x).distance, 1e-12) << p.p.transpose();
  return *r;
}

// Perimeter of an ellipse by the composite midpoint rule on 20000 pieces (independent of the
// library's Gauss-Legendre; error ~1e-12 for these smooth periodic integrands).
double ellipse_perimeter(double a, double b) {
  const int n = 20000;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * 2 * kPi / n;
    s += std::hypot(a * std::sin(t), b * std::cos(t));
  }
  return s * 2 * kPi / n;
}

TEST(ClosedForm, PlaneSphereIsACircleOfRadiusSqrtR2MinusD2) {
  const Vec3 n(1, 1, 2);
  const double d = 2 / n.norm();  // distance of the plane through (0,0,1) from the centre
  const auto r = solve(Sphere(Vec3::Zero(), 2), big_plane(Vec3(0, 0, 1), n));
  ASSERT_EQ(r.conics.size(), 1u);
  EXPECT_EQ(r.conics[0].type, ConicType::kCircle);
  EXPECT_NEAR(r.conics[0].a, std::sqrt(4 - d * d), 1e-14);
  EXPECT_THAT(r.conics[0].center, testing::IsNear(d * n.normalized(), 1e-14));
  EXPECT_TRUE(r.result.curves[0].closed);
  EXPECT_THAT(r.result.curves[0], testing::HasLength(2 * kPi * std::sqrt(4 - d * d), 1e-12));
  EXPECT_EQ(r.pair, "plane-quadric");
}

TEST(ClosedForm, ObliquePlaneCylinderIsAnEllipse) {
  // z = x / 2 cuts x^2 + y^2 = 1 in an ellipse with semi-axes sqrt(1 + 1/4) and 1.
  const auto r = solve(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-3, 3}), big_plane(Vec3::Zero(), Vec3(-0.5, 0, 1)));
  ASSERT_EQ(r.conics.size(), 1u);
  EXPECT_EQ(r.conics[0].type, ConicType::kEllipse);
  EXPECT_NEAR(r.conics[0].a, std::sqrt(1.25), 1e-14);
  EXPECT_NEAR(r.conics[0].b, 1, 1e-14);
  EXPECT_THAT(r.result.curves[0], testing::HasLength(ellipse_perimeter(std::sqrt(1.25), 1), 1e-10));
}

TEST(ClosedForm, PlaneParallelToTheAxisGivesTwoLinesClippedToTheTrim) {
  const auto r = solve(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-1, 1}), big_plane(Vec3(0.5, 0, 0), Vec3::UnitX()));
  ASSERT_EQ(r.conics.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(r.conics[i].type, ConicType::kLine);
    EXPECT_EQ(r.conics[i].contact, Contact::kTransversal);
    EXPECT_FALSE(r.result.curves[i].closed);
    EXPECT_NEAR(std::fabs(r.result.curves[i].points[0].p.y()), std::sqrt(0.75), 1e-14);
    EXPECT_THAT(r.result.curves[i], testing::HasLength(2, 1e-12));  // the cylinder's axial range [-1, 1]
    EXPECT_NEAR(std::fabs(r.result.curves[i].points.back().p.z()), 1, 1e-14);
  }
}

TEST(ClosedForm, CylinderLyingOnAPlaneTouchesItAlongALine) {
  // Cylinder x^2 + (z-1)^2 = 1 along y, plane z = 0: the double line x = z = 0 (cases.jsonl).
  const auto r = solve(Cylinder(Vec3(0, 0, 1), Vec3::UnitY(), 1, {-2, 2}), big_plane(Vec3::Zero(), Vec3::UnitZ()));
  ASSERT_EQ(r.conics.size(), 1u);
  EXPECT_EQ(r.conics[0].type, ConicType::kLine);
  EXPECT_EQ(r.conics[0].contact, Contact::kTangential);
  EXPECT_NEAR(r.conics[0].center.x(), 0, 1e-15);
  EXPECT_NEAR(r.conics[0].center.z(), 0, 1e-15);
  EXPECT_NEAR(std::fabs(r.conics[0].e0.y()), 1, 1e-15);
  EXPECT_THAT(r.result.curves[0], testing::HasLength(4, 1e-12));  // y in [-2, 2] (cases.jsonl: length 4)
}

TEST(ClosedForm, SphereOnAPlaneTouchesItAtOnePoint) {
  const auto r = solve(Sphere(Vec3(0, 0, 1), 1), big_plane(Vec3::Zero(), Vec3::UnitZ()));
  EXPECT_TRUE(r.result.curves.empty());
  ASSERT_EQ(r.result.isolated_points.size(), 1u);
  EXPECT_NEAR(r.result.isolated_points[0].p.norm(), 0, 1e-15);
}

TEST(ClosedForm, PlaneConeSectionsByTheirAngle) {
  // Cone apex 0, axis z, half-angle 30 degrees (both nappes, |h| <= 4).
  const double alpha = kPi / 6, t = std::tan(alpha);
  auto cone = [&] { return Cone(Vec3::Zero(), Vec3::UnitZ(), alpha, {-4, 4}); };
  const auto circle = solve(cone(), big_plane(Vec3(0, 0, 2), Vec3::UnitZ()));
  ASSERT_EQ(circle.conics.size(), 1u);
  EXPECT_EQ(circle.conics[0].type, ConicType::kCircle);
  EXPECT_NEAR(circle.conics[0].a, 2 * t, 1e-14);
  // A plane steeper than the generators: a hyperbola (both branches, one per nappe).
  const auto hyperbola = solve(cone(), big_plane(Vec3(0.5, 0, 0), Vec3::UnitX()));
  ASSERT_EQ(hyperbola.conics.size(), 2u);
  EXPECT_EQ(hyperbola.conics[0].type, ConicType::kHyperbola);
  // x = 0.5: y^2 = z^2 t^2 - 0.25, so the vertices are z = +-0.5 / t: a = 0.5 / t, b = 0.5.
  EXPECT_NEAR(hyperbola.conics[0].a, 0.5 / t, 1e-13);
  EXPECT_NEAR(hyperbola.conics[0].b, 0.5, 1e-13);
  // A plane parallel to a generator: a parabola; through the apex and steep: two lines.
  const auto parabola = solve(cone(), big_plane(Vec3(0, 0, 1), Vec3(-std::cos(alpha), 0, std::sin(alpha))));
  ASSERT_EQ(parabola.conics.size(), 1u);
  EXPECT_EQ(parabola.conics[0].type, ConicType::kParabola);
  const auto lines = solve(cone(), big_plane(Vec3::Zero(), Vec3::UnitX()));
  ASSERT_EQ(lines.conics.size(), 2u);
  EXPECT_EQ(lines.conics[0].type, ConicType::kLine);
}

TEST(ClosedForm, TwoSpheresMeetInTheRadicalPlane) {
  // |p| = 2 and |p - (1.5,0,0)| = 1.5: x = 4/3, r^2 = 4 - 16/9.
  const auto r = solve(Sphere(Vec3::Zero(), 2), Sphere(Vec3(1.5, 0, 0), 1.5));
  ASSERT_EQ(r.conics.size(), 1u);
  EXPECT_EQ(r.pair, "coaxial");
  EXPECT_NEAR(r.conics[0].center.x(), 4.0 / 3, 1e-14);
  EXPECT_NEAR(r.conics[0].a, std::sqrt(20.0 / 9), 1e-14);
  EXPECT_THAT(r.result.curves[0], testing::HasLength(2 * kPi * std::sqrt(20.0 / 9), 1e-12));
}

TEST(ClosedForm, SphereOnACylindersAxisMeetsItInTwoCircles) {
  const auto r = solve(Sphere(Vec3::Zero(), 2), Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-3, 3}));
  ASSERT_EQ(r.conics.size(), 2u);
  for (const Conic& c : r.conics) {
    EXPECT_NEAR(std::fabs(c.center.z()), std::sqrt(3.0), 1e-14);
    EXPECT_NEAR(c.a, 1, 1e-14);
  }
}

TEST(ClosedForm, ConeOnASpheresAxisOpenCascadeBug21494) {
  // OpenCASCADE tests/lowalgos/intss/bug21494_2: pcone 15 0 10 (apex (0,0,10), opening downwards,
  // tan alpha = 1.5) and psphere 10: (15 - 1.5 z)^2 + z^2 = 100 at z = 25 / 6.5 (a circle of
  // radius 120/13) and z = 10 (the apex, on the sphere's pole).
  const auto r = solve(Cone(Vec3(0, 0, 10), -Vec3::UnitZ(), std::atan(1.5), {0, 10}), Sphere(Vec3::Zero(), 10));
  ASSERT_EQ(r.conics.size(), 1u);
  EXPECT_NEAR(r.conics[0].center.z(), 25 / 6.5, 1e-13);
  EXPECT_NEAR(r.conics[0].a, 120.0 / 13, 1e-13);
  EXPECT_THAT(r.result.curves[0], testing::HasLength(2 * kPi * 120 / 13, 1e-11));
  ASSERT_EQ(r.result.isolated_points.size(), 1u);
  EXPECT_THAT(r.result.isolated_points[0].p, testing::IsNear(Vec3(0, 0, 10), 1e-13));
}

TEST(ClosedForm, SphereInsideAnEqualCylinderTouchesAlongTheEquator) {
  // OpenCASCADE tests/lowalgos/intss/bug24694_7: cylinder 10 (trimmed to [-20, 20]) and sphere 10.
  const auto r = solve(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 10, {-20, 20}), Sphere(Vec3::Zero(), 10));
  ASSERT_EQ(r.conics.size(), 1u);
  EXPECT_EQ(r.conics[0].contact, Contact::kTangential);
  EXPECT_NEAR(r.conics[0].center.norm(), 0, 1e-13);
  EXPECT_THAT(r.result.curves[0], testing::HasLength(20 * kPi, 1e-11));
}

TEST(ClosedForm, PairsWithoutAClosedFormAreLeftToTheTracer) {
  // Not a quadric (the pencil of two quadrics: quadric_pencil_test.cpp).
  const Problem torus(Torus(Vec3::Zero(), Vec3::UnitZ(), 2, 0.5), big_plane(Vec3::Zero(), Vec3::UnitX()),
                      PairKind::kImplicitImplicit);
  EXPECT_FALSE(closed_form_intersection(torus, TraceOptions{}).has_value());
}

TEST(ClosedForm, ChordsKeepTheDeviation) {
  // A circle of radius 1 sampled at deviation 1e-4: sagitta 1 - cos(dtheta / 2) <= 1e-4 per chord.
  Conic c;
  c.type = ConicType::kCircle;
  c.a = c.b = 1;
  c.range = {0, 2 * kPi};
  const TracedCurve curve = sample_conic(c, 1e-4, 10);
  ASSERT_GT(curve.points.size(), 3u);
  for (std::size_t i = 0; i + 1 < curve.points.size(); ++i) {
    const double chord = (curve.points[i + 1].p - curve.points[i].p).norm();
    EXPECT_LE(1 - std::sqrt(1 - chord * chord / 4), 1e-4 * (1 + 1e-9));
  }
  EXPECT_EQ(curve.points.front().p, curve.points.back().p);
}

}  // namespace
}  // namespace ssimarch
