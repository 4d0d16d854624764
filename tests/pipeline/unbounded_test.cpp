// Unbounded primitives (surface/unbounded.hpp; issue 29): a plane, cylinder, cone or paraboloid
// without its extent is the whole surface, so a default never cuts the intersection. Each case
// against its closed form, with the closed form on (the analytic answer) and off (the tracer).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/surface/unbounded.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLength = 1e-7;  // relative: the traced lengths (chordal step) are within 1e-9

const char* kScene = R"json({
  "surfaces": {"sphere": {"sphere": {"center": [0,0,0], "radius": 2}},
               "plane": {"plane": {"point": [0,0,1], "normal": [0,0,1]}},
               "coaxial": {"cylinder": {"point": [0,0,0], "axis": [0,0,1], "radius": 1}},
               "viviani": {"cylinder": {"point": [0,-1,0], "axis": [0,0,1], "radius": 1}},
               "cone": {"cone": {"apex": [0,0,0], "axis": [0,0,1], "half_angle": "pi/4"}},
               "bowl": {"paraboloid": {"vertex": [0,0,0], "axis": [0,0,1], "focal_length": 0.25}},
               "high": {"plane": {"point": [0,0,2], "normal": [0,0,1]}},
               "cx": {"cylinder": {"point": [0,0,0], "axis": [1,0,0], "radius": 1}},
               "cy": {"cylinder": {"point": [0,0,0], "axis": [0,1,0], "radius": 1}}},
  "intersections": [
    {"name": "sphere_plane", "surfaces": ["sphere", "plane"]},
    {"name": "sphere_coaxial", "surfaces": ["sphere", "coaxial"]},
    {"name": "viviani", "surfaces": ["sphere", "viviani"]},
    {"name": "sphere_cone", "surfaces": ["sphere", "cone"]},
    {"name": "bowl_plane", "surfaces": ["bowl", "high"]},
    {"name": "two_unbounded_cylinders", "surfaces": ["cx", "cy"]}
  ]})json";

struct Expected {
  const char* name;
  int curves;
  double length;
};

double total_length(const IntersectionRun& r) {
  double l = 0;
  for (const TracedCurve& c : r.result.curves) l += c.length;
  return l;
}

TEST(Unbounded, ADefaultExtentNeverCutsTheIntersection) {
  const Scene scene = parse_scene(kScene, "unbounded.json");
  // Viviani's curve (sphere radius 2, cylinder radius 1 through the centre): 15.2807911561;
  // the two unit cylinders: two ellipses of semi-axes sqrt 2 and 1, 7.64039557805 each.
  const Expected cases[] = {{"sphere_plane", 1, 2 * kPi * std::sqrt(3.0)},
                            {"sphere_coaxial", 2, 2 * 2 * kPi},
                            {"viviani", 1, 15.2807911561},
                            {"sphere_cone", 2, 2 * 2 * kPi * std::sqrt(2.0)},
                            {"bowl_plane", 1, 2 * kPi * std::sqrt(2.0)},
                            {"two_unbounded_cylinders", 2, 2 * 7.64039557805}};
  for (const Expected& e : cases)
    for (bool closed_form : {true, false}) {
      SCOPED_TRACE(std::string(e.name) + (closed_form ? " (closed form)" : " (traced)"));
      IntersectionSpec spec = *scene.intersection(e.name);
      spec.options.closed_form = closed_form;
      const IntersectionRun r = run_intersection(scene, spec);
      EXPECT_FALSE(has_unbounded_direction(r.problem.first()));
      EXPECT_FALSE(has_unbounded_direction(r.problem.second()));
      ASSERT_EQ(static_cast<int>(r.result.curves.size()), e.curves);
      for (const TracedCurve& c : r.result.curves) EXPECT_TRUE(c.closed);
      EXPECT_NEAR(total_length(r), e.length, kLength * e.length);
    }
}

TEST(Unbounded, TheNominalExtentStaysForWhatHasNoPair) {
  const Scene scene = parse_scene(kScene, "unbounded.json");
  const Surface& plane = scene.surface("plane");
  EXPECT_TRUE(plane.domain().unbounded_u && plane.domain().unbounded_v);
  EXPECT_EQ(plane.domain().u.lo, -1);
  EXPECT_FALSE(has_unbounded_direction(scene.surface("sphere")));
  // The clip covers the other surface's box with a margin: the sphere's box is [-2, 2]^3.
  const Surface clipped = clipped_to(plane, scene.surface("sphere").box());
  EXPECT_LT(clipped.domain().u.lo, -2);
  EXPECT_GT(clipped.domain().v.hi, 2);
}

}  // namespace
}  // namespace ssimarch
