// OpenCASCADE tests/lowalgos/intss scripts translated to examples/occt_* (issue 10 "Measure and
// publish"; bench/case_expectations.json) and the curve through a cone's apex (issue 11 item 5),
// traced with default options against closed forms:
//  * bug32850: two equal cylinders with perpendicular axes in strips 0 <= u <= 0.0225: the node
//    C + R e_z lies 7e-4 from both strips' u = 0 edges; the branches u1 = u2 (through the node)
//    and u1 + u2 = 2 delta (a 2e-3 stub crossing it), each once, the node an exact point of both;
//  * bug25950 (as the script states the locus): a sphere and a spheroid touching along the great
//    circle x = 0, which passes both poles of the sphere's parametrisation: one closed curve of
//    tangential contact of length 6 pi;
//  * a cone's apex on the curve (implicit, parametric, expression and B-spline cone): the node at the
//    apex, one closed curve;
//  * bug21494_2: the cone's apex on the sphere's pole, an isolated point, in both forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "testing/matchers.hpp"
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
  EXPECT_EQ(r.singular_points[0].type, SingularType::kNode);
  EXPECT_THAT(r.singular_points[0].p, testing::IsNear(node, 1e-10 * R));
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
    // The march's ends on the sphere's pole add the arc to the edge point, not the chord (which
    // left the parametric form 3.4e-6 short).
    EXPECT_NEAR(c.length, 6 * std::numbers::pi, 1e-6) << name;
    for (const CurvePoint& p : c.points) {  // on the circle x = 0, y^2 + z^2 = 9
      EXPECT_NEAR(p.p.x(), 0, 1e-9) << name;
      EXPECT_NEAR(std::hypot(p.p.y(), p.p.z()), 3, 1e-9) << name;
    }
  }
}

// Every form of the cone through its apex: implicit; parametric (the apex is the row v = 0 inside
// its parameter rectangle, where F_u x F_v = 0); implicit as the second surface of a
// parametric-implicit pair (its gradient vanishes at the apex); an expression and an exact
// rational B-spline without implicit form (the collapsed row's chart, docs/math/
// singular_local_curve.md §7), against the implicit cylinder and the B-spline against the
// parametric one. The apex is a node of the curve in 3D whatever the parametrisation: two
// branches with tangents (0, -1, -+1)/sqrt2 crossing straight, each half-branch once, the apex an
// exact point of the one closed curve, whose length is the implicit form's to 1e-8.
TEST(OcctCases, CurveThroughAConesApexHasItsNodeThereInEveryForm) {
  // z = 2 cos(t/2) on the cylinder (1 + cos t, sin t, z): length 8 sqrt2 E(1/2) (Viviani's).
  const double length = 15.2807911561;
  const Vec3 t1 = Vec3(0, -1, -1).normalized(), t2 = Vec3(0, -1, 1).normalized();
  double implicit_length = 0;
  for (const char* name : {"apex_implicit", "apex_cone_parametric", "apex_cylinder_parametric", "apex_cone_expression",
                           "apex_cone_spline", "apex_cone_spline_pp"}) {
    const TraceResult r = trace_example("cone_apex_cylinder.json", name);
    ASSERT_EQ(r.curves.size(), 1u) << name;
    EXPECT_TRUE(r.curves[0].closed) << name;
    EXPECT_THAT(r.curves[0], testing::HasLength(length, 1e-6 * length)) << name;
    if (implicit_length == 0) implicit_length = r.curves[0].length;
    EXPECT_THAT(r.curves[0], testing::HasLength(implicit_length, 1e-8 * length)) << name;
    ASSERT_EQ(r.singular_points.size(), 1u) << name;
    const SingularPointReport& s = r.singular_points[0];
    EXPECT_EQ(s.type, SingularType::kNode) << name;
    EXPECT_EQ(s.ak, "A1") << name;
    EXPECT_LT(s.p.norm(), 1e-10) << name;
    EXPECT_EQ(s.curves, std::vector<int>{0}) << name;
    const bool on_curve = std::any_of(r.curves[0].points.begin(), r.curves[0].points.end(),
                                      [](const CurvePoint& q) { return q.p.norm() <= 1e-10; });
    EXPECT_TRUE(on_curve) << name;
    ASSERT_EQ(s.half_branches.size(), 4u) << name;
    for (const auto& b : s.half_branches) {
      EXPECT_NEAR(std::max(std::fabs(b.tangent.dot(t1)), std::fabs(b.tangent.dot(t2))), 1.0, 1e-9) << name;
      ASSERT_GE(b.continuation, 0) << name;
      EXPECT_NEAR(b.tangent.dot(s.half_branches[static_cast<std::size_t>(b.continuation)].tangent), -1.0, 1e-9) << name;
    }
  }
}

