// The tracer against exact curves: the thesis' torus curve C1 and Viviani's figure eight, for
// every pair kind (issue 2 acceptance tests).
#include "ssimarch/trace/trace_all.hpp"

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "testing/surface_pairs.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"

namespace ssimarch {
namespace {

// Every point within `tol` of the exact curve c(s), with s recovered from the point by `param`.
template <class Curve, class Param>
void expect_on_curve(const TracedCurve& c, Curve curve, Param param, double tol) {
  for (const auto& p : c.points) ASSERT_THAT(curve(param(p.p)), testing::IsNear(p.p, tol)) << p.p.transpose();
}

// No stretch traced twice: the curve parameters of consecutive points advance monotonically
// (mod the period, in the direction the tracer chose) and add up to exactly the curve's period
// for a closed curve. Returns the total advance, its sign removed.
template <class Param>
double total_parameter_advance(const TracedCurve& c, Param param, double period) {
  double total = 0, sign = 0;
  for (std::size_t i = 1; i < c.points.size(); ++i) {
    double d = param(c.points[i].p) - param(c.points[i - 1].p);
    d -= period * std::round(d / period);
    if (sign == 0) sign = d > 0 ? 1 : -1;
    EXPECT_GT(d * sign, 0.0) << "point " << i << " went backwards";
    total += d * sign;
  }
  return total;
}

double c1_param(const Vec3& p) { return std::atan2(p.y(), p.x()); }

void check_torus_curve(const Problem& P, double tolerance_on_surfaces) {
  TraceOptions o;
  o.step_length = 0.05;
  Tracer tracer(P, o);
  TraceResult r = trace_all(tracer, {testing::c1(0.3)});
  ASSERT_EQ(r.curves.size(), 1u);
  const TracedCurve& c = r.curves[0];
  EXPECT_TRUE(c.closed);
  EXPECT_NEAR(c.length / testing::kC1Length - 1, 0.0, 1e-6);
  expect_on_curve(c, testing::c1, c1_param, 1e-10);
  EXPECT_NEAR(total_parameter_advance(c, c1_param, 2 * M_PI), 2 * M_PI, 1e-12);
  EXPECT_EQ((c.points.front().p - c.points.back().p).norm(), 0.0);
  for (const auto& p : c.points) EXPECT_LE(P.linearize(p.x).distance, tolerance_on_surfaces);
  EXPECT_EQ(r.stats.points + 1, static_cast<long>(c.points.size()));  // the closing point repeats the first
}

TEST(Tracer, TorusCurveParametricParametric) {
  check_torus_curve(Problem(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric), 1e-12);
}

TEST(Tracer, TorusCurveParametricImplicit) {
  check_torus_curve(
      Problem(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit),
      1e-12);
}

TEST(Tracer, TorusCurveWithTaylorPredictor) {
  Problem P(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  TraceOptions o;
  o.step_length = 0.1;
  o.predictor = PredictorKind::kTaylor;
  TraceResult r = trace_all(P, o, {testing::c1(1.0)});
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_NEAR(r.curves[0].length / testing::kC1Length - 1, 0.0, 1e-6);
  // A fourth-order predictor needs fewer Newton updates than the tangent one.
  EXPECT_GT(r.stats.iterations[0] + r.stats.iterations[1], 0.9 * r.stats.points);
}

// The curve without its points at Viviani's node (0, -2, 0): the tracer puts the node itself on
// the curve (issue 10), and there both laps of the parameter meet, so the lap is undefined.
TracedCurve without_node(const TracedCurve& c) {
  TracedCurve out = c;
  out.points.clear();
  for (const auto& p : c.points)
    if ((p.p - Vec3(0, -2, 0)).norm() > 1e-9) out.points.push_back(p);
  return out;
}

// Viviani: s = atan2 of (x, -1 - y) ... recovered on the right lap from z = 2 sin(s/2).
double viviani_param(const Vec3& p) {
  double s = std::atan2(p.x(), -1 - p.y());  // in (-pi, pi]
  if (s < 0) s += 2 * M_PI;                  // [0, 2 pi)
  // z = 2 sin(s/2) >= 0 on the first lap, <= 0 on the second (s + 2 pi)
  return p.z() >= 0 ? s : s + 2 * M_PI;
}

void check_viviani(const Problem& P) {
  TraceOptions o;
  o.step_length = 0.05;
  Tracer tracer(P, o);
  TraceResult r = trace_all(tracer, {testing::viviani(M_PI / 2)});
  ASSERT_EQ(r.curves.size(), 1u);
  const TracedCurve& c = r.curves[0];
  EXPECT_TRUE(c.closed) << to_string(c.end_end) << ": " << c.end_message;
  EXPECT_NEAR(c.length / testing::kVivianiLength - 1, 0.0, 1e-6);
  expect_on_curve(c, testing::viviani, viviani_param, 1e-10);
  // Crossing the node at (0,-2,0) twice, staying on the incoming branch: the curve parameter
  // advances by exactly 4 pi, one full figure eight.
  EXPECT_NEAR(total_parameter_advance(without_node(c), viviani_param, 4 * M_PI), 4 * M_PI, 1e-12);
  ASSERT_EQ(r.singular_points.size(), 1u);
  EXPECT_EQ(r.singular_points[0].type, SingularType::kNode);
  EXPECT_THAT(r.singular_points[0].p, testing::IsNear(Vec3(0, -2, 0), 1e-10));
  for (const auto& p : c.points) EXPECT_LE(P.linearize(p.x).distance, 1e-10);
}

TEST(Tracer, VivianiCrossesItsNodeParametricImplicit) {
  check_viviani(Problem(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit));
}
TEST(Tracer, VivianiCrossesItsNodeParametricParametric) {
  check_viviani(Problem(testing::cylinder_f2(), testing::sphere_g2_parametric(), PairKind::kParametricParametric));
}
TEST(Tracer, VivianiCrossesItsNodeImplicitImplicit) {
  check_viviani(Problem(testing::sphere_g2_implicit(), testing::cylinder_f2_implicit(), PairKind::kImplicitImplicit));
}

TEST(Tracer, OpenCurveLandsExactlyOnTheDomainEdge) {
  // Cylinder x^2+(y+1)^2 = 1 with v in [-3,3] against the plane z = 0.5 y + 1 cut to u in [0, pi]
  Problem P(testing::parametric("cos(u)", "sin(u)-1", "v", {0, M_PI}, {-3, 3}),
            testing::implicit("z - 0.5*y - 1", Box{{-5, 5}, {-5, 5}, {-5, 5}}), PairKind::kParametricImplicit);
  TraceOptions o;
  o.step_length = 0.07;
  TraceResult r = trace_all(P, o, {Vec3(0, 0, 1)});
  ASSERT_EQ(r.curves.size(), 1u);
  const TracedCurve& c = r.curves[0];
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.start_end, Termination::kLeftDomain);
  EXPECT_EQ(c.end_end, Termination::kLeftDomain);
  // Ends at u = 0 and u = pi exactly (either order).
  double u0 = c.points.front().x[0], u1 = c.points.back().x[0];
  EXPECT_NEAR(std::min(u0, u1), 0.0, 1e-14);
  EXPECT_NEAR(std::max(u0, u1), M_PI, 1e-14);
  // Exact length: half an ellipse with semi-axes 1 and sqrt(1.25): the curve (cos u, sin u - 1, 0.5 sin u + 0.5).
  // Arc length integral of sqrt(sin^2 u + 1.25 cos^2 u) over [0, pi].
  double exact = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    double u = M_PI * (i + 0.5) / n;
    exact += std::sqrt(std::sin(u) * std::sin(u) + 1.25 * std::cos(u) * std::cos(u)) * M_PI / n;
  }
  EXPECT_NEAR(c.length / exact - 1, 0.0, 1e-6);
}

TEST(Tracer, FindsStartPointsAutomatically) {
  Problem P(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit);
  TraceOptions o;
  o.step_length = 0.05;
  TraceResult r = trace_all(P, o);
  ASSERT_GE(r.curves.size(), 1u);
  // The torus curve C1 is among them, traced once.
  int matches = 0;
  for (const auto& c : r.curves)
    if (c.closed && std::fabs(c.length / testing::kC1Length - 1) < 1e-6) ++matches;
  EXPECT_EQ(matches, 1);
}

TEST(Tracer, InvalidOptionsAreRejectedWithTheFieldName) {
  Problem P(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
  TraceOptions o;
  o.tolerance = -1;
  try {
    Tracer t(P, o);
    FAIL() << "accepted a negative tolerance";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("tolerance"), std::string::npos);
  }
}

}  // namespace
}  // namespace ssimarch
