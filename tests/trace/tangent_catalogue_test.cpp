// The catalogue of tangent configurations (issue 10 items 5 and 7, issue 11 items 1 and 6),
// each traced with default options in the four forms (implicit / parametric for each surface:
// ii, pi, ip, pp; scenes in tests/trace/data/tangent), against closed forms:
//  * villarceau: the plane through the torus (R = 2, r = 1) centre at the slope r / sqrt(R^2 - r^2)
//    touches it at (±1.5, 0, ±sqrt(3)/2) (two nodes) and cuts two Villarceau circles of radius R;
//  * lemniscate: the plane x = R - r touches the torus at its inner equator; the spiric section
//    (y^2 + z^2)^2 = 8 (y^2 - z^2) is Bernoulli's lemniscate of half-width a = 2 sqrt 2, length
//    2 varpi a (varpi = 2.62205755429211981046, the lemniscate constant), node (1, 0, 0);
//  * torus_top: the plane z = r touches the torus along the circle of radius R (tangential contact);
//  * isolated tangencies (two spheres touching outside and inside, a sphere on a cylinder, the
//    plane x = R + r on the torus' outer equator): one isolated point, no curve, certified;
//  * cone_plane_line: a plane touching a double cone along the generator through its apex: the
//    contact line, length 4 sqrt 2 over the cone's range, and no singular point off the apex;
//  * two unit spheres with centres d apart: the circle of radius sqrt(1 - d^2 / 4) for overlaps
//    2 - d = 1e-9, 1e-6, 1e-3; nothing, certified, for the gap d - 2 = 1e-9.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "testing/matchers.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

// Every intersection of the scene (or those whose name ends in one of `forms`), traced.
void each_form(const std::string& stem, const std::function<void(const IntersectionRun&)>& check,
               const std::vector<std::string>& forms = {"_ii", "_pi", "_ip", "_pp"}) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/tests/trace/data/tangent/" + stem + ".json");
  int traced = 0;
  for (const IntersectionSpec& spec : scene.intersections) {
    bool wanted = false;
    for (const std::string& f : forms) wanted = wanted || spec.name.ends_with(f);
    if (!wanted) continue;
    SCOPED_TRACE(spec.name);
    check(run_intersection(scene, spec));
    ++traced;
  }
  EXPECT_EQ(traced, static_cast<int>(forms.size())) << stem;
}

// The singular point of `type` nearest to p, or nullptr.
const SingularPointReport* nearest(const TraceResult& r, const Vec3& p, const std::string& type) {
  const SingularPointReport* best = nullptr;
  for (const SingularPointReport& s : r.singular_points)
    if (to_string(s.type) == type && (!best || (s.p - p).norm() < (best->p - p).norm())) best = &s;
  return best;
}

// Points are located to 1e-12 and more (docs/singular.md); 1e-10 leaves room for rounding in the
// parametrisations' trigonometry.
constexpr double kPointTolerance = 1e-10;

TEST(TangentCatalogue, VillarceauTwoCirclesThroughTwoNodes) {
  each_form("villarceau", [](const IntersectionRun& run) {
    const TraceResult& r = run.result;
    ASSERT_EQ(r.curves.size(), 2u);
    for (const TracedCurve& c : r.curves) {
      EXPECT_TRUE(c.closed);
      // Circles: the circular-arc length estimate is exact on them up to the points' tolerance.
      EXPECT_NEAR(c.length, 4 * kPi, 1e-8);
    }
    ASSERT_EQ(r.singular_points.size(), 2u);
    for (double s : {1.0, -1.0}) {
      const Vec3 node(1.5 * s, 0, s * std::sqrt(3.0) / 2);
      const SingularPointReport* n = nearest(r, node, "node");
      ASSERT_NE(n, nullptr);
      EXPECT_THAT(n->p, testing::IsNear(node, kPointTolerance));
    }
    EXPECT_TRUE(run_complete(run));
  });
}

TEST(TangentCatalogue, LemniscateOneClosedCurveThroughItsNode) {
  // 2 varpi a with varpi = Gamma(1/4)^2 / (2 sqrt(2 pi)).
  const double varpi = std::pow(std::tgamma(0.25), 2) / (2 * std::sqrt(2 * kPi));
  const double length = 2 * varpi * 2 * std::sqrt(2.0);
  each_form("lemniscate", [&](const IntersectionRun& run) {
    const TraceResult& r = run.result;
    ASSERT_EQ(r.curves.size(), 1u);
    EXPECT_TRUE(r.curves[0].closed);
    // The circular-arc length estimate falls short by kappa'^2 h^5 / 1440 per segment of length h
    // (docs/marching.md): on the lemniscate kappa = 3 r / a^2, so |kappa'| <= 3 / a^2, and next to
    // the node (kappa = 0) the chordal rule takes its longest steps, h <= 0.25 in all four forms;
    // the sum is at most kappa'^2 h^4 L / 1440 = 3.8e-7 L (measured: 2e-8 .. 7e-8 L).
    EXPECT_THAT(r.curves[0], testing::HasLength(length, 3.8e-7 * length));
    const SingularPointReport* n = nearest(r, Vec3(1, 0, 0), "node");
    ASSERT_NE(n, nullptr);
    EXPECT_THAT(n->p, testing::IsNear(Vec3(1, 0, 0), kPointTolerance));
    EXPECT_TRUE(run_complete(run));
  });
}