// bug21494_2 with both surfaces parametric: the cone's apex is the sphere's pole, an isolated
// point of the intersection (the cone's tip inside the sphere), where both parametrisations are
// degenerate; beside it the circle z = 50/13 of radius 120/13.
TEST(OcctCases, Bug21494ApexOnThePoleIsAnIsolatedPointInEveryForm) {
  for (const char* name : {"bug21494_2", "bug21494_2_param"}) {
    const TraceResult r = trace_example("occt_bug21494_2_cone_sphere.json", name);
    ASSERT_EQ(r.curves.size(), 1u) << name;
    EXPECT_TRUE(r.curves[0].closed) << name;
    EXPECT_THAT(r.curves[0], testing::HasLength(240 * std::numbers::pi / 13, 1e-8)) << name;
    std::vector<Vec3> isolated;
    for (const auto& s : r.singular_points)
      if (s.type == SingularType::kIsolated) isolated.push_back(s.p);
    for (const auto& s : r.isolated_points) isolated.push_back(s.p);
    ASSERT_FALSE(isolated.empty()) << name;
    for (const Vec3& p : isolated) EXPECT_THAT(p, testing::IsNear(Vec3(0, 0, 10), 1e-10)) << name;
  }
}

// bug21494_1 (issue 29: one representation of an isolated point): the cone opening away from the
// sphere touches it only at its apex on the sphere's pole. Closed form, traced and both
// parametric: no curve (a march from the apex takes no step; its one point is not a curve) and
// the one isolated point (0, 0, 10).
TEST(OcctCases, Bug21494ApexTouchingThePoleIsOneIsolatedPointNeverACurve) {
  const Scene scene = parse_scene(R"json({"surfaces": {
      "cone": {"cone": {"apex": [0, 0, 10], "axis": [0, 0, 1], "half_angle": "atan(1.5)", "range": [0, 10]}},
      "sphere": {"sphere": {"center": [0, 0, 0], "radius": 10}}},
    "intersections": [{"name": "closed_form", "surfaces": ["cone", "sphere"]},
                      {"name": "traced", "surfaces": ["cone", "sphere"], "options": {"closed_form": false}},
                      {"name": "parametric", "surfaces": ["cone", "sphere"], "as": ["parametric", "parametric"]}]})json",
                                  "bug21494_1.json");
  for (const IntersectionSpec& spec : scene.intersections) {
    SCOPED_TRACE(spec.name);
    const TraceResult r = run_intersection(scene, spec).result;
    EXPECT_TRUE(r.curves.empty());
    ASSERT_EQ(r.isolated_points.size(), 1u);
    EXPECT_THAT(r.isolated_points[0].p, testing::IsNear(Vec3(0, 0, 10), 1e-10));
    EXPECT_EQ(r.isolated_points[0].type, SingularType::kIsolated);
  }
}

