// A start point on a traced curve, by the curve's geometry (trace/on_traced_curve.hpp; issue 26):
// points of the same curve between its traced points are on it, a second component closer than
// the old resolution radius (a fifth of a step) but farther than the curve's accuracy is not.
#include "ssimarch/trace/on_traced_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTolerance = 1e-12;

// A circle of radius r in the plane z = 0 traced with n points (closed: the last is the first).
TracedCurve circle(double r, int n) {
  TracedCurve c;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * kPi * i / n;
    c.points.push_back({VecX(), Vec3(r * std::cos(a), r * std::sin(a), 0), Vec3(-std::sin(a), std::cos(a), 0)});
  }
  c.closed = true;
  return c;
}

TracedCurve line(const Vec3& from, const Vec3& to, int n) {
  TracedCurve c;
  const Vec3 t = (to - from).normalized();
  for (int i = 0; i <= n; ++i) c.points.push_back({VecX(), from + (to - from) * (static_cast<double>(i) / n), t});
  return c;
}

TEST(OnTracedCurve, HermiteArcOfACircleIsCloseToIt) {
  // 64 points on the unit circle: chord 0.098, sagitta 1.2e-3; the Hermite arc is within 1e-7.
  const double a = 2 * kPi / 64;
  const Vec3 mid(std::cos(a / 2), std::sin(a / 2), 0);
  const double d = hermite_arc_distance(mid, Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(std::cos(a), std::sin(a), 0),
                                        Vec3(-std::sin(a), std::cos(a), 0));
  EXPECT_LT(d, 1e-7);
}

TEST(OnTracedCurve, PointsOfTheSameCurveBetweenItsPointsAreOnIt) {
  const std::vector<TracedCurve> curves = {circle(2, 100)};
  const double radius = 0.2 * 4 * kPi / 100;  // a fifth of the step
  for (double a : {0.013, 1.0, 2.5, 4.0, 6.2}) {
    const Vec3 p(2 * std::cos(a), 2 * std::sin(a), 0);
    EXPECT_TRUE(on_traced_curve(p, curves, radius, kTolerance)) << a;
  }
}

TEST(OnTracedCurve, ASecondComponentInsideTheOldRadiusIsNotOnIt) {
  // Two unit cylinders 2 - 1e-6 apart meet in two lines 2e-3 apart; a step of 0.05 put the second
  // line within a fifth of a step of the first.
  const std::vector<TracedCurve> lines = {line(Vec3(1, 1e-3, -1), Vec3(1, 1e-3, 1), 40)};
  EXPECT_FALSE(on_traced_curve(Vec3(1, -1e-3, 0.3), lines, 0.01, kTolerance));
  EXPECT_TRUE(on_traced_curve(Vec3(1, 1e-3, 0.3), lines, 0.01, kTolerance));
  // The torus R = 2, r = 1 cut 1e-6 below its top: circles of radius 2 -+ 1.4e-3.
  const std::vector<TracedCurve> outer = {circle(2 + 1.4142e-3, 200)};
  const double a = 0.77;
  EXPECT_FALSE(
      on_traced_curve(Vec3((2 - 1.4142e-3) * std::cos(a), (2 - 1.4142e-3) * std::sin(a), 0), outer, 0.02, kTolerance));
  EXPECT_TRUE(
      on_traced_curve(Vec3((2 + 1.4142e-3) * std::cos(a), (2 + 1.4142e-3) * std::sin(a), 0), outer, 0.02, kTolerance));
}

TEST(OnTracedCurve, UnknownTangentsFallBackToTheRadius) {
  TracedCurve c = line(Vec3(0, 0, 0), Vec3(1, 0, 0), 4);
  for (CurvePoint& p : c.points) p.t = Vec3::Zero();
  EXPECT_TRUE(on_traced_curve(Vec3(0.5, 1e-3, 0), {c}, 0.01, kTolerance));
  EXPECT_FALSE(on_traced_curve(Vec3(0.5, 0.1, 0), {c}, 0.01, kTolerance));
}

}  // namespace
}  // namespace ssimarch
