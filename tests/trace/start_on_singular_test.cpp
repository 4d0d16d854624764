// Traces started exactly on a singular point with short steps (issue 10 "Tracing through", issue 11
// "every branch once"): the cardioid from its cusp, the two loops of Ex. 35 from their tacnode, at
// steps 1e-4 .. 1e-3 of the curves' size, come back with every branch once, closed, through the
// point; and the leading offset term reported at Viviani's node (JSON `expansion.coefficient`)
// against its closed form and the refined expansion.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "testing/matchers.hpp"
#include "ssimarch/analytic/closed_form.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/surface/primitives.hpp"
#include "ssimarch/trace/trace_all.hpp"
#include "testing/viviani_forms.hpp"

namespace ssimarch {
namespace {

TraceResult trace_from(const std::string& file, const std::vector<Vec3>& starts, double step) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/" + file);
  IntersectionSpec spec = scene.intersections.at(0);
  spec.starts = starts;
  spec.options.trace.step_length = step;
  spec.options.trace.max_points = 10000000;
  return run_intersection(scene, spec).result;
}

bool passes(const TracedCurve& c, const Vec3& p, double tol) {
  for (const auto& q : c.points)
    if ((q.p - p).norm() <= tol) return true;
  return false;
}

// The cardioid (u^2 + v^2)^2 - 4u(u^2 + v^2) - 4v^2 = 0 (r = 2(1 + cos phi), size 4, length 16),
// started on its cusp at the origin.
TEST(StartOnSingular, CardioidFromItsCuspIsOneClosedCurve) {
  for (double step : {4e-4, 1e-3, 4e-3}) {
    const TraceResult r = trace_from("thesis_ex20_cardioid.json", {Vec3::Zero()}, step);
    ASSERT_EQ(r.curves.size(), 1u) << step;
    EXPECT_TRUE(r.curves[0].closed) << step;
    EXPECT_THAT(r.curves[0], testing::HasLength(16.0, 1e-5)) << step;
    EXPECT_TRUE(passes(r.curves[0], Vec3::Zero(), 1e-10)) << step;
    ASSERT_EQ(r.singular_points.size(), 1u) << step;
    EXPECT_EQ(r.singular_points[0].type, SingularType::kCusp) << step;
    EXPECT_EQ(r.singular_points[0].curves, std::vector<int>{0}) << step;
  }
}

// v^2 - v^4 = u^4 (Ex. 35): two closed loops v > 0 and v < 0 touching at the tacnode, each of
// length 2 int_0^1 sqrt(1 + u'(v)^2) dv with u = (v^2 - v^4)^(1/4): 3.891720465065750 (mpmath
// tanh-sinh quadrature, 30 digits), started on the tacnode.
TEST(StartOnSingular, TacnodeLoopsFromTheirTacnodeEachOnce) {
  const double loop = 3.891720465065750;
  for (double step : {4e-4, 1e-3, 3e-3}) {
    const TraceResult r = trace_from("thesis_ex35_tacnode_loops.json", {Vec3::Zero()}, step);
    ASSERT_EQ(r.curves.size(), 2u) << step;
    for (const auto& c : r.curves) {
      EXPECT_TRUE(c.closed) << step;
      EXPECT_NEAR(c.length, loop, 1e-5) << step;
      EXPECT_TRUE(passes(c, Vec3::Zero(), 1e-10)) << step;
    }
    ASSERT_EQ(r.singular_points.size(), 1u) << step;
    EXPECT_EQ(r.singular_points[0].type, SingularType::kTacnode) << step;
    EXPECT_EQ(r.singular_points[0].curves, (std::vector<int>{0, 1})) << step;
  }
}

// Viviani's curve (sin s, -1 - cos s, 2 sin(s/2)) on the cylinder x^2 + (y + 1)^2 = 1 passes its
// node (0, -2, 0) at s = 0 and s = 2 pi. Over the common tangent plane y = -2 each branch is
// offset from its tangent by w = c X^3 (its curvature vector (0, 1/2, 0) is normal to that plane):
// c = lim w / X^3 with X, w the components of P(s) - P(0) along the half-branch's tangent and
// `normal` (the frame of docs/math/singular_local_curve.md §4, "The expansion frame": |c| = 1/32).
// The reported leading coefficient and the expansion's first term are that c, with its sign, on
// all four half-branches, whichever pair kind or parametrisation gives the node.
void expect_viviani_node(const std::vector<SingularPointReport>& points, const std::string& label) {
  ASSERT_EQ(points.size(), 1u) << label;
  const SingularPointReport& node = points[0];
  EXPECT_EQ(node.type, SingularType::kNode) << label;
  EXPECT_THAT(node.p, testing::IsNear(Vec3(0, -2, 0), 1e-10)) << label;
  ASSERT_EQ(node.half_branches.size(), 4u) << label;
  auto P = [](double s) { return Vec3(std::sin(s), -1 - std::cos(s), 2 * std::sin(s / 2)); };
  for (const auto& b : node.half_branches) {
    // The passage and direction of the curve along this half-branch.
    double s0 = 0, dir = 0;
    for (double c : {0.0, 2 * M_PI}) {
      const Vec3 d = (P(c + 1e-6) - P(c - 1e-6)).normalized();
      if (std::fabs(d.dot(b.tangent)) > 0.999) s0 = c, dir = d.dot(b.tangent) > 0 ? 1.0 : -1.0;
    }
    ASSERT_NE(dir, 0.0) << label;
    const double ds = 2e-3;
    const Vec3 q = P(s0 + dir * ds) - P(s0);
    const double X = q.dot(b.tangent), w = q.dot(b.normal);
    const double c_ref = w / (X * X * X);  // c + O(X^2): 1e-5 relative at this ds
    EXPECT_NEAR(std::fabs(c_ref), 1.0 / 32, 1e-5) << label;
    ASSERT_FALSE(b.expansion.empty()) << label;
    EXPECT_NEAR(b.expansion[0].exponent, 3.0, 1e-12) << label;
    EXPECT_NEAR(b.expansion[0].coefficient, c_ref, 2e-5 * std::fabs(c_ref)) << label;
    EXPECT_NEAR(b.exponent, 3.0, 1e-12) << label;
    // The whole series over the tangent plane: W = +-(X^3/32 + X^5/256 + 11 X^7/16384 + ...)
    // (sympy: X and W from P(s), X(s) reverted), no X^4 or X^6 term.
    ASSERT_EQ(b.expansion.size(), 2u) << label;
    EXPECT_NEAR(b.expansion[1].exponent, 5.0, 1e-12) << label;
    EXPECT_NEAR(b.expansion[1].coefficient, (c_ref > 0 ? 1.0 : -1.0) / 256, 1e-9) << label;
    // The measured leading term (at the classifier's circle, O(1e-2) relative) in the same frame.
    EXPECT_NEAR(b.coefficient, b.expansion[0].coefficient, 0.05 * std::fabs(c_ref)) << label;
  }
}

TEST(StartOnSingular, VivianiNodeLeadingTermsAgreeWithTheClosedForm) {
  // The scene (parametric cylinder, implicit sphere: the general classifier), with the closed form
  // off and on (its own start point keeps the general path; without one the pair is traced).
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/viviani.json");
  IntersectionSpec spec = scene.intersections.at(0);
  expect_viviani_node(run_intersection(scene, spec).result.singular_points, "viviani.json");
  // The three pair kinds of the general classifier (testing/viviani_forms.hpp), from a start on the curve.
  const char* kinds[] = {"parametric-parametric", "parametric-implicit", "implicit-implicit"};
  int k = 0;
  for (const Problem& P : testing::viviani_problems()) {
    TraceOptions o;
    o.step_length = 0.05;
    expect_viviani_node(trace_all(P, o, {testing::viviani(1.0)}).singular_points, kinds[k++]);
  }
  // The closed form of the quadric pair (analytic/ruled_crossing.cpp).
  const auto cf =
      closed_form_intersection(Problem(Sphere(Vec3::Zero(), 2), Cylinder(Vec3(0, -1, 0), Vec3::UnitZ(), 1, {-3, 3}),
                                       PairKind::kImplicitImplicit),
                               TraceOptions{});
  ASSERT_TRUE(cf.has_value());
  expect_viviani_node(cf->result.singular_points, "closed form");
}

}  // namespace
}  // namespace ssimarch
