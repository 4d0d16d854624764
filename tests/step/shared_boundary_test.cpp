// Faces of one solid meet only along the edges and at the vertices they share (pipeline/
// shared_boundary.hpp; docs/cad.md, "Faces of one solid"). Model: tests/step/data/solids.step
// (make_trim_models.py): the octahedron |x - 5| + |y| + |z| <= 1, one face per octant, whose 28
// pairs are 12 with a shared edge (a segment of length sqrt 2), 12 with one shared vertex only and
// 4 opposite pairs with nothing in common; and a puck split into two half cylinders (tangent to
// each other along two lines of length 1) with a bottom and a top (half circles, length pi).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/step/reader.hpp"
#include "testing/matchers.hpp"

namespace ssimarch {
namespace {

const std::filesystem::path kModel = std::filesystem::path(SSIMARCH_SOURCE_DIR) / "tests/step/data/solids.step";

IntersectionRun run_pair(int a, int b, bool topology = true) {
  const StepModel model = StepModel::read(kModel);
  nlohmann::json scene = step_faces_scene_json(kModel, model, {a, b});
  if (!topology) scene["intersections"][0]["options"] = {{"solid_topology", false}};
  const Scene s = parse_scene(scene.dump(), "solids.json");
  return run_intersection(s, s.intersections.at(0));
}

// Octahedron face k (1-8) is the octant of signs (x - 5, y, z) = bits of k - 1, 0: -, 1: +.
Vec3 signs_of(int face) {
  const int b = face - 1;
  return {(b & 4) ? 1.0 : -1.0, (b & 2) ? 1.0 : -1.0, (b & 1) ? 1.0 : -1.0};
}

// Every point of a curve on both faces' planes and on the segment between the shared vertices;
// its unknowns give back its point.
void expect_on_edge(const IntersectionRun& r, const TracedCurve& c, const Vec3& a, const Vec3& b) {
  for (const CurvePoint& q : c.points) {
    const Vec3 d = b - a;
    const double t = (q.p - a).dot(d) / d.squaredNorm();
    EXPECT_GE(t, -1e-15);
    EXPECT_LE(t, 1 + 1e-15);
    EXPECT_THAT(q.p, testing::IsNear(Vec3(a + t * d), 1e-15));
    EXPECT_THAT(r.problem.point(q.x), testing::IsNear(q.p, 1e-14));
  }
}

TEST(SharedBoundary, TheOctahedronsFacesMeetAtTheirEdgesAndVertices) {
  const Vec3 centre(5, 0, 0);
  int edges = 0, vertices = 0, apart = 0;
  for (int a = 1; a <= 8; ++a)
    for (int b = a + 1; b <= 8; ++b) {
      const IntersectionRun r = run_pair(a, b);
      const std::string pair = std::to_string(a) + "-" + std::to_string(b);
      EXPECT_EQ(r.result.start_search.method, StartSearchMethod::kSharedBoundary) << pair;
      EXPECT_TRUE(r.result.start_search.certified) << pair;
      const Vec3 sa = signs_of(a), sb = signs_of(b);
      std::vector<int> same;
      for (int k = 0; k < 3; ++k)
        if (sa[k] == sb[k]) same.push_back(k);
      auto vertex = [&](int k) { return Vec3(centre + sa[k] * Vec3::Unit(k)); };
      if (same.size() == 2) {  // one edge, between the vertices on the two shared axes
        ++edges;
        ASSERT_EQ(r.result.curves.size(), 1u) << pair;
        EXPECT_TRUE(r.result.isolated_points.empty()) << pair;
        const TracedCurve& c = r.result.curves[0];
        EXPECT_FALSE(c.closed);
        EXPECT_FALSE(c.tangential_contact);
        EXPECT_NEAR(c.length, std::sqrt(2.0), 1e-14) << pair;
        EXPECT_EQ(c.start_end, Termination::kLeftDomain);
        expect_on_edge(r, c, vertex(same[0]), vertex(same[1]));
      } else if (same.size() == 1) {  // only the vertex on the shared axis
        ++vertices;
        EXPECT_TRUE(r.result.curves.empty()) << pair;
        ASSERT_EQ(r.result.isolated_points.size(), 1u) << pair;
        EXPECT_THAT(r.result.isolated_points[0].p, testing::IsNear(vertex(same[0]), 1e-15)) << pair;
      } else {
        ++apart;
        EXPECT_TRUE(r.result.curves.empty()) << pair;
        EXPECT_TRUE(r.result.isolated_points.empty()) << pair;
      }
    }
  EXPECT_EQ(edges, 12);
  EXPECT_EQ(vertices, 12);
  EXPECT_EQ(apart, 4);
}

TEST(SharedBoundary, HalfCylindersTouchAlongTheirSeamsAndMeetTheDiscsInHalfCircles) {
  const IntersectionRun halves = run_pair(9, 10);
  ASSERT_EQ(halves.result.curves.size(), 2u);
  for (const TracedCurve& c : halves.result.curves) {
    EXPECT_NEAR(c.length, 1.0, 1e-15);
    EXPECT_TRUE(c.tangential_contact);  // one cylinder: the normals agree along the seams
    EXPECT_NEAR(std::abs(c.points.front().p.x()), 1.0, 1e-15);
    EXPECT_NEAR(c.points.front().p.y(), 0.0, 1e-15);
  }
  for (const auto& [half, disc, z] : {std::tuple{9, 11, 0.0}, std::tuple{9, 12, 1.0}, std::tuple{10, 11, 0.0}}) {
    const IntersectionRun r = run_pair(half, disc);
    ASSERT_EQ(r.result.curves.size(), 1u) << half << "-" << disc;
    const TracedCurve& c = r.result.curves[0];
    EXPECT_FALSE(c.closed);
    EXPECT_FALSE(c.tangential_contact);
    EXPECT_NEAR(c.length, std::numbers::pi, 1e-13) << half << "-" << disc;
    const double side = half == 9 ? 1.0 : -1.0;  // face 9 is y >= 0, face 10 y <= 0
    for (const CurvePoint& q : c.points) {
      EXPECT_NEAR(std::hypot(q.p.x(), q.p.y()), 1.0, 1e-15);
      EXPECT_NEAR(q.p.z(), z, 1e-15);
      EXPECT_GE(side * q.p.y(), -1e-15);
      EXPECT_THAT(r.problem.point(q.x), testing::IsNear(q.p, 1e-14));
    }
    // Sampled as a closed form's conics are: within the deviation of the arc.
    for (std::size_t k = 1; k < c.points.size(); ++k) {
      const Vec3 mid = 0.5 * (c.points[k - 1].p + c.points[k].p);
      EXPECT_LE(1.0 - std::hypot(mid.x(), mid.y()), r.used.options.deviation * (1 + 1e-9));
    }
  }
}

TEST(SharedBoundary, OnlyFacesOfOneSolidOccurrenceAndOnlyWhenAsked) {
  // Switched off, the pair is traced (and here the edge's curve is cut by the loops).
  EXPECT_NE(run_pair(1, 2, false).result.start_search.method, StartSearchMethod::kSharedBoundary);
  // Faces of two solids, and one part placed twice, are two solids.
  const StepModel model = StepModel::read(kModel);
  const auto octa = model.face_region(model.face(1, "t").entity), puck = model.face_region(model.face(9, "t").entity);
  ASSERT_TRUE(octa && puck);
  EXPECT_FALSE(octa->solid().empty());
  EXPECT_NE(octa->solid(), puck->solid());
  const StepModel rods =
      StepModel::read(std::filesystem::path(SSIMARCH_SOURCE_DIR) / "tests/step/data/rod_assembly.step");
  const StepFace &rod1 = rods.face(1, "t"), &rod3 = rods.face(3, "t"), &plate = rods.face(4, "t");
  ASSERT_EQ(rod1.entity, rod3.entity);
  EXPECT_NE(rods.face_region(rod1.entity, rod1.placement)->solid(),
            rods.face_region(rod3.entity, rod3.placement)->solid());
  EXPECT_EQ(rods.face_region(rod1.entity, rod1.placement)->solid(),
            rods.face_region(rod1.entity, rod1.placement)->solid());
  EXPECT_TRUE(rods.face_region(plate.entity, plate.placement)->solid().empty());  // an open shell bounds no solid
}

// A solid whose shell cannot be read bounds nothing: its faces are read and traced as any others.
TEST(SharedBoundary, AnUnreadableShellGivesItsFacesNoSolid) {
  std::ifstream in(kModel);
  std::stringstream text;
  text << in.rdbuf();
  std::string t = text.str();
  const std::size_t at = t.find("CLOSED_SHELL('',(");
  ASSERT_NE(at, std::string::npos);
  t.replace(at, 17, "CLOSED_SHELL('',#1,(");  // cfs_faces is no list now
  const StepModel m(parse_step(t, "solids.step"));
  ASSERT_EQ(m.faces().size(), 12u);
  EXPECT_TRUE(m.face_region(m.face(1, "t").entity)->solid().empty());   // the octahedron's shell
  EXPECT_FALSE(m.face_region(m.face(9, "t").entity)->solid().empty());  // the puck's
}

// The exact derivative of a rational B-spline edge (the half circles of half_cylinder_nurbs.step,
// a double knot at the middle of each, where the speed jumps) against central differences of its
// points away from the knot.
TEST(SharedBoundary, RationalSplineEdgesHaveExactDerivatives) {
  const StepModel m =
      StepModel::read(std::filesystem::path(SSIMARCH_SOURCE_DIR) / "tests/step/data/half_cylinder_nurbs.step");
  const auto region = m.face_region(m.face(1, "t").entity);
  ASSERT_TRUE(region);
  int checked = 0;
  for (int i = 0; i < region->boundary_curves(); ++i) {
    const auto [lo, hi] = region->boundary_range(i);
    for (double t : {0.1, 0.37, 0.62, 0.81}) {
      const double s = lo + t * (hi - lo), h = 1e-5 * (hi - lo);
      const Vec3 fd = (region->boundary_point(i, s + h) - region->boundary_point(i, s - h)) / (2 * h);
      EXPECT_THAT(region->boundary_derivative(i, s), testing::IsNear(fd, 1e-8 * fd.norm())) << i << " " << t;
      ++checked;
    }
  }
  EXPECT_GE(checked, 16);
}

}  // namespace
}  // namespace ssimarch
