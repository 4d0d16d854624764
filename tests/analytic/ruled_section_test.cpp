// Sections along the rulings of a cylinder or cone (analytic/ruled_section.hpp) against closed
// forms (Steinmetz's two ellipses, Viviani's curve) and against the tracer (closed_form off).
#include "ssimarch/analytic/ruled_section.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "ssimarch/analytic/closed_form.hpp"
#include "ssimarch/surface/primitives.hpp"
#include "ssimarch/trace/trace_all.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

// Perimeter of an ellipse by the composite midpoint rule on 20000 pieces (error ~1e-12 here).
double ellipse_perimeter(double a, double b) {
  const int n = 20000;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * 2 * kPi / n;
    s += std::hypot(a * std::sin(t), b * std::cos(t));
  }
  return s * 2 * kPi / n;
}

ClosedFormResult solve(const Problem& problem) {
  auto r = closed_form_intersection(problem, TraceOptions{});
  EXPECT_TRUE(r.has_value());
  if (!r) return {};
  EXPECT_EQ(r->pair, "ruled-quadric");
  for (const TracedCurve& c : r->result.curves)
    for (const CurvePoint& p : c.points) EXPECT_LE(problem.linearize(p.x).distance, 1e-12) << p.p.transpose();
  return *r;
}

double total_length(const TraceResult& r) {
  double s = 0;
  for (const TracedCurve& c : r.curves) s += c.length;
  return s;
}

TEST(RuledSection, TwoEqualCylindersAreTwoEllipsesCrossingAtTwoNodes) {
  // y^2 + z^2 = 1 (axis x) and x^2 + y^2 = 1 (axis z): the ellipses z = x and z = -x, semi-axes
  // sqrt(2) and 1, crossing at (0, +-1, 0) (Steinmetz; the peers case two_cylinders).
  const Problem P(Cylinder(Vec3::Zero(), Vec3::UnitX(), 1, {-2, 2}), Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-2, 2}),
                  PairKind::kImplicitImplicit);
  const ClosedFormResult r = solve(P);
  ASSERT_EQ(r.result.curves.size(), 2u);
  const double ellipse = ellipse_perimeter(std::sqrt(2.0), 1);
  for (const TracedCurve& c : r.result.curves) {
    EXPECT_TRUE(c.closed);
    EXPECT_NEAR(c.length / ellipse - 1, 0, 1e-12);
    // Each curve lies in one of the planes z = x, z = -x.
    const double side = c.points[1].p.z() * c.points[1].p.x() > 0 ? 1 : -1;
    for (const CurvePoint& p : c.points) EXPECT_NEAR(p.p.z(), side * p.p.x(), 1e-12);
  }
  ASSERT_EQ(r.result.singular_points.size(), 2u);
  for (const SingularPointReport& s : r.result.singular_points) {
    EXPECT_EQ(s.type, SingularType::kNode);
    EXPECT_NEAR(std::fabs(s.p.y()), 1, 1e-10);
    EXPECT_NEAR(std::hypot(s.p.x(), s.p.z()), 0, 1e-10);
    EXPECT_EQ(s.curves.size(), 2u);
  }
}

TEST(RuledSection, VivianiIsOneClosedCurveThroughItsNode) {
  // |p| = 2 and x^2 + (y+1)^2 = 1: t^2 = 2 + 2 sin(theta) on the cylinder's rulings, one double
  // root (the node (0, -2, 0)), so the curve goes round the cylinder twice.
  const Problem P(Sphere(Vec3::Zero(), 2), Cylinder(Vec3(0, -1, 0), Vec3::UnitZ(), 1, {-3, 3}),
                  PairKind::kImplicitImplicit);
  const ClosedFormResult r = solve(P);
  ASSERT_EQ(r.result.curves.size(), 1u);
  EXPECT_TRUE(r.result.curves[0].closed);
  // integral_0^{4 pi} sqrt(1 + cos^2(s/2)) ds = 4 sqrt(2) E(1/2) (Viviani's curve).
  EXPECT_THAT(r.result.curves[0], testing::HasLength(15.280791156174, 1e-9));
  ASSERT_EQ(r.result.singular_points.size(), 1u);
  EXPECT_EQ(r.result.singular_points[0].type, SingularType::kNode);
  EXPECT_THAT(r.result.singular_points[0].p, testing::IsNear(Vec3(0, -2, 0), 1e-10));
}

// The closed form against the tracer on the same pair: curve count, closed flags, lengths.
void expect_as_traced(const Problem& P, std::size_t curves) {
  const ClosedFormResult exact = solve(P);
  TraceOptions o;
  o.step_length = 0.01;
  const TraceResult traced = trace_all(P, o);
  ASSERT_EQ(exact.result.curves.size(), curves);
  ASSERT_EQ(traced.curves.size(), curves);
  int closed_exact = 0, closed_traced = 0;
  for (std::size_t i = 0; i < curves; ++i) {
    closed_exact += exact.result.curves[i].closed;
    closed_traced += traced.curves[i].closed;
  }
  EXPECT_EQ(closed_exact, closed_traced);
  EXPECT_NEAR(total_length(exact.result) / total_length(traced) - 1, 0, 1e-5);
}

TEST(RuledSection, OffAxisCylinderThroughASphereIsTwoLoopsAsTraced) {
  // Fully through: Delta > 0 for every ruling, no double root: two loops (top and bottom).
  expect_as_traced(Problem(Sphere(Vec3::Zero(), 2), Cylinder(Vec3(0.7, 0.2, 0), Vec3(0.1, 0, 1), 0.5, {-3, 3}),
                           PairKind::kImplicitImplicit),
                   2);
}

