// Viviani's curve on an exact rational B-spline sphere, whose pole rows are collapsed edges of
// its patch and which has no implicit form (docs/math/singular_local_curve.md §7; issue 10
// "Not done yet"): traced with default options it is one closed curve of the closed-form length,
// with its node found, located and classified; the curve passes both poles, regular points of it
// where the patch's chart collapses. With the node itself on a pole row it is classified there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "testing/matchers.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/half_branches.hpp"
#include "ssimarch/singular/locate.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "ssimarch/surface/primitives.hpp"
#include "ssimarch/trace/trace_all.hpp"
#include "testing/nurbs_sphere.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

using testing::nurbs_sphere;

// Viviani's curve on the sphere of radius 2 and the cylinder (x - 1)^2 + y^2 = 1:
// (1 + cos t, sin t, 2 sin(t/2)), t in [0, 4 pi), length 2 int_0^{2 pi} sqrt(1 + cos^2 s) ds
// (Simpson's rule, 20000 panels: far below the tolerances used); the node (2, 0, 0), the poles
// (0, 0, -+2) of the z-axis sphere regular points of it.
double viviani_length() {
  const int n = 20000;
  const double step = 2 * kPi / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double c = std::cos(i * step);
    sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * std::sqrt(1 + c * c);
  }
  return 2 * sum * step / 3;
}

void expect_viviani_with_its_node(const TraceResult& r, const char* label) {
  ASSERT_EQ(r.curves.size(), 1u) << label;
  EXPECT_TRUE(r.curves[0].closed) << label;
  EXPECT_NEAR(r.curves[0].length / viviani_length() - 1, 0.0, 1e-8) << label;
  const Vec3 node(2, 0, 0);
  ASSERT_EQ(r.singular_points.size(), 1u) << label;
  const SingularPointReport& s = r.singular_points[0];
  EXPECT_EQ(s.type, SingularType::kNode) << label;
  EXPECT_THAT(s.p, testing::IsNear(node, 1e-10)) << label;
  EXPECT_EQ(s.half_branches.size(), 4u) << label;
  EXPECT_EQ(s.curves, std::vector<int>{0}) << label;
  EXPECT_TRUE(std::any_of(r.curves[0].points.begin(), r.curves[0].points.end(), [&](const CurvePoint& q) {
    return (q.p - node).norm() <= 1e-10;
  })) << label;
}

TEST(CollapsedRow, VivianiOnARationalSphereThroughItsPolesKeepsItsNode) {
  const Surface sphere = nurbs_sphere(2, 2);
  const Cylinder cylinder(Vec3(1, 0, 0), Vec3::UnitZ(), 1, {-3, 3});
  expect_viviani_with_its_node(trace_all(Problem(sphere, cylinder, PairKind::kParametricImplicit), {}),
                               "implicit cylinder");
  expect_viviani_with_its_node(trace_all(Problem(sphere, cylinder, PairKind::kParametricParametric), {}),
                               "parametric cylinder");
}

