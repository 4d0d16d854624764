// OpenCASCADE tests/lowalgos/intss scripts translated to examples/occt_* (issue 10 "Measure and
// publish"; bench/case_expectations.json) and the curve through a cone's apex (issue 11 item 5),
// traced with default options against closed forms:
//  * bug32850: two equal cylinders with perpendicular axes in strips 0 <= u <= 0.0225: the node
//    C + R e_z lies 7e-4 from both strips' u = 0 edges; the branches u1 = u2 (through the node)
//    and u1 + u2 = 2 delta (a 2e-3 stub crossing it), each once, the node an exact point of both;
//  * bug25950 (as the script states the locus): a sphere and a spheroid touching along the great
//    circle x = 0, which passes both poles of the sphere's parametrisation: one closed curve of
//    tangential contact of length 6 pi;
//  * a cone's apex on the curve (implicit cone): the node at the apex, one closed curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {
namespace {

TraceResult trace_example(const std::string& file, const std::string& name) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/" + file);
  for (const auto& spec : scene.intersections)
    if (spec.name == name) return run_intersection(scene, spec).result;
  ADD_FAILURE() << "no intersection " << name << " in " << file;
  return {};
}

// R times the integral of sqrt(1 + cos^2 s) over [a, b] (composite Simpson, 2000 panels: the
// integrand is smooth, the error is far below the tolerances used).
double steinmetz_arc(double R, double a, double b) {
  const int n = 2000;
  const double h = (b - a) / n;
  auto f = [](double s) { return std::sqrt(1 + std::cos(s) * std::cos(s)); };
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
  return R * sum * h / 3;
}

TEST(OcctCases, Bug32850NodeNextToTheStripEdgeBothBranchesOnce) {
  const double R = 408.974517822893, U = 0.0225015452057227;
  const double delta = std::atan2(1.73024882663956e-06, 0.999999999998503);
  const Vec3 node(25.8071575178163, 1974.19284248218, -373.974517822281 + R);
  const TraceResult r = trace_example("occt_bug32850_cylinders.json", "bug32850");
  ASSERT_EQ(r.singular_points.size(), 1u);
  EXPECT_EQ(r.singular_points[0].type, "node");
  EXPECT_LT((r.singular_points[0].p - node).norm(), 1e-10 * R);
  ASSERT_EQ(r.curves.size(), 2u);
  std::vector<double> lengths;
  for (const TracedCurve& c : r.curves) {
    EXPECT_FALSE(c.closed);
    lengths.push_back(c.length);
    bool has_node = false;  // the node is an exact point of both branches
    for (const CurvePoint& p : c.points) has_node = has_node || (p.p - node).norm() < 1e-9 * R;
    EXPECT_TRUE(has_node);
  }
  std::sort(lengths.begin(), lengths.end());
  EXPECT_NEAR(lengths[0], steinmetz_arc(R, -delta, delta), 1e-6 * lengths[0]);
  EXPECT_NEAR(lengths[1], steinmetz_arc(R, -delta, U - delta), 1e-6 * lengths[1]);
}

TEST(OcctCases, Bug25950ContactCircleThroughBothPolesIsOneClosedCurve) {
  for (const std::string name : {"bug25950", "bug25950_param"}) {
    const TraceResult r = trace_example("occt_bug25950_sphere_ellipsoid.json", name);
    ASSERT_EQ(r.curves.size(), 1u) << name;
    const TracedCurve& c = r.curves[0];
    EXPECT_TRUE(c.tangential_contact) << name;
    EXPECT_TRUE(c.closed) << name;
    EXPECT_NEAR(c.length, 6 * std::numbers::pi, 1e-6) << name;
    for (const CurvePoint& p : c.points) {  // on the circle x = 0, y^2 + z^2 = 9
      EXPECT_NEAR(p.p.x(), 0, 1e-9) << name;
      EXPECT_NEAR(std::hypot(p.p.y(), p.p.z()), 3, 1e-9) << name;
    }
  }
}

TEST(OcctCases, CurveThroughAnImplicitConesApexHasItsNodeThere) {
  // z = 2 cos(t/2) on the cylinder (1 + cos t, sin t, z): length 8 sqrt2 E(1/2) (Viviani's).
  const double length = 15.2807911561;
  const TraceResult r = trace_example("cone_apex_cylinder.json", "apex_implicit");
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_NEAR(r.curves[0].length, length, 1e-6 * length);
  ASSERT_EQ(r.singular_points.size(), 1u);
  EXPECT_EQ(r.singular_points[0].type, "node");
  EXPECT_LT(r.singular_points[0].p.norm(), 1e-10);
}

}  // namespace
}  // namespace ssimarch
