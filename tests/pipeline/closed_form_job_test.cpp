// The closed form in the pipeline (docs/math/closed_form_quadrics.md): the same answer as the
// traced one (curves, closed, lengths, points on the same curve), plus the conic; option
// closed_form = false traces.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

const char* kScene = R"json({
  "surfaces": {"sphere": {"sphere": {"center": [0,0,0], "radius": 2}},
               "small": {"sphere": {"center": [1.5,0,0], "radius": 1.5}},
               "tilted": {"plane": {"point": [0,0,1], "normal": [1,1,2], "u": [-6,6], "v": [-6,6]}},
               "cyl": {"cylinder": {"point": [0,0,0], "axis": [0,0,1], "radius": 1, "range": [-3,3]}},
               "slant": {"plane": {"point": [0,0,0], "normal": [-0.5,0,1], "u": [-6,6], "v": [-6,6]}}},
  "intersections": [
    {"name": "plane_sphere", "surfaces": ["sphere", "tilted"]},
    {"name": "two_spheres", "surfaces": ["sphere", "small"]},
    {"name": "sphere_cylinder", "surfaces": ["sphere", "cyl"]},
    {"name": "plane_cylinder", "surfaces": ["cyl", "slant"]}
  ]})json";

struct Pair {
  IntersectionRun exact, traced;
};

Pair both(const Scene& scene, const std::string& name) {
  IntersectionSpec spec = *scene.intersection(name);
  IntersectionSpec off = spec;
  off.options.closed_form = false;
  return Pair{run_intersection(scene, spec), run_intersection(scene, off)};
}

TEST(ClosedFormJob, AgreesWithTheTracedAnswer) {
  const Scene scene = parse_scene(kScene, "closed_form.json");
  const double d = 2 / std::sqrt(6.0);
  const std::vector<std::pair<std::string, double>> cases = {
      {"plane_sphere", 2 * kPi * std::sqrt(4 - d * d)},
      {"two_spheres", 2 * kPi * std::sqrt(20.0 / 9)},
      {"sphere_cylinder", 2 * 2 * kPi},
      {"plane_cylinder", -1}};  // an ellipse: compared with the trace only
  for (const auto& [name, exact_length] : cases) {
    SCOPED_TRACE(name);
    const Pair p = both(scene, name);
    ASSERT_EQ(p.exact.conics.size(), p.exact.result.curves.size());
    EXPECT_TRUE(p.traced.conics.empty());
    EXPECT_EQ(p.exact.result.start_search.method, StartSearchMethod::kClosedForm);
    ASSERT_EQ(p.exact.result.curves.size(), p.traced.result.curves.size());
    double le = 0, lt = 0;
    for (std::size_t c = 0; c < p.exact.result.curves.size(); ++c) {
      EXPECT_EQ(p.exact.result.curves[c].closed, p.traced.result.curves[c].closed);
      le += p.exact.result.curves[c].length;
      lt += p.traced.result.curves[c].length;
    }
    EXPECT_NEAR(le, lt, 1e-6 * le);
    if (exact_length > 0) {
      EXPECT_NEAR(le, exact_length, 1e-11 * exact_length);
    }
    // Every traced point lies on one of the exact conics: within the chordal deviation of the
    // polyline of the closed-form points, which are on the conic.
    for (const TracedCurve& t : p.traced.result.curves)
      for (const CurvePoint& q : t.points) {
        double best = INFINITY;
        for (const TracedCurve& e : p.exact.result.curves)
          for (const CurvePoint& r : e.points) best = std::min(best, (r.p - q.p).norm());
        EXPECT_LT(best, 0.25) << q.p.transpose();  // nearest sample; the samples are <= scale/10 apart
      }
  }
}

TEST(ClosedFormJob, PointsAreExactAndTheOptionTurnsItOff) {
  const Scene scene = parse_scene(kScene, "closed_form.json");
  const Pair p = both(scene, "plane_cylinder");
  ASSERT_EQ(p.exact.conics.size(), 1u);
  EXPECT_EQ(p.exact.conics[0].type, ConicType::kEllipse);
  for (const CurvePoint& q : p.exact.result.curves[0].points) {
    EXPECT_NEAR(q.p.x() * q.p.x() + q.p.y() * q.p.y(), 1, 1e-14);
    EXPECT_NEAR(q.p.z(), 0.5 * q.p.x(), 1e-14);
  }
  EXPECT_EQ(p.traced.result.start_search.method == StartSearchMethod::kClosedForm, false);
}

}  // namespace
}  // namespace ssimarch