// The same sphere turned so that its pole +2 e_x is the node: the singular point lies exactly on
// a collapsed edge row of the patch, where the height over the cylinder vanishes to order 2 in
// the distance from the row (every generator lies in the common tangent plane). Located from the
// pole's parameters, it is classified in the cylinder's chart: a node with the tangents
// (0, +-1, +-1)/sqrt2 of (1 + cos t, sin t, 2 sin(t/2)) at t = 0, 2 pi, each half-branch continued
// straight on.
TEST(CollapsedRow, VivianiNodeOnARationalSpheresPoleIsClassified) {
  const Problem P(nurbs_sphere(2, 0), Cylinder(Vec3(1, 0, 0), Vec3::UnitZ(), 1, {-3, 3}),
                  PairKind::kParametricImplicit);
  VecX x(2);
  x << 0.3, 1.0;  // on the pole row v = 1, any u
  const SingularLocation s = locate_singular_point(P, x);
  ASSERT_EQ(s.status, LocateStatus::kConverged);
  EXPECT_THAT(s.point, testing::IsNear(Vec3(2, 0, 0), 1e-10));
  const LocalCurve c = local_curve(P, s.x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  const Classification kind = classify(c.h);
  EXPECT_EQ(kind.type, SingularType::kNode);
  EXPECT_EQ(kind.ak, "A1");
  const std::vector<HalfBranch> hb = half_branches(P, c, kind);
  ASSERT_EQ(hb.size(), 4u);
  const Vec3 t1 = Vec3(0, 1, 1).normalized(), t2 = Vec3(0, 1, -1).normalized();
  for (const HalfBranch& b : hb) {
    EXPECT_NEAR(std::max(std::fabs(b.tangent_3d.dot(t1)), std::fabs(b.tangent_3d.dot(t2))), 1.0, 1e-9);
    ASSERT_GE(b.continuation, 0);
    EXPECT_NEAR(b.tangent_3d.dot(hb[static_cast<std::size_t>(b.continuation)].tangent_3d), -1.0, 1e-9);
    EXPECT_TRUE(b.exit_ok);
  }
}

// Traced with default options: the pole passage carries the curve through the pole, the hunt
// finds the node there and inserts it into both passages of the curve: one closed curve.
TEST(CollapsedRow, VivianiNodeOnARationalSpheresPoleIsTracedOnce) {
  const Problem P(nurbs_sphere(2, 0), Cylinder(Vec3(1, 0, 0), Vec3::UnitZ(), 1, {-3, 3}),
                  PairKind::kParametricImplicit);
  expect_viviani_with_its_node(trace_all(P, {}), "node on the pole");
}

// Issue 27: the rational sphere resting on a plane with its pole at the contact point (as
// OpenCASCADE's GeomConvert lays a sphere out: poles on the axis). Every meridian curves away
// from the plane the same way, so no branch leaves the pole row: one isolated point, in either
// order, never a curve (it was a "curve" of length 2e-6 from the pole's plain chart).
TEST(CollapsedRow, RationalSpherePoleRestingOnAPlaneIsOneIsolatedPoint) {
  const BSplineSurface s = nurbs_sphere(1, 2);
  const Plane plane(Vec3(0, 0, -1), Vec3::UnitZ(), {{-2, 2}, {-2, 2}});
  for (bool sphere_first : {true, false}) {
    const TraceResult r = sphere_first ? trace_all(Problem(s, plane, PairKind::kParametricParametric), {})
                                       : trace_all(Problem(plane, s, PairKind::kParametricParametric), {});
    EXPECT_TRUE(r.curves.empty()) << "sphere first: " << sphere_first;
    ASSERT_EQ(r.isolated_points.size(), 1u) << "sphere first: " << sphere_first;
    EXPECT_THAT(r.isolated_points[0].p, testing::IsNear(Vec3(0, 0, -1), 1e-9));
    EXPECT_EQ(r.isolated_points[0].type, SingularType::kIsolated);
  }
}

// A curve crossing the rational sphere's pole where the march's watch stops (the cone of
// examples/occt_sphere_cone_node.json moved so that the sphere of radius 2 is centred at the
// origin: the curve passes the south pole (0, 0, -2) transversally and has its node at the
// contact point): the pole is a regular point of the curve that the walk passes along its two
// halves, not an end, and not reported as a singular point. One closed curve, its node only, of
// the primitive sphere's length.
TEST(CollapsedRow, CurveThroughARationalSpheresPoleIsOneClosedCurve) {
  const Vec3 c(-std::sqrt(2.0) + 1, 0, 1 + std::sqrt(2.0));  // the example's sphere centre
  const Cone cone(-c, Vec3::UnitZ(), kPi / 4, {0, 5});
  const TraceResult ref = trace_all(Problem(Sphere(Vec3::Zero(), 2), cone, PairKind::kParametricParametric), {});
  ASSERT_EQ(ref.curves.size(), 1u);
  const TraceResult r = trace_all(Problem(nurbs_sphere(2, 2), cone, PairKind::kParametricParametric), {});
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_NEAR(r.curves[0].length / ref.curves[0].length - 1, 0.0, 1e-8);
  ASSERT_EQ(r.singular_points.size(), 1u);
  EXPECT_EQ(r.singular_points[0].type, SingularType::kNode);
  EXPECT_THAT(r.singular_points[0].p, testing::IsNear((Vec3(1, 0, 1) - c), 1e-9));
}

// Issue 27: two loops, each through one pole of the rational sphere of radius 2 (the cylinder
// x^2 + y^2 = x inside it: z^2 = 4 - x). At each pole the two roots w, w + pi of the row give one
// branch whose tangent line lies along the chart's first axis, which rounds to either end of
// [0, pi); taken for two branches, their product made the pole a "tangential contact" and the loop
// was traced four times over. Reference length of a loop: int_0^2pi sqrt(1/4 + (sin t /
// (4 sqrt(7/2 - cos t / 2)))^2) dt = 3.19724445684831 (mpmath, 30 digits).
TEST(CollapsedRow, LoopsThroughBothPolesAreTracedOnceEach) {
  const Cylinder cylinder(Vec3(0.5, 0, 0), Vec3::UnitZ(), 0.5, {-3, 3});
  for (PairKind kind : {PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
    const TraceResult r = trace_all(Problem(nurbs_sphere(2, 2), cylinder, kind), {});
    ASSERT_EQ(r.curves.size(), 2u) << to_string(kind);
    for (const TracedCurve& c : r.curves) {
      EXPECT_TRUE(c.closed) << to_string(kind);
      EXPECT_NEAR(c.length / 3.19724445684831 - 1, 0.0, 1e-8) << to_string(kind);
    }
    EXPECT_TRUE(r.singular_points.empty()) << to_string(kind);
  }
}

}  // namespace
}  // namespace ssimarch
