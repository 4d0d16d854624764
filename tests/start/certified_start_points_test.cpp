// The certified start-point search (docs/topology.md): boundary roots and turning points of
// simple pairs against closed forms, a loop between sampling points, no intersection as a
// result, and uncertain regions when the budget is too small.
#include "ssimarch/start/certified_start_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "testing/nurbs_sphere.hpp"
#include "testing/surface_pairs.hpp"
#include "testing/simpson.hpp"
#include "ssimarch/trace/trace_all.hpp"

namespace ssimarch {
namespace {

using testing::implicit;
using testing::parametric;

// The certified roots' midpoints, sorted.
std::vector<std::vector<double>> roots_of(const RootSearchResult& r) {
  std::vector<std::vector<double>> out;
  for (const CertifiedRoot& c : r.roots) out.emplace_back(c.x.data(), c.x.data() + c.x.size());
  std::sort(out.begin(), out.end());
  return out;
}

void expect_roots(const RootSearchResult& r, std::vector<std::vector<double>> expected, double tol) {
  std::sort(expected.begin(), expected.end());
  auto got = roots_of(r);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    for (std::size_t j = 0; j < got[i].size(); ++j) EXPECT_NEAR(got[i][j], expected[i][j], tol) << "root " << i;
}

// The plane z = 0 over [-1, 1]^2 against a sphere about the origin: a circle of radius R.
Problem plane_sphere(double R) {
  return Problem(parametric("u", "v", "0", {-1, 1}, {-1, 1}),
                 implicit("x^2+y^2+z^2-" + std::to_string(R * R), Box{{-2, 2}, {-2, 2}, {-2, 2}}),
                 PairKind::kParametricImplicit);
}

TEST(CertifiedStartPoints, BoundaryRootsOfPlaneAndSphere) {
  const RootSearchOptions o;
  const Problem inside = plane_sphere(0.8);
  for (int i = 0; i < 2; ++i)
    for (bool upper : {false, true}) {
      RootSearchResult r = boundary_roots(inside, i, upper, o);
      EXPECT_TRUE(r.roots.empty());
      EXPECT_TRUE(r.complete());
    }
  // R = 1.2 crosses u = 1 at v = +-sqrt(0.44) and v = -1 at u = +-sqrt(0.44).
  const Problem crossing = plane_sphere(1.2);
  const double s = std::sqrt(0.44);
  RootSearchResult right = boundary_roots(crossing, 0, true, o);
  EXPECT_TRUE(right.complete());
  expect_roots(right, {{1, -s}, {1, s}}, 1e-12);
  RootSearchResult bottom = boundary_roots(crossing, 1, false, o);
  expect_roots(bottom, {{-s, -1}, {s, -1}}, 1e-12);
}

TEST(CertifiedStartPoints, BoundaryRootsOnTheSeamOfAPeriodicCylinder) {
  // Cylinder (cos u, sin u, v), u periodic, against the plane z = 0.5 x: the ellipse v = 0.5 cos u
  // crosses the seam u = 0 at v = 0.5 and never reaches v = +-1; u has no upper boundary.
  Problem P(parametric("cos(u)", "sin(u)", "v", {0, 2 * M_PI}, {-1, 1}, true, false),
            implicit("z-0.5*x", Box{{-2, 2}, {-2, 2}, {-2, 2}}), PairKind::kParametricImplicit);
  const RootSearchOptions o;
  expect_roots(boundary_roots(P, 0, false, o), {{0, 0.5}}, 1e-12);
  EXPECT_TRUE(boundary_roots(P, 0, true, o).roots.empty());
  EXPECT_TRUE(boundary_roots(P, 1, false, o).roots.empty());
  EXPECT_TRUE(boundary_roots(P, 1, true, o).complete());
  // Turning points: dv = 0 where h_u = 0.5 sin u = 0, i.e. (0, 0.5) and (pi, -0.5); du never 0.
  // (The copy of (0, 0.5) at u = 2 pi lies just beyond the double 2 pi that ends the box.)
  expect_roots(turning_points(P, 1, o), {{0, 0.5}, {M_PI, -0.5}}, 1e-12);
  EXPECT_TRUE(turning_points(P, 0, o).roots.empty());
  EXPECT_TRUE(turning_points(P, 0, o).complete());
}

TEST(CertifiedStartPoints, TurningPointsOfACircle) {
  const RootSearchOptions o;
  const Problem P = plane_sphere(0.8);
  RootSearchResult du = turning_points(P, 0, o);  // tangent's u component 0: h_v = 0, v = 0
  EXPECT_TRUE(du.complete());
  expect_roots(du, {{-0.8, 0}, {0.8, 0}}, 1e-12);
  expect_roots(turning_points(P, 1, o), {{0, -0.8}, {0, 0.8}}, 1e-12);
}

// Every undecided box lies within `r` of the point c.
void expect_undecided_near(const RootSearchResult& r, const std::vector<Vec3>& points, double tol) {
  for (const UndecidedBox& u : r.undecided) {
    EXPECT_FALSE(u.budget);
    Vec3 m(u.box[0].mid(), u.box[1].mid(), u.box[2].mid());
    double best = 1e300;
    for (const Vec3& c : points) best = std::min(best, (m - c).norm());
    EXPECT_LT(best, tol) << m.transpose();
  }
}

TEST(CertifiedStartPoints, TurningPointsOfVivianisCurve) {
  // Viviani (sin s, -1 - cos s, 2 sin(s/2)), tangent (cos s, sin s, cos(s/2)), node (0, -2, 0).
  Problem P(testing::sphere_g2_implicit(), testing::cylinder_f2_implicit(), PairKind::kImplicitImplicit);
  const RootSearchOptions o;
  const double r2 = std::sqrt(2.0);
  RootSearchResult dx = turning_points(P, 0, o);  // cos s = 0
  expect_roots(dx, {{-1, -1, -r2}, {-1, -1, r2}, {1, -1, -r2}, {1, -1, r2}}, 1e-12);
  EXPECT_FALSE(dx.undecided.empty());  // the node: a singular root, not certifiable
  expect_undecided_near(dx, {Vec3(0, -2, 0)}, 1e-4);
  RootSearchResult dz = turning_points(P, 2, o);  // cos(s/2) = 0
  expect_roots(dz, {{0, 0, -2}, {0, 0, 2}}, 1e-12);
  expect_undecided_near(dz, {Vec3(0, -2, 0)}, 1e-4);
  for (int i = 0; i < 3; ++i)
    for (bool upper : {false, true}) EXPECT_TRUE(boundary_roots(P, i, upper, o).roots.empty());
}

TEST(CertifiedStartPoints, TurningPointsOfTwoCylinders) {
  // x^2 + z^2 = 1 and y^2 + z^2 = 1: two ellipses crossing at (0, 0, +-1); tangent (-yz, -xz, xy).
  Problem P(implicit("x^2+z^2-1", Box{{-2, 2}, {-2, 2}, {-2, 2}}),
            implicit("y^2+z^2-1", Box{{-2, 2}, {-2, 2}, {-2, 2}}), PairKind::kImplicitImplicit);
  RootSearchResult dx = turning_points(P, 0, {});  // yz = 0 off the crossings: (+-1, +-1, 0)
  expect_roots(dx, {{-1, -1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}}, 1e-12);
  expect_undecided_near(dx, {Vec3(0, 0, -1), Vec3(0, 0, 1)}, 1e-4);
}

// A loop of radius 0.002 on a narrow bump, far from every sample of a 24 x 24 grid over
// [-5, 5]^2: Newton from the samples sees a flat function and never reaches it.
Problem tiny_loop() {
  return Problem(parametric("u", "v", "0", {-5, 5}, {-5, 5}),
                 implicit("z + 1 - 1.01*exp(-((x-0.3)^2+(y-0.2)^2)/0.0004)", Box{{-6, 6}, {-6, 6}, {-6, 6}}),
                 PairKind::kParametricImplicit);
}

TEST(CertifiedStartPoints, FindsASmallLoopThatSamplingMisses) {
  TraceOptions o;
  o.step_length = 0.0005;
  o.certified_start_points = false;
  TraceResult sampled = trace_all(tiny_loop(), o);
  EXPECT_TRUE(sampled.curves.empty());
  EXPECT_EQ(sampled.start_search.method, StartSearchMethod::kSampling);
  EXPECT_FALSE(sampled.start_search.certified);

  o.certified_start_points = true;
  TraceResult r = trace_all(tiny_loop(), o);
  EXPECT_EQ(r.start_search.method, StartSearchMethod::kCertified);
  EXPECT_TRUE(r.start_search.certified);
  EXPECT_TRUE(r.start_search.uncertain_regions.empty());
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  const double radius = 0.02 * std::sqrt(std::log(1.01));
  EXPECT_NEAR(r.curves[0].length / (2 * M_PI * radius), 1.0, 1e-6);
}

TEST(CertifiedStartPoints, DisjointSurfacesGiveNoCurveCertified) {
  // Concentric spheres of radii 1 and 0.5 (parametric-implicit): the search proves no root.
  Problem P(Sphere(Vec3::Zero(), 1.0), Sphere(Vec3::Zero(), 0.5), PairKind::kParametricImplicit);
  TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_TRUE(r.curves.empty());
  EXPECT_TRUE(r.start_search.certified);
  EXPECT_TRUE(r.start_search.uncertain_regions.empty());
}

TEST(CertifiedStartPoints, DisjointBoxesGiveNoCurveAndAMessage) {
  Problem P(implicit("x^2+y^2+z^2-1", Box{{-1, 1}, {-1, 1}, {-1, 1}}),
            implicit("(x-5)^2+y^2+z^2-1", Box{{4, 6}, {-1, 1}, {-1, 1}}), PairKind::kImplicitImplicit);
  EXPECT_TRUE(P.disjoint());
  TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_TRUE(r.curves.empty());
  EXPECT_TRUE(r.start_search.certified);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("no intersection"), std::string::npos);
}

TEST(CertifiedStartPoints, TinyBudgetReportsUncertainRegions) {
  TraceOptions o;
  o.start_box_budget = 2;
  TraceResult r = trace_all(plane_sphere(0.8), o);
  EXPECT_FALSE(r.start_search.certified);
  ASSERT_FALSE(r.start_search.uncertain_regions.empty());
  for (const UncertainRegion& u : r.start_search.uncertain_regions) {
    EXPECT_EQ(u.reason, UncertainReason::kBudgetSpent);
    EXPECT_EQ(u.box.size(), 2u);
  }
  EXPECT_FALSE(r.start_search.note.empty());
}

TEST(CertifiedStartPoints, CapsuleFallsBackToSamplingAndSaysSo) {
  Problem P(Capsule(Vec3::Zero(), Vec3::UnitZ(), 1.0, 2.0), Plane(Vec3::Zero(), Vec3::UnitZ(), {{-3, 3}, {-3, 3}}),
            PairKind::kParametricImplicit);
  EXPECT_FALSE(evaluates_on_intervals(P.first()));
  TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_EQ(r.start_search.method, StartSearchMethod::kSampling);
  EXPECT_NE(r.start_search.note.find("capsule"), std::string::npos);
  EXPECT_EQ(r.curves.size(), 1u);
}

// B-spline surfaces of several pieces are searched with a certificate against implicit surfaces
// (surface/piece_enclosure.hpp, issue 27 item 2): the rational sphere (4 x 2 pieces, C0 knots
// that are C1 arcs, a closed seam, two collapsed pole rows) cut by the plane z = 1/2 in a circle
// of radius sqrt(3)/2.
TEST(CertifiedStartPoints, NurbsSphereAgainstAPlaneIsCertified) {
  const Problem P(testing::nurbs_sphere(1, 2), Plane(Vec3(0, 0, 0.5), Vec3::UnitZ(), {{-2, 2}, {-2, 2}}),
                  PairKind::kParametricImplicit);
  const TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_EQ(r.start_search.method, StartSearchMethod::kCertified);
  EXPECT_TRUE(r.start_search.certified) << r.start_search.note;
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_NEAR(r.curves[0].length, 2 * std::numbers::pi * std::sqrt(0.75), 1e-8);
}

// The plane z = 1 + x through the sphere's north pole, a circle of radius 1/sqrt(2): the pole row
// is a face that the sphere maps to one point on the plane, a continuum of roots of its boundary
// system on which the search spent its whole budget; it is decided by a start point there
// (collapsed_face), so no boundary system is left uncertain. The turning systems' roots at the
// pole are singular (F_u vanishes on the row) and stay undecided: no certificate, said so.
TEST(CertifiedStartPoints, APoleRowOnTheOtherSurfaceIsDecidedByAStartPointThere) {
  const Problem P(testing::nurbs_sphere(1, 2), Plane(Vec3(0, 0, 1), Vec3(-1, 0, 1).normalized(), {{-2, 2}, {-2, 2}}),
                  PairKind::kParametricImplicit);
  const TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_EQ(r.start_search.method, StartSearchMethod::kCertified);
  for (const UncertainRegion& u : r.start_search.uncertain_regions)
    EXPECT_EQ(u.system.find("boundary"), std::string::npos) << u.system;
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_NEAR(r.curves[0].length, std::numbers::pi * std::sqrt(2.0), 1e-8);
}

// Two parametric surfaces with a B-spline of several pieces: its four-unknown systems spent the
// box budget on every NURBS peers case measured, so sampling, and the note says why.
TEST(CertifiedStartPoints, TwoParametricSurfacesWithAMultiPieceBSplineAreSampledAndSaySo) {
  const Problem P(testing::nurbs_sphere(1, 2), parametric("u", "v", "0.5", {-2, 2}, {-2, 2}),
                  PairKind::kParametricParametric);
  const TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_EQ(r.start_search.method, StartSearchMethod::kSampling);
  EXPECT_NE(r.start_search.note.find("four-unknown"), std::string::npos) << r.start_search.note;
  double length = 0;
  for (const TracedCurve& curve : r.curves) length += curve.length;
  EXPECT_NEAR(length, 2 * std::numbers::pi * std::sqrt(0.75), 1e-8);
}

// The plane z = v / 2 over (u, v) in [-2, 2]^2 against the cylinder x^2 + y^2 = 1 trimmed to
// z in [0.25, 1] (its implicit form carries the range as a slab, surface/trims.hpp). The curve
// u^2 + v^2 = 1 lies inside the parameter square; only the arc v >= 1/2, (cos s, sin s, sin s / 2)
// for s in [pi/6, 5 pi/6], is inside the trim. It meets no face of the square, and the tangent's
// u component vanishes at (+-1, 0), outside the trim: the arc's only boundary is the trim face
// z = 1/4, at (+-sqrt(3)/2, 1/2).
Problem plane_trimmed_cylinder() {
  return Problem(parametric("u", "v", "0.5*v", {-2, 2}, {-2, 2}),
                 Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1.0, {0.25, 1.0}), PairKind::kParametricImplicit);
}

