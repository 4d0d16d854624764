// Poles, trims and the model-size rules (docs/math/poles.md): a curve through a pole of a
// parametrisation is one curve, the trim of an implicit form ends the curve exactly, and loops
// of any size close once; lengths against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "testing/matchers.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/march/model_size.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/surface/degenerate_edges.hpp"
#include "ssimarch/surface/primitives.hpp"
#include "ssimarch/trace/trace_all.hpp"
#include "testing/nurbs_sphere.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

double total_length(const TraceResult& r) {
  double s = 0;
  for (const auto& c : r.curves) s += c.length;
  return s;
}

// Viviani's curve on the sphere of radius 2a and the cylinder (x - a)^2 + y^2 = a^2:
// x = a(1 + cos t), y = a sin t, z = 2a sin(t/2), t in [0, 4 pi), |x'| = a sqrt(1 + cos^2(t/2)),
// so the length is 2a int_0^{2 pi} sqrt(1 + cos^2 s) ds, here by Simpson's rule.
double viviani_length(double a) {
  const int n = 20000;
  const double h = 2 * kPi / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double c = std::cos(i * h);
    sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * std::sqrt(1 + c * c);
  }
  return 2 * a * sum * h / 3;
}

using testing::nurbs_sphere;

void expect_one_closed_curve(const TraceResult& r, double length, double rel) {
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_NEAR(r.curves[0].length / length - 1, 0.0, rel);
  EXPECT_GT(r.curves[0].points.size(), 10u);
}

TEST(DegenerateEdges, SpherePolesConeApexAndTheRationalSphere) {
  const auto sphere = degenerate_edges(Sphere(Vec3(1, 2, 3), 2));
  ASSERT_EQ(sphere.size(), 2u);
  EXPECT_THAT(sphere[0].point, testing::IsNear(Vec3(1, 2, 1), 1e-15));
  EXPECT_THAT(sphere[1].point, testing::IsNear(Vec3(1, 2, 5), 1e-15));
  EXPECT_TRUE(degenerate_edges(Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-1, 1})).empty());
  const auto cone = degenerate_edges(Cone(Vec3::Zero(), Vec3::UnitZ(), 0.5, {0, 1}));
  ASSERT_EQ(cone.size(), 1u);
  EXPECT_FALSE(cone[0].upper);
  const Surface nurbs = nurbs_sphere();
  const auto poles = degenerate_edges(nurbs);
  ASSERT_EQ(poles.size(), 2u);
  EXPECT_THAT(poles[0].point, testing::IsNear(Vec3(0, 0, -1), 1e-15));
  // The patch's seam u = 0 ~ 1 is one curve: the patch is periodic in u (bspline_surface.hpp),
  // so the sampled seam test has nothing left to add; v runs pole to pole.
  EXPECT_TRUE(nurbs.domain().periodic_u);
  EXPECT_FALSE(nurbs.domain().periodic_v);
  EXPECT_FALSE(closes_seam(nurbs, 0));
  EXPECT_FALSE(closes_seam(nurbs, 1));
}

TEST(Poles, PlaneThroughBothPolesIsOneCircleInEveryForm) {
  const Sphere sphere(Vec3::Zero(), 2);
  const Plane plane(Vec3::Zero(), Vec3::UnitX(), {{-3, 3}, {-3, 3}});
  expect_one_closed_curve(trace_all(Problem(sphere, plane, PairKind::kParametricImplicit), {}), 4 * kPi, 1e-7);
  expect_one_closed_curve(trace_all(Problem(sphere, plane, PairKind::kParametricParametric), {}), 4 * kPi, 1e-7);
  expect_one_closed_curve(trace_all(Problem(plane, sphere, PairKind::kParametricParametric), {}), 4 * kPi, 1e-7);
}

