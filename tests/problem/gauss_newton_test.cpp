// The problem layer's solves on Viviani's curve (sphere radius 2, cylinder through its centre):
// Gauss-Newton, Newton with one unknown fixed, the shared convergence rule, and the curve jet's
// refusal of orders it does not hold.
#include "ssimarch/problem/gauss_newton.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "testing/surface_pairs.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {
namespace {

Problem viviani_problem() {
  return Problem(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
}

TEST(GaussNewton, ConvergesQuadraticallyOntoVivianisCurve) {
  const Problem P = viviani_problem();
  VecX guess(2);
  guess << 0.4, 1.3;  // near (u, v) = (s - pi/2, 2 sin(s/2)) for some s
  CorrectorResult r = gauss_newton(P, guess, CorrectorOptions{1e-12, 12});
  ASSERT_EQ(r.status, CorrectorStatus::kConverged);
  EXPECT_LE(P.linearize(r.x).distance, 1e-12);
  EXPECT_GE(r.iterations, 1);
  EXPECT_LE(r.iterations, 6);
  // The point lies on the sphere of radius 2 and on the cylinder x^2 + (y+1)^2 = 1.
  const Vec3 p = P.point(r.x);
  EXPECT_NEAR(p.norm(), 2.0, 1e-11);
  EXPECT_NEAR(std::hypot(p.x(), p.y() + 1), 1.0, 1e-12);
}

TEST(GaussNewton, SingularAtTheNode) {
  // At the node (0, -2, 0) of Viviani's curve J_H = 0: no update is defined.
  const Problem P = viviani_problem();
  VecX node(2);
  node << -M_PI / 2, 0.0;
  EXPECT_EQ(gauss_newton(P, node, CorrectorOptions{1e-30, 12}).status, CorrectorStatus::kSingular);
}

TEST(SolveWithFixedUnknown, LandsOnTheCurveWithThatUnknownExactly) {
  const Problem P = viviani_problem();
  VecX guess(2);
  guess << 0.5, 1.5;
  CorrectorResult r = solve_with_fixed_unknown(P, guess, 1, 1.6, CorrectorOptions{1e-12, 20});
  ASSERT_EQ(r.status, CorrectorStatus::kConverged);
  EXPECT_NEAR(r.x[1], 1.6, 1e-14);
  // z = v = 2 sin(s/2) = 1.6 on Viviani's curve: x = sin s with s = 2 asin(0.8) (or pi +- ...).
  const Vec3 p = P.point(r.x);
  EXPECT_NEAR(std::fabs(p.x()), std::fabs(std::sin(2 * std::asin(0.8))), 1e-11);
}

TEST(SolveOnPlane, LandsOnTheCurveOnThePlane) {
  // The plane 0.6 x + 0.8 z = 0.9 cuts Viviani's curve in isolated points; the one found lies on
  // the plane, the sphere and the cylinder (three equations, the independent check) to the
  // tolerance, after the polishing update (iterations >= 2).
  const Problem P = viviani_problem();
  const Vec3 normal(0.6, 0, 0.8);
  VecX guess(2);
  guess << 0.4, 1.3;
  const CorrectorResult r = solve_on_plane(P, guess, normal, 0.9, CorrectorOptions{1e-12, 20});
  ASSERT_EQ(r.status, CorrectorStatus::kConverged);
  EXPECT_GE(r.iterations, 2);
  const Vec3 p = P.point(r.x);
  EXPECT_NEAR(normal.dot(p), 0.9, 1e-14);
  EXPECT_NEAR(p.norm(), 2.0, 1e-12);
  EXPECT_NEAR(std::hypot(p.x(), p.y() + 1), 1.0, 1e-12);
}

TEST(ConstrainedNewton, ASingularSquareSystemIsSaidSo) {
  // The plane z = 0 at the node (0, -2, 0): J_H = 0 there, so [J_H; grad c] has rank 1.
  const Problem P = viviani_problem();
  VecX node(2);
  node << -M_PI / 2, 0.0;
  const CorrectorResult r =
      constrained_newton(P, node, SideCondition::plane(Vec3::UnitZ(), 0.0), CorrectorOptions{1e-30, 12});
  EXPECT_EQ(r.status, CorrectorStatus::kSingular);
}

TEST(ConvergenceRule, ConvergedBelowToleranceDivergingAfterTwoGrowths) {
  CorrectorOptions o{1e-6, 12};
  CorrectorResult r;
  ConvergenceRule rule(1.0);
  Linearization L;
  L.distance = 2.0;
  EXPECT_EQ(rule.judge(L, o, &r), ConvergenceRule::Verdict::kContinue);
  L.distance = 3.0;
  EXPECT_EQ(rule.judge(L, o, &r), ConvergenceRule::Verdict::kDiverging);
  EXPECT_EQ(r.linearizations, 2);
  ConvergenceRule fresh(1.0);
  L.distance = 1e-7;
  EXPECT_EQ(fresh.judge(L, o, &r), ConvergenceRule::Verdict::kConverged);
  EXPECT_EQ(r.status, CorrectorStatus::kConverged);
  L.distance = std::nan("");
  EXPECT_EQ(fresh.judge(L, o, &r), ConvergenceRule::Verdict::kDiverging);
}

TEST(CurveJet, OrdersOutsideTheSupportedRangeAreInputErrors) {
  const Problem P = viviani_problem();
  VecX x(2);
  x << 0.3, 2 * std::sin((0.3 + M_PI / 2) / 2);
  EXPECT_EQ(curve_jet_dynamic(P, x, kMaxCurveJetOrder).order, kMaxCurveJetOrder);
  EXPECT_THROW(curve_jet_dynamic(P, x, 0), InputError);
  EXPECT_THROW(curve_jet_dynamic(P, x, kMaxCurveJetOrder + 1), InputError);
  EXPECT_THROW(curve_jet<2>(P, VecX::Zero(3)), InputError);
}

}  // namespace
}  // namespace ssimarch
