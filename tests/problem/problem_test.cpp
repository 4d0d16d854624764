// Problem: H and its Jacobian for the three pair kinds, against central differences.
#include "ssimarch/problem/problem.hpp"

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "testing/surface_pairs.hpp"
#include "ssimarch/surface/sphere.hpp"

namespace ssimarch {
namespace {

void expect_jacobian_matches_differences(const Problem& P, const VecX& x) {
  Linearization L = P.linearize(x);
  const double h = 1e-6;
  for (int j = 0; j < P.dim(); ++j) {
    VecX a = x, b = x;
    a[j] += h;
    b[j] -= h;
    VecX d = (P.linearize(a).h - P.linearize(b).h) / (2 * h);
    // Implicit rows are normalised by |grad| at each point; the difference of the normalised
    // residual differs from the frozen-normalisation Jacobian by O(residual), small here.
    for (int i = 0; i < P.num_equations(); ++i) EXPECT_NEAR(L.jacobian(i, j), d[i], 1e-6) << i << "," << j;
  }
}

TEST(Problem, ParametricParametricResidualAndJacobian) {
  Problem P(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  EXPECT_EQ(P.dim(), 4);
  VecX x(4);
  x << 0.3, 0.0, 1.2, M_PI / 2 - 0.3;  // F1(s,0) = G1(4s, pi/2 - s)
  Linearization L = P.linearize(x);
  EXPECT_NEAR(L.h.norm(), 0.0, 1e-14);
  EXPECT_THAT(L.point, testing::IsNear(testing::c1(0.3), 1e-14));
  expect_jacobian_matches_differences(P, x);
}

TEST(Problem, ParametricImplicitDistanceIsInModelUnits) {
  Problem P(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
  VecX x(2);
  x << 0.0, 1.0;  // (1, -1, 1): |p| = sqrt 3, distance 2 - sqrt 3 = 0.268 from the sphere
  Linearization L = P.linearize(x);
  // First-order estimate |f|/|grad f| = 0.25/(sqrt(3)/2) = 0.2887 for f = (|p|^2 - 4)/4.
  EXPECT_NEAR(L.distance, 0.5 / std::sqrt(3.0), 1e-15);
  x << 0.0, std::sqrt(2.0);  // on Viviani's curve
  EXPECT_NEAR(P.linearize(x).distance, 0.0, 1e-15);
  expect_jacobian_matches_differences(P, x);
}

TEST(Problem, ImplicitImplicitAndPeriodicWrap) {
  Problem P(testing::sphere_g2_implicit(), testing::cylinder_f2_implicit(), PairKind::kImplicitImplicit);
  VecX x(3);
  x << 1.0, -1.0, std::sqrt(2.0);
  EXPECT_NEAR(P.linearize(x).distance, 0.0, 1e-15);
  expect_jacobian_matches_differences(P, x);

  Problem Q(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  VecX y(4);
  y << 7.0, 0.1, -1.0, 13.0;
  VecX w = Q.wrap(y);
  EXPECT_NEAR(w[0], 7.0 - 2 * M_PI, 1e-14);
  EXPECT_NEAR(w[1], 0.1, 0);
  EXPECT_NEAR(w[2], 2 * M_PI - 1.0, 1e-14);
  EXPECT_NEAR(w[3], 13.0 - 4 * M_PI, 1e-14);
  EXPECT_NEAR(Q.difference(w, y).norm(), 0.0, 1e-13);
  EXPECT_TRUE(Q.inside(y));
  y[1] = 0.6;
  EXPECT_FALSE(Q.inside(y));
}

TEST(Problem, RejectsSurfacesWithoutTheNeededForm) {
  EXPECT_THROW(Problem(testing::sphere_g2_implicit(), testing::cylinder_f2(), PairKind::kParametricImplicit), std::exception);
  EXPECT_THROW(Problem(testing::cylinder_f2(), testing::cylinder_f2(), PairKind::kImplicitImplicit), std::exception);
}

}  // namespace
}  // namespace ssimarch