TEST(TangentCatalogue, TorusTopContactCircle) {
  each_form("torus_top",
            [](const IntersectionRun& run) {
              const TraceResult& r = run.result;
              ASSERT_EQ(r.curves.size(), 1u);
              EXPECT_TRUE(r.curves[0].closed);
              EXPECT_TRUE(r.curves[0].tangential_contact);
              EXPECT_THAT(r.curves[0], testing::HasLength(4 * kPi, 1e-8));
              EXPECT_TRUE(run_complete(run));
            },
            {"_pi", "_ip"});
}

// One isolated point at p, no curve, the start-point search certified (the cluster of undecided
// boxes around the point decided by a convex box, docs/math/isolated_box.md), complete.
void expect_isolated(const std::string& stem, const Vec3& p) {
  each_form(stem, [&](const IntersectionRun& run) {
    const TraceResult& r = run.result;
    EXPECT_TRUE(r.curves.empty());
    ASSERT_EQ(r.isolated_points.size(), 1u);
    // An isolated tangency is located to sqrt(rounding) along the contact at worst.
    EXPECT_THAT(r.isolated_points[0].p, testing::IsNear(p, 1e-7));
    EXPECT_TRUE(r.start_search.certified) << r.start_search.note;
    EXPECT_TRUE(r.start_search.uncertain_regions.empty());
    // Where the search ran (not a closed form), it is the convex box that certified the point.
    if (r.start_search.method == StartSearchMethod::kCertified) {
      EXPECT_NE(r.start_search.note.find("decided by convex boxes"), std::string::npos) << r.start_search.note;
    }
    EXPECT_TRUE(run_complete(run));
  });
}

TEST(TangentCatalogue, SpheresTouchingOutside) { expect_isolated("spheres_external", Vec3(1, 0, 0)); }
TEST(TangentCatalogue, SpheresTouchingInside) { expect_isolated("spheres_internal", Vec3(1, 0, 0)); }
TEST(TangentCatalogue, SphereOnCylinder) { expect_isolated("sphere_cyl_tangent", Vec3(1, 0, 0)); }
TEST(TangentCatalogue, PlaneOnTorusOuterEquator) { expect_isolated("torus_outer_pt", Vec3(3, 0, 0)); }

TEST(TangentCatalogue, ConeTouchedAlongAGeneratorThroughItsApex) {
  each_form("cone_plane_line", [](const IntersectionRun& run) {
    const TraceResult& r = run.result;
    ASSERT_EQ(r.curves.size(), 1u);
    EXPECT_TRUE(r.curves[0].tangential_contact);
    EXPECT_THAT(r.curves[0], testing::HasLength(4 * std::sqrt(2.0), 1e-8));
    // The apex is a singular point of the cone, not of the intersection's contact line: nothing
    // is reported off it (a sign change of lambda through its pole there is no crossing).
    for (const SingularPointReport& s : r.singular_points) EXPECT_LT(s.p.norm(), kPointTolerance) << to_string(s.type);
  });
}

TEST(TangentCatalogue, SpheresOverlappingSlightlyCutACircle) {
  for (const char* stem : {"sph_ov_1e-9", "sph_ov_1e-6", "sph_ov_1e-3"}) {
    SCOPED_TRACE(stem);
    const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/tests/trace/data/tangent/" + stem + ".json");
    const double d = scene.surfaces.at("b").get_if<Sphere>()->center().x();
    const double radius = std::sqrt(1 - d * d / 4);
    each_form(stem,
              [&](const IntersectionRun& run) {
                const TraceResult& r = run.result;
                ASSERT_EQ(r.curves.size(), 1u);
                EXPECT_TRUE(r.curves[0].closed);
                // A point of the circle is known to the point tolerance over sin(theta) ~ radius (the
                // normals' angle): relative 1e-6 of the length for the 1e-9 overlap, far less otherwise.
                EXPECT_THAT(r.curves[0], testing::HasLength(2 * kPi * radius, 1e-6 * 2 * kPi * radius));
                EXPECT_TRUE(run_complete(run));
              },
              {"_ii", "_pi", "_ip"});
  }
}

TEST(TangentCatalogue, SpheresAGapApartGiveNothingCertified) {
  each_form("sph_gap_p1e-9", [](const IntersectionRun& run) {
    EXPECT_TRUE(run.result.curves.empty());
    EXPECT_TRUE(run.result.isolated_points.empty());
    EXPECT_TRUE(run.result.start_search.certified);
    EXPECT_TRUE(run_complete(run));
  });
}

}  // namespace
}  // namespace ssimarch
