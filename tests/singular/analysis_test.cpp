// The one entry point of singular-point analysis (singular/analysis.hpp): each status, the four
// steps agreeing with the steps called one by one, half-branches on demand. Viviani's node
// (0, -2, 0) for R = 2: a node (A1) with four half-branches whose tangents are +-(1, 0, +-1)/sqrt 2.
#include "ssimarch/singular/analysis.hpp"

#include <gtest/gtest.h>
#include "testing/matchers.hpp"

#include <cmath>

#include "singular/pairs.hpp"

namespace ssimarch {
namespace {

using testing::implicit_surface;
using testing::param;

Problem viviani_pi() {
  return Problem(param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true), implicit_surface("(x^2+y^2+z^2-4)/4"),
                 PairKind::kParametricImplicit);
}

VecX at(double u, double v) {
  VecX x(2);
  x << u, v;
  return x;
}

TEST(SingularAnalysis, VivianiNodeIsLocatedClassifiedAndHasFourHalfBranches) {
  const Problem P = viviani_pi();
  const SingularAnalysis a = analyse_singular_point(P, at(1.5 * M_PI + 0.05, 0.04));
  ASSERT_EQ(a.status, SingularAnalysisStatus::kAnalysed) << to_string(a.status);
  EXPECT_THAT(a.location.point, testing::IsNear(Vec3(0, -2, 0), 1e-10));
  EXPECT_EQ(a.kind.type, SingularType::kNode);
  EXPECT_EQ(a.kind.ak, "A1");
  ASSERT_EQ(a.branches.size(), 4u);
  for (const HalfBranch& b : a.branches) {
    // The tangents of Viviani's node: |x| = |z| = 1/sqrt 2, y = 0.
    EXPECT_NEAR(std::fabs(b.tangent_3d.x()), std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(std::fabs(b.tangent_3d.z()), std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(b.tangent_3d.y(), 0, 1e-6);
  }
}

TEST(SingularAnalysis, TheStepsAgreeWithTheStepsCalledOneByOne) {
  const Problem P = viviani_pi();
  const SingularLocation s = locate_singular_point(P, at(1.5 * M_PI - 0.03, -0.02));
  ASSERT_EQ(s.status, LocateStatus::kConverged);
  const LocalCurve c = local_curve(P, s.x);
  const Classification k = classify(c.h);
  const std::vector<HalfBranch> hb = half_branches(P, c, k);
  const SingularAnalysis a = analyse_singular_point(P, at(1.5 * M_PI - 0.03, -0.02));
  ASSERT_TRUE(a.analysed());
  EXPECT_EQ(a.location.x, s.x);
  EXPECT_EQ(a.kind.type, k.type);
  EXPECT_EQ(a.kind.milnor, k.milnor);
  ASSERT_EQ(a.branches.size(), hb.size());
  for (std::size_t i = 0; i < hb.size(); ++i) EXPECT_EQ(a.branches[i].tangent_3d, hb[i].tangent_3d);
}

TEST(SingularAnalysis, HalfBranchesOnlyWhenAskedAndAddedLater) {
  const Problem P = viviani_pi();
  SingularAnalysisOptions o;
  o.half_branches = false;
  SingularAnalysis a = analyse_singular_point(P, at(1.5 * M_PI, 0.01), o);
  ASSERT_TRUE(a.analysed());
  EXPECT_TRUE(a.branches.empty());
  with_half_branches(P, &a);
  EXPECT_EQ(a.branches.size(), 4u);
}

TEST(SingularAnalysis, ARegularPointOfTheCurveIsClassifiedRegular) {
  const Problem P = viviani_pi();
  // (0, 0, 2) = F(pi/2, 2) lies on Viviani's curve, far from its node: the surfaces cross there.
  SingularAnalysisOptions here;
  here.locate = false;
  const SingularAnalysis given = analyse_singular_point(P, at(M_PI / 2, 2.0), here);
  ASSERT_TRUE(given.analysed()) << to_string(given.status);
  EXPECT_EQ(given.kind.type, SingularType::kRegular);
  EXPECT_THAT(given.location.point, testing::IsNear(Vec3(0, 0, 2), 1e-15));
}

}  // namespace
}  // namespace ssimarch
