// The `mixed` geometry method at a singular point (issue 10): the located node of Viviani's
// curve and the geometry along each of its branches there, against the closed form
// c(s) = (sin s, -1 - cos s, 2 sin(s/2)) (R = 2): at the node s = 0 and s = 2 pi,
// c' = (1, 0, +-1), c'' = (0, 1, 0), c''' = (-1, 0, -+1/4): kappa = 1/2, tau = +-3/8.
#include <gtest/gtest.h>

#include <cmath>

#include "testing/matchers.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/branch_geometry.hpp"
#include "ssimarch/pipeline/point_geometry.hpp"

namespace ssimarch {
namespace {

TEST(BranchGeometry, MixedAtTheVivianiNodeFollowsEachBranch) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/thesis_pair2_cylinder_sphere.json");
  const Problem P = scene.problem(scene.intersections.at(0));
  for (const double sz : {1.0, -1.0}) {
    PointGeometryQuery q;
    q.at = Vec3(1e-3, -2, 1e-3 * sz);
    q.method = GeometryMethod::kMixed;
    q.toward = Vec3(1, 0, sz);
    const PointGeometry g = geometry_at_point(P, q);
    ASSERT_TRUE(g.x.has_value());
    EXPECT_THAT(g.point, testing::IsNear(Vec3(0, -2, 0), 1e-10));
    EXPECT_EQ(g.geometry.status, GeometryStatus::kOk);
    EXPECT_THAT(g.geometry.t, testing::IsNear(Vec3(1, 0, sz).normalized(), 1e-9));
    EXPECT_NEAR(g.geometry.kappa, 0.5, 1e-7);
    EXPECT_NEAR(g.geometry.tau, 0.375 * sz, 1e-6);
    EXPECT_NEAR(std::sin(g.geometry.theta), 0.0, 1e-9);
  }
}

TEST(BranchGeometry, CuspHasItsTangentAndInfiniteCurvature) {
  // The cardioid's cusp (thesis Ex. 20): one half-branch pair leaving along one tangent.
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/thesis_ex20_cardioid.json");
  const Problem P = scene.problem(scene.intersections.at(0));
  VecX x = VecX::Zero(P.dim());
  const auto g = singular_branch_geometry(P, x, nullptr, 1e-3);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->geometry.status, GeometryStatus::kSingular);
  EXPECT_NEAR(g->geometry.t.norm(), 1.0, 1e-12);
  EXPECT_TRUE(std::isinf(g->geometry.kappa));
}

}  // namespace
}  // namespace ssimarch