TEST(Poles, VivianiCurveIsOneClosedCurveThroughBothPoles) {
  const Sphere sphere(Vec3::Zero(), 2);
  const Cylinder cylinder(Vec3(1, 0, 0), Vec3::UnitZ(), 1, {-3, 3});
  for (PairKind kind : {PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
    const TraceResult r = trace_all(Problem(sphere, cylinder, kind), {});
    EXPECT_NEAR(total_length(r) / viviani_length(1) - 1, 0.0, 1e-6) << to_string(kind);
    for (const auto& c : r.curves) {
      EXPECT_TRUE(c.closed) << to_string(kind);
      EXPECT_GT(c.points.size(), 10u) << to_string(kind);  // no one-point curves at the poles
    }
  }
}

TEST(Poles, ExactRationalSphereThroughItsPolesAndAcrossItsSeam) {
  const Surface sphere = nurbs_sphere();
  const Plane through_poles(Vec3::Zero(), Vec3(1, 1, 0), {{-2, 2}, {-2, 2}});
  expect_one_closed_curve(trace_all(Problem(sphere, through_poles, PairKind::kParametricImplicit), {}), 2 * kPi, 1e-7);
  const Plane across_seam(Vec3(0.5, 0, 0), Vec3::UnitX(), {{-2, 2}, {-2, 2}});
  expect_one_closed_curve(trace_all(Problem(sphere, across_seam, PairKind::kParametricImplicit), {}),
                          2 * kPi * std::sqrt(0.75), 1e-7);
}

// A cylinder of length 4 (axis along (1,1,0)/sqrt 2, not a coordinate axis) cut by the plane
// z = 0.5 parallel to its axis: two lines of length exactly 4, ending on the trim's faces.
TEST(Trims, ImplicitCylinderEndsOnItsRangeInEveryForm) {
  const Cylinder cylinder(Vec3::Zero(), Vec3(1, 1, 0), 1, {-2, 2});
  const Plane plane(Vec3(0, 0, 0.5), Vec3::UnitZ(), {{-5, 5}, {-5, 5}});
  const Problem forms[] = {Problem(cylinder, plane, PairKind::kImplicitImplicit),
                           Problem(plane, cylinder, PairKind::kParametricImplicit),
                           Problem(cylinder, plane, PairKind::kParametricParametric)};
  for (const Problem& P : forms) {
    const TraceResult r = trace_all(P, {});
    ASSERT_EQ(r.curves.size(), 2u) << to_string(P.kind());
    for (const auto& c : r.curves) {
      EXPECT_FALSE(c.closed);
      EXPECT_NEAR(c.length, 4.0, 1e-9) << to_string(P.kind());
      for (const CurvePoint* end : {&c.points.front(), &c.points.back()})
        EXPECT_NEAR(std::fabs(end->p.dot(Vec3(1, 1, 0).normalized())), 2.0, 1e-10) << to_string(P.kind());
    }
  }
}

TEST(ModelSize, RejectsWhatDoublePrecisionCannotTraceNamingTheKey) {
  auto key_of = [](const Problem& P, const TraceOptions& o) {
    try {
      Tracer t(P, o);
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("accepted");
  };
  const Problem tiny(Sphere(Vec3::Zero(), 1e-300), Plane(Vec3::Zero(), Vec3::UnitZ(), {{-2e-300, 2e-300}, {-2e-300, 2e-300}}),
                     PairKind::kParametricImplicit);
  EXPECT_EQ(key_of(tiny, {}), "model size");
  const Problem unit(Sphere(Vec3::Zero(), 1), Plane(Vec3::Zero(), Vec3::UnitZ(), {{-2, 2}, {-2, 2}}),
                     PairKind::kParametricImplicit);
  TraceOptions o;
  EXPECT_EQ(key_of(unit, o), "accepted");
  o.step_length = 1e-300;
  EXPECT_EQ(key_of(unit, o), "step_length");
  o.step_length = 1e-320;  // subnormal
  EXPECT_EQ(key_of(unit, o), "step_length");
  o.step_length = 0;
  o.max_length = 1e-300;
  EXPECT_EQ(key_of(unit, o), "max_length");
  o.max_length = std::numeric_limits<double>::infinity();
  o.tolerance = 0.1;  // larger than a thousandth of the model
  EXPECT_EQ(key_of(unit, o), "tolerance");
  EXPECT_GT(step_floor(1.0, 1e-12), 0.0);
  EXPECT_EQ(step_floor(1.0, 1e-12), 8e-12);
}

TEST(ModelSize, SmallAndLargeModelsGiveOneClosedCircle) {
  for (double r : {1e-6, 1e6}) {
    const Problem P(Sphere(Vec3::Zero(), r), Plane(Vec3::Zero(), Vec3::UnitY(), {{-2 * r, 2 * r}, {-2 * r, 2 * r}}),
                    PairKind::kParametricImplicit);
    TraceOptions o;
    o.tolerance = std::max(1e-12, 1e-15 * r);
    expect_one_closed_curve(trace_all(P, o), 2 * kPi * r, 1e-7);
  }
}

// The sphere of radius 1 about (0, 0, 1) (poles on the x axis) cut by the plane z = 1e-12: a
// circle of radius sqrt(2e-12 - 1e-24) ~ 1.4e-6 where the surfaces are nearly tangent
// (sin theta ~ 1.4e-6), from a start on it with the default step (~0.3, 2e5 times the loop):
// closed once, with the circle's length.
TEST(Closure, LoopFarSmallerThanTheStepClosesOnce) {
  const double gap = 1e-12, r = std::sqrt(2 * gap - gap * gap);
  const Problem P(Sphere(Vec3(0, 0, 1), 1, Vec3::UnitX()), Plane(Vec3(0, 0, gap), Vec3::UnitZ(), {{-2, 2}, {-2, 2}}),
                  PairKind::kParametricImplicit);
  const Tracer tracer(P, TraceOptions{});
  const Vec3 on(0, r, gap);  // in the sphere's frame: u along the circle of latitude about x
  const std::optional<Vec2> uv = closest_parameters(P.first(), on);
  ASSERT_TRUE(uv.has_value());
  VecX x(2);
  x << (*uv)[0], (*uv)[1];
  ASSERT_THAT(P.point(x), testing::IsNear(on, 1e-15));
  const CurvePoint start{x, P.point(x), curve_jet_dynamic(P, x, 1).tangent()};
  TraceStats stats;
  MarchLimits limits = tracer.limits();
  limits.max_points = 500;
  const MarchResult m = tracer.march_until_event(start, Direction::kForward, limits, &stats);
  EXPECT_EQ(m.event.kind, EventKind::kClosed) << m.event.message;
  // Points are fixed across the curve only to tolerance / sin(theta) (~0.7 of r at worst); the
  // converged residuals are far smaller, and the length comes out to a few 1e-6.
  EXPECT_NEAR(m.length / (2 * kPi * r) - 1, 0.0, 1e-4);
}

}  // namespace
}  // namespace ssimarch