TEST(RuledSection, CylinderBitingAnEllipsoidIsOneLoopAsTraced) {
  // Partly through: two simple roots of Delta, one loop turning on two rulings.
  expect_as_traced(Problem(Ellipsoid(Vec3::Zero(), {1, 1.5, 2}), Cylinder(Vec3(1, 0, 0), Vec3(0, 1, 0.3), 0.6, {-4, 4}),
                           PairKind::kImplicitImplicit),
                   1);
}

TEST(RuledSection, ConeAgainstACylinderAsTraced) {
  // The cylinder is the ruled one; the cone is the quadric Q.
  expect_as_traced(Problem(Cone(Vec3(0, 0, -3), Vec3::UnitZ(), 0.5, {0, 6}), Cylinder(Vec3::Zero(), Vec3::UnitX(), 0.8, {-4, 4}),
                           PairKind::kImplicitImplicit),
                   2);
}

TEST(RuledSection, ConeAgainstASphereAlongTheConesRulings) {
  // A cone with its apex off the sphere, tilted: the cone's rulings carry the quadratic.
  expect_as_traced(Problem(Sphere(Vec3(0.3, 0.1, 0), 1.5), Cone(Vec3(0, 0, -3), Vec3(0.1, 0, 1), 0.3, {0, 6}),
                           PairKind::kImplicitImplicit),
                   2);
}

TEST(RuledSection, NarrowLoopOfNearlyTouchingCylindersHasItsLength) {
  // x^2 + y^2 = 1 and (x - d)^2 + z^2 = 1 (perpendicular axes), d = 2 - eps: a small loop round
  // (1, 0, 0) where Delta is ~eps of its terms all along the loop. References: the arc length of
  // (cos t, sin t, +-sqrt(1 - (cos t - d)^2)) integrated by mpmath at 50 digits with t = T sin s
  // (T = acos(1 - eps), eps = 2 - d of the double d), tanh-sinh quadrature. A difference of
  // points gave 2.80950e-4 for eps = 1e-9 (1.5e-4 short): sqrt(Delta)'s cancellation. The input's
  // own conditioning is eps's rounding, 1.1e-16 / eps: the bound is ten times that, over 2.
  const struct {
    double d, length;
  } cases[] = {{2 - 1e-9, 2.8099260084880896e-4}, {2 - 1e-6, 8.8857653205909771e-3}};
  for (const auto& c : cases) {
    const Problem P(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-3, 3}), Cylinder(Vec3(c.d, 0, 0), Vec3::UnitY(), 1, {-3, 3}),
                    PairKind::kImplicitImplicit);
    const ClosedFormResult r = solve(P);
    ASSERT_EQ(r.result.curves.size(), 1u);
    EXPECT_TRUE(r.result.curves[0].closed);
    const double eps = 2 - c.d;
    EXPECT_NEAR(r.result.curves[0].length / c.length - 1, 0, 10 * 1.1e-16 / eps / 2) << "d = " << c.d;
  }
}

TEST(RuledSection, TrimmedCylinderGivesOpenPiecesEndingOnItsRims) {
  // The z-axis cylinder of the Steinmetz pair cut to |z| <= 0.5: four open arcs, each end on a rim.
  const Problem P(Cylinder(Vec3::Zero(), Vec3::UnitX(), 1, {-2, 2}), Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-0.5, 0.5}),
                  PairKind::kImplicitImplicit);
  const ClosedFormResult r = solve(P);
  ASSERT_EQ(r.result.curves.size(), 4u);
  double total = 0;
  for (const TracedCurve& c : r.result.curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_NEAR(std::fabs(c.points.front().p.z()), 0.5, 1e-12);
    EXPECT_NEAR(std::fabs(c.points.back().p.z()), 0.5, 1e-12);
    total += c.length;
  }
  // On z = x (x = cos s, y = sin s, z = cos s) |z| <= 0.5 keeps s in [pi/3, 2pi/3] and
  // [4pi/3, 5pi/3]: twice integral sqrt(1 + sin^2 s) ds over [pi/3, 2pi/3], for each ellipse.
  const int n = 200000;
  double arc = 0;
  for (int i = 0; i < n; ++i) {
    const double s = kPi / 3 + (i + 0.5) * (kPi / 3) / n;
    arc += std::sqrt(1 + std::sin(s) * std::sin(s)) * (kPi / 3) / n;
  }
  EXPECT_NEAR(total / (4 * arc) - 1, 0, 1e-10);
}

TEST(RuledSection, ApexOnTheQuadricAndParallelRulingsAreLeftToTheTracer) {
  const Problem apex(Sphere(Vec3(0, 0, -2), 1), Cone(Vec3(0, 0, -3), Vec3(0.2, 0, 1), 0.4, {0, 6}),
                     PairKind::kImplicitImplicit);
  EXPECT_FALSE(closed_form_intersection(apex, TraceOptions{}).has_value());
  const Problem parallel(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-2, 2}), Cylinder(Vec3(1, 0, 0), Vec3::UnitZ(), 1, {-2, 2}),
                         PairKind::kImplicitImplicit);
  EXPECT_FALSE(closed_form_intersection(parallel, TraceOptions{}).has_value());
}

}  // namespace
}  // namespace ssimarch