TEST(CertifiedStartPoints, RootsOnTheTrimFaces) {
  const Problem P = plane_trimmed_cylinder();
  const RootSearchOptions o;
  const RootSearchResult lower = trim_face_roots(P, 0, false, o);
  EXPECT_TRUE(lower.complete());
  expect_roots(lower, {{-std::sqrt(3.0) / 2, 0.5}, {std::sqrt(3.0) / 2, 0.5}}, 1e-12);
  const RootSearchResult upper = trim_face_roots(P, 0, true, o);  // z = 1: v = 2, u^2 = -3
  EXPECT_TRUE(upper.complete());
  EXPECT_TRUE(upper.roots.empty());
  EXPECT_TRUE(trim_face_roots(P, 1, false, o).roots.empty());  // no second trim
}

using testing::simpson;

TEST(CertifiedStartPoints, ArcBoundedOnlyByATrimFace) {
  const Problem P = plane_trimmed_cylinder();
  const Tracer tracer(P, TraceOptions{});
  TraceStats stats;
  StartPointSearch search;
  const std::vector<VecX> starts = certified_start_points(tracer, &stats, &search);
  EXPECT_TRUE(search.certified);
  // The trim face's roots are start points themselves (not points beyond the trim moved onto it).
  int on_face = 0;
  for (const VecX& x : starts) on_face += std::fabs(P.point(x).z() - 0.25) < 1e-12 && std::fabs(x[1] - 0.5) < 1e-12;
  EXPECT_EQ(on_face, 2);

  const TraceResult r = trace_all(P, TraceOptions{});
  ASSERT_EQ(r.curves.size(), 1u);
  const TracedCurve& c = r.curves[0];
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.start_end, Termination::kLeftDomain);
  EXPECT_EQ(c.end_end, Termination::kLeftDomain);
  for (const CurvePoint* e : {&c.points.front(), &c.points.back()}) {
    EXPECT_NEAR(e->p.z(), 0.25, 1e-12);
    EXPECT_NEAR(std::fabs(e->p.x()), std::sqrt(3.0) / 2, 1e-10);
  }
  // Arc element |d/ds (cos s, sin s, sin s / 2)| = sqrt(1 + cos^2 s / 4).
  const double expected =
      simpson([](double s) { return std::sqrt(1 + 0.25 * std::cos(s) * std::cos(s)); }, M_PI / 6, 5 * M_PI / 6);
  EXPECT_NEAR(c.length, expected, 1e-6);
}

}  // namespace
}  // namespace ssimarch
