// The rotation-index condition of loop closure (march/closure_turning.hpp, thesis ch. 6 sec. 6.3)
// on tangent sequences of plane curves whose turning is known in closed form: a circle turns by
// 2 pi per revolution; an S (a half circle one way, a half circle the other) by 0; a half circle
// by pi; a straight line by 0.
#include <gtest/gtest.h>

#include <cmath>

#include "ssimarch/march/closure_turning.hpp"

namespace ssimarch {
namespace {

// Tangent of a circle traversed counter-clockwise (+1) or clockwise (-1, then a decreases), at
// angle a.
Vec2 circle_tangent(double a, int sense) { return Vec2(-std::sin(a), std::cos(a)) * sense; }

// Walks n steps of a circle of radius r from angle a0 to a1 (turning a1 - a0).
void walk_arc(ClosureTurning* c, double r, double a0, double a1, int n, int sense) {
  for (int i = 1; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n, b = a0 + (a1 - a0) * (i - 1) / n;
    c->step(circle_tangent(a, sense), r * Vec2(std::cos(a) - std::cos(b), std::sin(a) - std::sin(b)));
  }
}

constexpr double kTurningTolerance = 1e-12;  // rad: sums of about 100 atan2 values

TEST(ClosureTurning, AFullTurnClosesWithIndexOne) {
  ClosureTurning c(circle_tangent(0, 1), Vec2::Zero());
  // Up to the last point before the start (one step short), then the closing turn back to t0.
  walk_arc(&c, 1.0, 0.0, 2 * M_PI * 63 / 64, 63, 1);
  ASSERT_TRUE(c.known());
  EXPECT_NEAR(c.turning(), 2 * M_PI * 63 / 64, kTurningTolerance);
  EXPECT_TRUE(c.admits_closure());
}

TEST(ClosureTurning, AClockwiseFullTurnClosesToo) {
  ClosureTurning c(circle_tangent(0, -1), Vec2::Zero());
  walk_arc(&c, 1.0, 0.0, -2 * M_PI * 63 / 64, 63, -1);
  EXPECT_NEAR(c.turning(), -2 * M_PI * 63 / 64, kTurningTolerance);
  EXPECT_TRUE(c.admits_closure());
}

TEST(ClosureTurning, AStrandPassingByAfterHalfATurnDoesNotClose) {
  // A half circle brings the curve back next to its start (a waist, as in thesis Ex. 36 at
  // level 0.917) running the other way.
  ClosureTurning c(circle_tangent(0, 1), Vec2::Zero());
  walk_arc(&c, 1.0, 0.0, M_PI, 32, 1);
  EXPECT_NEAR(c.turning(), M_PI, kTurningTolerance);
  EXPECT_FALSE(c.admits_closure());
}

TEST(ClosureTurning, AParallelStrandWithoutATurnDoesNotClose) {
  // An S: half a circle one way, half a circle the other, ends running parallel to the start
  // (first order holds) having turned by 0, not by 2 pi: not the start's loop closing.
  ClosureTurning c(circle_tangent(0, 1), Vec2::Zero());
  walk_arc(&c, 1.0, 0.0, M_PI, 32, 1);
  walk_arc(&c, 1.0, 0.0, -M_PI, 32, -1);  // the next circle, tangent (0, -1) at its angle 0
  EXPECT_NEAR(c.turning(), 0.0, kTurningTolerance);
  EXPECT_FALSE(c.admits_closure());
}

TEST(ClosureTurning, ALoopIsNotClosedOnItsSecondRound) {
  ClosureTurning c(circle_tangent(0, 1), Vec2::Zero());
  walk_arc(&c, 1.0, 0.0, 2 * M_PI * 127 / 64, 127, 1);
  EXPECT_NEAR(c.turning(), 2 * M_PI * 127 / 64, kTurningTolerance);
  EXPECT_FALSE(c.admits_closure());
}

TEST(ClosureTurning, ACurveWindingOnceRoundAPeriodClosesWithIndexZero) {
  // v = sin(u) on a cylinder of period 2 pi in u: back at the start shifted by one period, with
  // the tangent turned back to where it was (turning 0).
  const double period = 2 * M_PI;
  const Vec2 t0 = Vec2(1, 1).normalized();
  ClosureTurning c(t0, Vec2(period, 0));
  const int n = 64;
  for (int i = 1; i < n; ++i) {
    const double u = period * i / n, du = period / n;
    c.step(Vec2(1, std::cos(u)).normalized(), Vec2(du, std::sin(u) - std::sin(u - du)));
  }
  c.step(t0, Vec2(period / n, std::sin(period) - std::sin(period * (n - 1) / n)));
  EXPECT_EQ(c.period_shift()[0], 1);
  EXPECT_NEAR(c.turning(), 0.0, kTurningTolerance);
  EXPECT_TRUE(c.admits_closure());
}

TEST(ClosureTurning, AWindingCurveWithAFullTurnDoesNotClose) {
  // The same shift by a period with a full turn on the way is not a simple curve on the cylinder.
  ClosureTurning c(circle_tangent(0, 1), Vec2(2 * M_PI, 0));
  walk_arc(&c, 1.0, 0.0, 2 * M_PI * 63 / 64, 63, 1);
  c.step(circle_tangent(2 * M_PI * 63 / 64, 1), Vec2(2 * M_PI, 0));  // a step that wraps
  EXPECT_EQ(c.period_shift()[0], 1);
  EXPECT_FALSE(c.admits_closure());
}

TEST(ClosureTurning, AFoldOfTheImageLosesTheTurningAndLeavesClosureToFirstOrder) {
  ClosureTurning c(Vec2(1, 0), Vec2::Zero());
  c.step(Vec2(std::cos(kRotationMaxChordTurn + 0.1), std::sin(kRotationMaxChordTurn + 0.1)), Vec2(0.1, 0));
  EXPECT_FALSE(c.known());
  EXPECT_TRUE(c.admits_closure());
  ClosureTurning none;  // no parameter plane (implicit-implicit)
  EXPECT_TRUE(none.admits_closure());
}

}  // namespace
}  // namespace ssimarch
