// Correctors on their own: Newton (Moore-Penrose) and seed 000's projection corrector, for every
// pair kind, with their statuses.
#include "ssimarch/march/corrector.hpp"

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "testing/surface_pairs.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"

namespace ssimarch {
namespace {

struct Case {
  Problem problem;
  VecX on_curve;  // unknowns of a point of the curve
  VecX offset;    // a direction to perturb them in
};

std::vector<Case> cases() {
  std::vector<Case> r;
  {  // torus curve C1(0.3), parametric-parametric
    VecX x(4), d(4);
    x << 0.3, 0.0, 1.2, M_PI / 2 - 0.3;
    d << 0.3, -1.0, 0.5, 0.7;
    r.push_back({Problem(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric), x, d});
  }
  {  // the same curve, parametric-implicit
    VecX x(2), d(2);
    x << 0.3, 0.0;
    d << 0.2, 1.0;
    r.push_back({Problem(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit), x, d});
  }
  {  // Viviani at s = 0.7, implicit-implicit
    VecX x = testing::viviani(0.7), d(3);
    d << 0.3, -0.8, 0.5;
    r.push_back({Problem(testing::sphere_g2_implicit(), testing::cylinder_f2_implicit(), PairKind::kImplicitImplicit), x, d});
  }
  return r;
}

TEST(Corrector, BothConvergeOnEveryPairKindAndCountTheirWork) {
  CorrectorOptions o{1e-12, 12};
  for (const Case& c : cases()) {
    for (double size : {1e-2, 1e-4}) {
      VecX guess = c.on_curve + size * c.offset.normalized();
      for (int which = 0; which < 2; ++which) {
        AnyCorrector corr = which == 0 ? AnyCorrector(NewtonCorrector{}) : AnyCorrector(TangentPlaneProjection{});
        CorrectorResult r = correct(corr, c.problem, guess, o);
        SCOPED_TRACE(std::string(to_string(c.problem.kind())) + (which == 0 ? " newton" : " projection") + " size " +
                     std::to_string(size));
        ASSERT_EQ(r.status, CorrectorStatus::kConverged);
        Linearization L = c.problem.linearize(r.x);
        EXPECT_LE(L.distance, 1e-12);
        EXPECT_NEAR(r.distance, L.distance, 1e-15);
        // Landed near the point it started from (no jump along or off the curve).
        EXPECT_THAT(L.point, testing::IsNear(c.problem.point(c.on_curve), 5 * size));
        // Quadratic convergence: few iterations, fewer from the closer guess.
        EXPECT_LE(r.iterations, size > 1e-3 ? 5 : 3);
        EXPECT_GE(r.linearizations, r.iterations);
        EXPECT_GE(r.evaluations[0], r.linearizations);
        EXPECT_GE(r.evaluations[1], r.linearizations);
        if (which == 0) {
          EXPECT_EQ(r.evaluations[0], r.linearizations);
          EXPECT_EQ(r.evaluations[1], r.linearizations);
        }
      }
    }
  }
}

TEST(Corrector, ProjectionLandsWhereTheSeedSays) {
  // From a point P0 off a circle of two planes' intersection the projection corrector is exact in
  // one round: plane z = 0 and plane y = 0 meet in the x axis; feet and midpoint are P0's foot.
  Problem P(testing::implicit("z", Box{{-2, 2}, {-2, 2}, {-2, 2}}), testing::implicit("y", Box{{-2, 2}, {-2, 2}, {-2, 2}}),
            PairKind::kImplicitImplicit);
  CorrectorResult r = TangentPlaneProjection{}.correct(P, Vec3(0.3, 0.2, -0.1), CorrectorOptions{1e-12, 12});
  ASSERT_EQ(r.status, CorrectorStatus::kConverged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_THAT(r.x, testing::IsNear(Vec3(0.3, 0, 0), 1e-15));
}

TEST(Corrector, SingularAndDivergedAreReported) {
  // Viviani's node (0,-2,0): sphere and cylinder are tangent there.
  Problem P(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
  VecX node(2);
  node << -M_PI / 2, 0.0;
  EXPECT_EQ(NewtonCorrector{}.correct(P, node, CorrectorOptions{1e-12, 12}).status, CorrectorStatus::kSingular);
  EXPECT_EQ(TangentPlaneProjection{}.correct(P, node, CorrectorOptions{1e-12, 12}).status, CorrectorStatus::kSingular);
  // One update is not enough from 0.01 away: diverged after exactly max_iterations.
  for (const Case& c : cases()) {
    VecX guess = c.on_curve + 1e-2 * c.offset.normalized();
    for (const AnyCorrector& corr : {AnyCorrector(NewtonCorrector{}), AnyCorrector(TangentPlaneProjection{})}) {
      CorrectorResult r = correct(corr, c.problem, guess, CorrectorOptions{1e-12, 1});
      EXPECT_EQ(r.status, CorrectorStatus::kDiverged);
      EXPECT_EQ(r.iterations, 1);
    }
  }
  // Two disjoint spheres: no curve to converge to.
  Problem apart(testing::implicit("x^2+y^2+z^2-1", Box{{-9, 9}, {-9, 9}, {-9, 9}}),
                testing::implicit("(x-5)^2+y^2+z^2-1", Box{{-9, 9}, {-9, 9}, {-9, 9}}), PairKind::kImplicitImplicit);
  for (const AnyCorrector& corr : {AnyCorrector(NewtonCorrector{}), AnyCorrector(TangentPlaneProjection{})}) {
    CorrectorResult r = correct(corr, apart, Vec3(2.5, 1.0, 0.3), CorrectorOptions{1e-12, 30});
    EXPECT_NE(r.status, CorrectorStatus::kConverged);
    EXPECT_LE(r.iterations, 30);
  }
}

}  // namespace
}  // namespace ssimarch