// bug23163_1's situation (its surfaces are data files not available here; the scene is
// examples/occt_tori_tangent_circle.json): two tori tangent along a whole circle, crossed there
// by a closed transversal curve that passes itself at a node. One network in every form: the
// contact circle cut at the two tangent_line_crossings into arcs of 2 acos(2/3) and
// 2 pi - 2 acos(2/3), the transversal curve through both crossings and twice through the node.
// The crossings lie where the separation's curvature cos v / (2 + cos v) + 1/2 vanishes (cos v =
// -2/3), at (4/3, 0, +-sqrt(5)/3); the transversal curve's length 26.9159167989017 comes from
// tests/trace/data/tangent/tori_tangent_circle_reference.py (its own continuation in 80-bit floats
// and Gauss-Legendre panels, converged to 1e-12).
TEST(OcctCases, Bug23163TangentCircleCrossedByAClosedCurveIsOneNetwork) {
  const std::string torus_a = R"({"torus": {"center": [0, 0, 0], "axis": [0, 0, 1], "reference": [1, 0, 0], )"
                              R"("major_radius": 2, "minor_radius": 1}})";
  const std::string torus_b = R"({"torus": {"center": [2, 0, 0], "axis": [0, 1, 0], "reference": [1, 0, 0], )"
                              R"("major_radius": 3, "minor_radius": 2}})";
  const double kTransversal = 26.9159167989017, arc = 2 * std::acos(2.0 / 3.0);
  for (const char* as : {"", R"(, "as": ["parametric", "implicit"])", R"(, "as": ["implicit", "parametric"])",
                         R"(, "as": ["parametric", "parametric"])"}) {
    SCOPED_TRACE(as);
    const Scene scene = parse_scene(R"({"surfaces": {"a": )" + torus_a + R"(, "b": )" + torus_b +
                                        R"(}, "intersections": [{"name": "t", "surfaces": ["a", "b"])" + as + "}]}",
                                    "bug23163");
    const IntersectionRun run = run_intersection(scene, scene.intersections.at(0));
    const TraceResult& r = run.result;
    ASSERT_EQ(r.curves.size(), 2u);
    double contact = 0, transversal = 0;
    for (const TracedCurve& c : r.curves) {
      EXPECT_TRUE(c.closed);
      (c.tangential_contact ? contact : transversal) += c.length;
    }
    EXPECT_NEAR(contact, 2 * std::numbers::pi, 1e-9);
    EXPECT_NEAR(transversal, kTransversal, 1e-9 * kTransversal);
    std::vector<Vec3> crossings, nodes;
    for (const SingularPointReport& s : r.singular_points)
      (s.type == SingularType::kTangentLineCrossing ? crossings : nodes).push_back(s.p);
    ASSERT_EQ(crossings.size(), 2u);
    ASSERT_EQ(nodes.size(), 1u);
    for (const Vec3& p : crossings) {
      EXPECT_NEAR(p.x(), 4.0 / 3.0, 1e-9);
      EXPECT_NEAR(std::fabs(p.y()), 0.0, 1e-9);
      EXPECT_NEAR(std::fabs(p.z()), std::sqrt(5.0) / 3.0, 1e-9);
    }
    EXPECT_THAT(nodes[0], testing::IsNear(Vec3(-3, 0, 0), 1e-9));
    const CurveNetwork& net = run.network;
    EXPECT_EQ(net.components.size(), 1u);
    EXPECT_TRUE(net.complete());
    std::vector<double> contact_edges;
    for (const NetworkEdge& e : net.edges)
      if (r.curves[static_cast<std::size_t>(e.curve)].tangential_contact) contact_edges.push_back(e.length);
    std::sort(contact_edges.begin(), contact_edges.end());
    ASSERT_EQ(contact_edges.size(), 2u);
    EXPECT_NEAR(contact_edges[0], arc, 1e-9);
    EXPECT_NEAR(contact_edges[1], 2 * std::numbers::pi - arc, 1e-9);
    EXPECT_EQ(net.edges.size(), 6u);
  }
}

}  // namespace
}  // namespace ssimarch
