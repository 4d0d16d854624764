// Curves of tangential contact (issue 10 item 5; docs/math/tangential_contact.md): surfaces that
// touch along a whole curve give that curve, traced and marked tangential_contact, with default
// options; against the closed forms of each pair. The coaxial tori are the situation of
// OpenCASCADE's tests/lowalgos/intss/bug23163 ("no resulting circle at the intersection of tori").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/trace/tangential_contact.hpp"

namespace ssimarch {
namespace {

TraceResult trace_scene(const std::string& json) {
  const Scene scene = parse_scene(json, "contact");
  return run_intersection(scene, scene.intersections.at(0)).result;
}

std::string pair_scene(const std::string& first, const std::string& second) {
  return R"({"surfaces": {"A": )" + first + R"(, "B": )" + second +
         R"(}, "intersections": [{"name": "c", "surfaces": ["A", "B"]}]})";
}

std::vector<const TracedCurve*> contact_curves(const TraceResult& r) {
  std::vector<const TracedCurve*> out;
  for (const auto& c : r.curves)
    if (c.tangential_contact) out.push_back(&c);
  return out;
}

TEST(TangentialContact, CylinderLyingOnAPlane) {
  // (v, sin u, 1 + cos u) touches z = 0 along the line u = pi: the segment y = z = 0, |x| <= 2.
  const TraceResult r = trace_scene(
      pair_scene(R"J({"parametric": ["v", "sin(u)", "1+cos(u)"], "u": [0, "2*pi"], "v": [-2, 2], "periodic": ["u"]})J",
                 R"J({"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})J"));
  ASSERT_EQ(r.curves.size(), 1u);
  const TracedCurve& c = r.curves[0];
  EXPECT_TRUE(c.tangential_contact);
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.start_end, Termination::kLeftDomain);
  EXPECT_EQ(c.end_end, Termination::kLeftDomain);
  EXPECT_NEAR(c.length, 4.0, 1e-9);
  EXPECT_NEAR(std::fabs(c.points.front().p.x() - c.points.back().p.x()), 4.0, 1e-9);
  for (const auto& p : c.points) {
    EXPECT_LE(std::fabs(p.p.y()), 1e-10);
    EXPECT_LE(std::fabs(p.p.z()), 1e-12);
  }
  EXPECT_TRUE(r.singular_points.empty());
  EXPECT_TRUE(r.isolated_points.empty());
}

// The peers case cylinder_plane_tangent traced (closed form off), both surfaces parametric: the
// contact line x = z = 0, |y| <= 2 lies on the cylinder's seam. Its march used to stop short of one
// edge (by 0.021 at the automatic step) and a second start in that gap traced the line again: two
// open curves of 3.979. One curve of length 4, ends on y = -2 and y = 2 to 1e-9, at every step.
TEST(TangentialContact, ContactLineLandsOnBothEdgesAndIsTracedOnce) {
  for (double step : {0.0, 0.01, 0.03, 0.05}) {
    const std::string json =
        R"({"surfaces": {"cyl": {"cylinder": {"point": [0, 0, 1], "axis": [0, 1, 0], "radius": 1, "range": [-2, 2]}},
      "plane": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1], "u": [-3, 3], "v": [-3, 3]}}},
      "intersections": [{"name": "c", "surfaces": ["cyl", "plane"], "options": {"closed_form": false, "step_length": )" +
        std::to_string(step) + "}}]}";
    const TraceResult r = trace_scene(json);
    ASSERT_EQ(r.curves.size(), 1u) << "step " << step;
    const TracedCurve& c = r.curves[0];
    EXPECT_TRUE(c.tangential_contact) << "step " << step;
    EXPECT_NEAR(c.length, 4.0, 1e-9) << "step " << step;
    const double y0 = c.points.front().p.y(), y1 = c.points.back().p.y();
    EXPECT_NEAR(std::min(y0, y1), -2.0, 1e-9) << "step " << step;
    EXPECT_NEAR(std::max(y0, y1), 2.0, 1e-9) << "step " << step;
  }
}

TEST(TangentialContact, SphereInsideCylinderOfEqualRadius) {
  // The unit sphere touches x^2 + y^2 = 1 along its equator (length 2 pi).
  const TraceResult r = trace_scene(pair_scene(
      R"J({"parametric": ["cos(u)*cos(v)", "sin(u)*cos(v)", "sin(v)"], "u": [0, "2*pi"], "v": [-1.5, 1.5], "periodic": ["u"]})J",
      R"J({"implicit": "x^2+y^2-1", "box": [[-2, 2], [-2, 2], [-2, 2]]})J"));
  const auto contact = contact_curves(r);
  ASSERT_EQ(contact.size(), 1u);
  EXPECT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(contact[0]->closed);
  EXPECT_NEAR(contact[0]->length, 2 * std::numbers::pi, 1e-6);
  for (const auto& p : contact[0]->points) {
    EXPECT_LE(std::fabs(p.p.z()), 1e-10);
    EXPECT_NEAR(std::hypot(p.p.x(), p.p.y()), 1.0, 1e-12);
  }
}

