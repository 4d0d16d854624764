// Isolated boxes (start/isolated_box.hpp, docs/math/isolated_box.md): a box around an
// elliptic contact is decided with a radius of the order sqrt(rounding / curvature), in all
// three pair kinds; a loop deeper than the tolerance, a node and a tacnode never are.
#include "ssimarch/start/isolated_box.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "testing/matchers.hpp"
#include "testing/surface_pairs.hpp"
#include "ssimarch/surface/plane.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {
namespace {

using testing::implicit;
using testing::parametric;

using testing::plane_against;

VecX origin(int n) { return VecX::Zero(n); }

IntervalBox cube(int n, double w) { return IntervalBox(static_cast<std::size_t>(n), IntervalNumber(-w, w)); }

// The radius and depth limits of the certified search at scale 1 with the default tolerance.
constexpr double kRadius = 1e-6, kDepth = 1e-12;

TEST(IsolatedBox, EllipticContactIsDecidedWithARoundingSizedRadius) {
  // u^2 + 2 v^2 = 0: an isolated point; Q = h exactly, lambda = 2, rounding only at the point.
  const IsolatedBoxResult r =
      decide_isolated_box(plane_against("x^2+2*y^2"), origin(2), cube(2, 0.01), kRadius, kDepth);
  EXPECT_TRUE(r.decided);
  EXPECT_GT(r.lambda, 1.9);  // Hess h = diag(2, 4): the least eigenvalue 2, Gershgorin exact here
  EXPECT_LE(r.radius, 1e-7);
}

TEST(IsolatedBox, LoopsNodesAndTacnodesAreNot) {
  // u^2 + v^2 = 1e-10: a loop of radius 1e-5, 1e-10 deep, beyond the contact tolerance.
  const IsolatedBoxResult loop =
      decide_isolated_box(plane_against("x^2+y^2-1e-10"), origin(2), cube(2, 0.01), kRadius, kDepth);
  EXPECT_FALSE(loop.decided);
  EXPECT_GT(loop.depth, 0.9e-10);
  // A node (Hessian indefinite) and a tacnode (semidefinite): no convex Q exists.
  EXPECT_FALSE(decide_isolated_box(plane_against("x^2-y^2"), origin(2), cube(2, 0.01), kRadius, kDepth).decided);
  EXPECT_FALSE(decide_isolated_box(plane_against("y^2-x^4"), origin(2), cube(2, 0.01), kRadius, kDepth).decided);
  // A box that does not hold the located point proves nothing.
  const IntervalBox aside{{0.1, 0.2}, {-0.01, 0.01}};
  EXPECT_FALSE(decide_isolated_box(plane_against("x^2+y^2"), origin(2), aside, kRadius, kDepth).decided);
}

TEST(IsolatedBox, SpheresTouchingImplicitAndParametric) {
  // Unit spheres centred at the origin and at (2, 0, 0) touch at (1, 0, 0).
  const Sphere a(Vec3::Zero(), 1), b(Vec3(2, 0, 0), 1);
  const Problem ii(a, b, PairKind::kImplicitImplicit);
  VecX x(3);
  x << 1, 0, 0;
  IntervalBox box{{1 - 1e-3, 1 + 1e-3}, {-1e-3, 1e-3}, {-1e-3, 1e-3}};
  const IsolatedBoxResult r3 = decide_isolated_box(ii, x, box, kRadius, kDepth);
  EXPECT_TRUE(r3.decided);
  EXPECT_LE(r3.radius, 1e-7);
  // Parametric-parametric: the sphere's parameters (longitude, latitude) are 0 at (1, 0, 0) for
  // the first and (pi, 0) for the second (the point (-1, 0, 0) of the sphere about (2, 0, 0)).
  const Problem pp(a, b, PairKind::kParametricParametric);
  VecX y(4);
  y << 0, 0, std::numbers::pi, 0;
  ASSERT_THAT(pp.point(y), testing::IsNear(Vec3(1, 0, 0), 1e-15));
  const IntervalBox box4{
      {-1e-3, 1e-3}, {-1e-3, 1e-3}, {std::numbers::pi - 1e-3, std::numbers::pi + 1e-3}, {-1e-3, 1e-3}};
  const IsolatedBoxResult r4 = decide_isolated_box(pp, y, box4, kRadius, kDepth);
  EXPECT_TRUE(r4.decided);
  EXPECT_LE(r4.radius, 1e-7);
  // Overlapping by 1e-9 (centre at 2 - 1e-9): a circle of radius 3e-5, not an isolated point.
  const Problem over(a, Sphere(Vec3(2 - 1e-9, 0, 0), 1), PairKind::kImplicitImplicit);
  x << 1 - 0.5e-9, 0, 0;
  EXPECT_FALSE(decide_isolated_box(over, x, box, kRadius, kDepth).decided);
}

}  // namespace
}  // namespace ssimarch
