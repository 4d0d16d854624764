// Detection signals between consecutive points (Viviani's node, the near miss of Ex. 21) and the
// isolated-point hunt (oracle s003.ex18.all_singular; Ex. 16's isolated point; Ex. 21's nodes).
#include "ssimarch/singular/detection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "singular/pairs.hpp"
#include "testing/matchers.hpp"
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {
namespace {

Problem viviani_pi() {
  return Problem(testing::param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true),
                 testing::implicit_surface("(x^2+y^2+z^2-4)/4"), PairKind::kParametricImplicit);
}
Problem viviani_ii() {
  return Problem(testing::implicit_surface("(x^2+(y+1)^2-1)/2"), testing::implicit_surface("(x^2+y^2+z^2-4)/4"),
                 PairKind::kImplicitImplicit);
}
// Viviani's curve (sin s, -1 - cos s, 2 sin(s/2)) in the unknowns of each kind; node at s = 0.
VecX viviani_x(const Problem& pr, double s) {
  VecX x(pr.dim());
  if (pr.kind() == PairKind::kParametricImplicit)
    x << pr.wrap((VecX(2) << std::atan2(-std::cos(s), std::sin(s)), 2 * std::sin(s / 2)).finished());
  else
    x << std::sin(s), -1 - std::cos(s), 2 * std::sin(s / 2);
  return x;
}

TEST(Detection, OrientedTangentVanishesAtTheNodeAndIsTheTangentElsewhere) {
  for (const Problem& pr : {viviani_pi(), viviani_ii()}) {
    EXPECT_LE(oriented_tangent(pr, viviani_x(pr, 0.0)).norm(), 1e-14);
    const double s = 0.7;
    const Vec3 T = oriented_tangent(pr, viviani_x(pr, s));
    const Vec3 exact = Vec3(std::cos(s), std::sin(s), std::cos(s / 2)).normalized();
    EXPECT_NEAR(std::fabs(T.normalized().dot(exact)), 1.0, 1e-12);
  }
}

TEST(Detection, SteppingOverTheNodeFlipsTheOrientation) {
  for (const Problem& pr : {viviani_pi(), viviani_ii()}) {
    StepSignals over = step_signals(pr, viviani_x(pr, -0.05), viviani_x(pr, 0.06));
    EXPECT_TRUE(over.flipped);
    EXPECT_NEAR(over.tangent_cos, -1.0, 0.05);
    StepSignals before = step_signals(pr, viviani_x(pr, -0.3), viviani_x(pr, -0.2));
    EXPECT_FALSE(before.flipped);
    EXPECT_FALSE(before.suspect());
    StepSignals close = step_signals(pr, viviani_x(pr, -0.01), viviani_x(pr, -0.005));
    EXPECT_FALSE(close.flipped);
    EXPECT_TRUE(close.near_singular);  // sin theta ~ 0.005 < 0.01
    EXPECT_LT(close.sine_b, 0.01);
  }
}

TEST(Detection, NearMissDoesNotFlip) {
  // Ex. 21 at the printed level 0.917: the curve passes (1, +-0.0183) smoothly, on the hyperbola
  // v^2 - 3(u-1)^2 ~ 1/3000; a step of 0.01 across u = 1 turns by 74 degrees but does not flip.
  Problem pr = testing::graph_vs_plane_pi("u^6/6-5*u^4/4+2*u^2+v^2", "0.917");
  auto on_curve = [](double u) {  // v^2 = 0.917 - (u^6/6 - 5u^4/4 + 2u^2), upper arc
    return (VecX(2) << u, std::sqrt(0.917 - (std::pow(u, 6) / 6 - 5 * std::pow(u, 4) / 4 + 2 * u * u))).finished();
  };
  StepSignals s = step_signals(pr, on_curve(0.995), on_curve(1.005));
  EXPECT_FALSE(s.flipped);
  EXPECT_NEAR(s.tangent_cos, 0.28, 0.02);
}

std::vector<Vec2> hunt(const Problem& pr) {
  std::vector<Vec2> r;
  for (const auto& s : hunt_singular_points(pr)) r.emplace_back(s.x[0], s.x[1]);
  std::sort(r.begin(), r.end(), [](const Vec2& a, const Vec2& b) { return a[0] + 1e-6 * a[1] < b[0] + 1e-6 * b[1]; });
  return r;
}

TEST(Detection, HuntFindsEveryThesisSingularPoint) {
  // Ex. 18: exactly (0,0) (tacnode) and (0,1) (node) (oracle s003.ex18.all_singular).
  std::vector<Vec2> ex18 = hunt(testing::graph_vs_plane_pi("0.2*u^4+0.1*v^4-0.3*u^2*v+0.1*v^2-0.2*v^3"));
  ASSERT_EQ(ex18.size(), 2u);
  std::sort(ex18.begin(), ex18.end(), [](const Vec2& a, const Vec2& b) { return a[1] < b[1]; });
  EXPECT_LE(ex18[0].norm(), 1e-12);
  EXPECT_THAT(ex18[1], testing::IsNear(Vec2(0, 1), 1e-12));
  // Ex. 16: the isolated point at the origin, which no trace passes near.
  std::vector<Vec2> ex16 = hunt(testing::graph_vs_plane_pi("3*u^4/4+u^3+u^2/4+7*u^2*v^2/2+u*v^2+v^4"));
  ASSERT_EQ(ex16.size(), 1u);
  EXPECT_LE(ex16[0].norm(), 1e-10);
  // Ex. 21 at 11/12: the two nodes (+-1, 0) (oracle s003.ex21.singular_points); none at 0.917.
  std::vector<Vec2> ex21 = hunt(testing::graph_vs_plane_pi("u^6/6-5*u^4/4+2*u^2+v^2", "11/12"));
  ASSERT_EQ(ex21.size(), 2u);
  EXPECT_THAT(ex21[0], testing::IsNear(Vec2(-1, 0), 1e-12));
  EXPECT_THAT(ex21[1], testing::IsNear(Vec2(1, 0), 1e-12));
  EXPECT_TRUE(hunt(testing::graph_vs_plane_pi("u^6/6-5*u^4/4+2*u^2+v^2", "0.917")).empty());
}

TEST(Detection, HuntFindsVivianisNodeForEveryPairKind) {
  Problem pp(testing::param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true),
             testing::param("2*sin(u)", "2*cos(u)*cos(v)", "2*cos(u)*sin(v)", {-M_PI / 2, M_PI / 2}, {0, 2 * M_PI}, false, true),
             PairKind::kParametricParametric);
  for (const Problem& pr : {viviani_pi(), viviani_ii(), pp}) {
    std::vector<SingularLocation> s = hunt_singular_points(pr);
    ASSERT_EQ(s.size(), 1u) << to_string(pr.kind());
    EXPECT_THAT(s[0].point, testing::IsNear(Vec3(0, -2, 0), 1e-12));
  }
  HuntOptions bad;
  bad.grid = 2;
  EXPECT_THROW(hunt_singular_points(viviani_pi(), bad), InputError);
}

}  // namespace
}  // namespace ssimarch