TEST(TangentialContact, CoaxialToriTouchingAlongACircle) {
  // Tori of radii (5, 1) and (7, 1) about the z axis: the tubes touch along the circle of
  // radius 6 in z = 0 (length 12 pi), OpenCASCADE bug23163's situation.
  const TraceResult r = trace_scene(pair_scene(
      R"J({"parametric": ["(5+cos(v))*cos(u)", "(5+cos(v))*sin(u)", "sin(v)"], "u": [0, "2*pi"], "v": [0, "2*pi"], "periodic": ["u", "v"]})J",
      R"J({"implicit": "(x^2+y^2+z^2+48)^2-196*(x^2+y^2)", "box": [[-9, 9], [-9, 9], [-2, 2]]})J"));
  const auto contact = contact_curves(r);
  ASSERT_EQ(contact.size(), 1u);
  EXPECT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(contact[0]->closed);
  EXPECT_NEAR(contact[0]->length, 12 * std::numbers::pi, 1e-5);
  for (const auto& p : contact[0]->points) {
    EXPECT_LE(std::fabs(p.p.z()), 1e-9);
    EXPECT_NEAR(std::hypot(p.p.x(), p.p.y()), 6.0, 1e-9);
  }
}

TEST(TangentialContact, TransversalBranchCrossingIt) {
  // h = u^2 v: the contact line u = 0 crossed by the transversal branch v = 0 at the origin, a
  // tangent_line_crossing (docs/math/tangential_contact.md §3).
  const TraceResult r = trace_scene(pair_scene(R"J({"parametric": ["u", "v", "u^2*v"], "u": [-1, 1], "v": [-1, 1]})J",
                                               R"J({"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})J"));
  const auto contact = contact_curves(r);
  ASSERT_EQ(contact.size(), 1u);
  EXPECT_NEAR(contact[0]->length, 2.0, 1e-9);
  ASSERT_EQ(r.singular_points.size(), 1u);
  const SingularPointReport& s = r.singular_points[0];
  EXPECT_EQ(s.type, SingularType::kTangentLineCrossing);
  EXPECT_LE(s.p.norm(), 1e-10);
  double transversal = 0;
  bool through = false;
  for (const auto& c : r.curves) {
    if (c.tangential_contact) continue;
    transversal += c.length;
    for (const auto& p : c.points) through = through || p.p.norm() <= 1e-10;
    for (const auto& p : c.points) EXPECT_LE(std::fabs(p.p.y()), 1e-8);  // |h| = u^2 |v| <= tolerance
  }
  EXPECT_NEAR(transversal, 2.0, 1e-6);
  EXPECT_TRUE(through);
}

TEST(TangentialContact, NearMissIsNoContact) {
  // The cylinder 1e-9 above the plane: the surfaces do not meet, no curve at all.
  const TraceResult r = trace_scene(pair_scene(
      R"J({"parametric": ["v", "sin(u)", "1+1e-9+cos(u)"], "u": [0, "2*pi"], "v": [-2, 2], "periodic": ["u"]})J",
      R"J({"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})J"));
  EXPECT_TRUE(r.curves.empty());
  EXPECT_TRUE(r.singular_points.empty());
  EXPECT_TRUE(r.isolated_points.empty());
}

TEST(TangentialContact, CorrectorLandsOnTheCurveAcrossIt) {
  // From (u, v) = (pi + 0.05, 0.3) the corrector moves across the line u = pi only (minimum-norm
  // step): v is kept.
  const Scene scene = parse_scene(
      pair_scene(R"J({"parametric": ["v", "sin(u)", "1+cos(u)"], "u": [0, "2*pi"], "v": [-2, 2], "periodic": ["u"]})J",
                 R"J({"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})J"),
      "contact");
  const Problem P = scene.problem(scene.intersections.at(0));
  VecX x(2);
  x << std::numbers::pi + 0.05, 0.3;
  const ContactPoint c = correct_onto_contact(P, x);
  ASSERT_TRUE(on_contact_curve(c));
  EXPECT_NEAR(c.location.x[0], std::numbers::pi, 1e-13);
  EXPECT_NEAR(c.location.x[1], 0.3, 1e-13);
  EXPECT_NEAR(c.lambda, 1.0, 1e-9);  // h = 1 + cos u = d^2 / 2 + ...: Hess h = diag(1, 0) in (s, t)
}

}  // namespace
}  // namespace ssimarch
