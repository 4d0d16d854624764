// `ssimarch singular` on curves of tangential contact (pipeline/singular_job.hpp, docs/singular.md):
// the hunt meets a contact curve at many of its points; they are counted, not listed, and the
// crossings of the contact curve with other branches are listed at their exact places.
#include "ssimarch/pipeline/singular_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ssimarch/io/scene.hpp"

namespace ssimarch {
namespace {

SingularJobResult singular_points_of(const std::string& file, const std::string& name) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/" + file);
  const std::vector<SingularJobResult> r = run_singular_job(scene, {name, 32});
  EXPECT_EQ(r.size(), 1u);
  return r.empty() ? SingularJobResult{} : r.front();
}

// Two tori tangent along a circle, crossed there by a closed curve that passes itself at a node
// (examples/occt_tori_tangent_circle.json; the crossings where cos v = -2/3 on the contact circle).
// Both forms of the pair: torus b implicit, and both tori parametric, where the node (-3, 0, 0) lies
// on torus a's outer equator; the grid's cells there are (R + r) / (R - r) = 3 times those of the
// domain's middle (the inner equator), and the hunt missed the node when it judged every start by
// the middle's cell (and listed each crossing with three half-branches along one direction of the
// contact curve).
class SingularJobBothForms : public ::testing::TestWithParam<const char*> {};

TEST_P(SingularJobBothForms, ContactCurvesAreCountedAndTheirCrossingsListed) {
  const SingularJobResult r = singular_points_of("occt_tori_tangent_circle.json", GetParam());
  EXPECT_GT(r.contact_points, 0);
  int crossings = 0, nodes = 0;
  for (const SingularAnalysis& p : r.points) {
    const Vec3& x = p.location.point;
    // Two half-branches along the contact curve and two across, or the node's four: rounding's
    // sign changes of h along the contact curve's double zero are no half-branches of their own.
    EXPECT_EQ(p.branches.size(), 4u) << x.transpose();
    if (p.kind.type == SingularType::kTangentLineCrossing) {
      ++crossings;
      EXPECT_NEAR(x.x(), 4.0 / 3.0, 1e-9);
      EXPECT_NEAR(x.y(), 0.0, 1e-9);
      EXPECT_NEAR(std::fabs(x.z()), std::sqrt(5.0) / 3.0, 1e-9);
    } else {
      EXPECT_EQ(p.kind.type, SingularType::kNode);
      ++nodes;
      EXPECT_NEAR((x - Vec3(-3, 0, 0)).norm(), 0.0, 1e-9);
    }
  }
  EXPECT_EQ(crossings, 2);
  EXPECT_EQ(nodes, 1);
}
INSTANTIATE_TEST_SUITE_P(ToriTangentCircle, SingularJobBothForms,
                         ::testing::Values("tori_tangent_circle", "tori_tangent_circle_pp"));

// A torus touching a cylinder along a circle, no other branch: nothing listed, the contact counted.
TEST(SingularJob, AContactCircleAloneListsNoPoint) {
  const SingularJobResult r = singular_points_of("occt_torus_cylinder_contact.json", "torus_cyl_contact");
  EXPECT_GT(r.contact_points, 0);
  EXPECT_TRUE(r.points.empty());
}

}  // namespace
}  // namespace ssimarch
