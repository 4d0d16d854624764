// Tracer::march_until_event on its own: each event it reports, on the thesis' torus curve C1
// (closed, length 35.683...) and on a half ellipse cut off by the cylinder's domain edges.
#include <gtest/gtest.h>

#include <cmath>

#include "testing/surface_pairs.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/surface/torus.hpp"

namespace ssimarch {
namespace {

Problem torus_problem() {
  return Problem(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit);
}

// The point of the curve with unknowns x (on it), with its unit tangent.
CurvePoint on_curve(const Problem& P, const VecX& x) {
  return CurvePoint{x, P.point(x), curve_jet_dynamic(P, x, 1).tangent()};
}

VecX c1_unknowns(double s) {  // C1(s) = F1(s, 0)
  VecX x(2);
  x << s, 0.0;
  return x;
}

TraceOptions options() {
  TraceOptions o;
  o.step_length = 0.05;
  return o;
}

TEST(MarchUntilEvent, ClosesOnTheStartOfAClosedCurve) {
  const Problem P = torus_problem();
  const Tracer tracer(P, options());
  TraceStats stats;
  const CurvePoint start = on_curve(P, c1_unknowns(0.3));
  MarchResult r = tracer.march_until_event(start, Direction::kForward, tracer.limits(), &stats);
  EXPECT_EQ(r.event.kind, EventKind::kClosed);
  EXPECT_EQ(to_termination(r.event), Termination::kClosedLoop);
  EXPECT_EQ((r.points.back().p - start.p).norm(), 0.0);
  EXPECT_NEAR(r.length / testing::kC1Length - 1, 0.0, 1e-6);
  EXPECT_EQ(stats.points + 1, static_cast<long>(r.points.size()) - 1);  // neither end counted
}

TEST(MarchUntilEvent, StopsAtEitherBudgetAndSaysWhich) {
  const Problem P = torus_problem();
  const Tracer tracer(P, options());
  TraceStats stats;
  const CurvePoint start = on_curve(P, c1_unknowns(0.3));
  MarchLimits points = tracer.limits();
  points.max_points = 10;
  MarchResult r = tracer.march_until_event(start, Direction::kForward, points, &stats);
  EXPECT_EQ(r.event.kind, EventKind::kBudget);
  EXPECT_EQ(r.event.bound, BudgetBound::kPoints);
  EXPECT_EQ(to_termination(r.event), Termination::kMaxPoints);
  EXPECT_EQ(r.points.size(), 10u);
  MarchLimits length = tracer.limits();
  length.max_length = 1.0;
  r = tracer.march_until_event(start, Direction::kBackward, length, &stats);
  EXPECT_EQ(r.event.bound, BudgetBound::kLength);
  EXPECT_EQ(to_termination(r.event), Termination::kMaxLength);
  EXPECT_GE(r.length, 1.0);
  EXPECT_LT(r.length, 1.0 + 0.05 + 1e-12);
  // Backward: the first step goes against the start's tangent, and every tangent along travel.
  EXPECT_LT((r.points[1].p - start.p).dot(start.t), 0.0);
  EXPECT_EQ((r.points[0].t + start.t).norm(), 0.0);
}

TEST(MarchUntilEvent, StopsOnReachingACurveTracedBefore) {
  // 20 points ahead of C1(0.3); then backward from C1(0.3) all the way round the loop until
  // the march meets that piece's far end.
  const Problem P = torus_problem();
  const Tracer tracer(P, options());
  TraceStats stats;
  const CurvePoint start = on_curve(P, c1_unknowns(0.3));
  MarchLimits first = tracer.limits();
  first.max_points = 20;
  MarchResult piece = tracer.march_until_event(start, Direction::kForward, first, &stats);
  ASSERT_EQ(piece.points.size(), 20u);
  std::vector<TracedCurve> traced(1);
  traced[0].points = piece.points;
  MarchLimits rest = tracer.limits();
  rest.detect_closure = false;
  rest.traced = &traced;
  rest.traced_radius = 0.2 * tracer.spacing();
  MarchResult r = tracer.march_until_event(start, Direction::kBackward, rest, &stats);
  EXPECT_EQ(r.event.kind, EventKind::kReachedTracedCurve);
  EXPECT_TRUE(near_traced_curve(r.points.back().p, traced, rest.traced_radius));
  EXPECT_FALSE(near_traced_curve(r.points[r.points.size() - 2].p, traced, rest.traced_radius));
  // Together the two marches go round once: within one step of the curve's length.
  EXPECT_NEAR(r.length + piece.length, testing::kC1Length, 0.05);
}

TEST(MarchUntilEvent, LandsExactlyOnTheDomainEdge) {
  // Cylinder x^2+(y+1)^2 = 1 with u in [0, pi] against the plane z = 0.5 y + 1.
  Problem P(testing::parametric("cos(u)", "sin(u)-1", "v", {0, M_PI}, {-3, 3}),
            testing::implicit("z - 0.5*y - 1", Box{{-5, 5}, {-5, 5}, {-5, 5}}), PairKind::kParametricImplicit);
  TraceOptions o;
  o.step_length = 0.07;
  const Tracer tracer(P, o);
  TraceStats stats;
  VecX x(2);
  x << M_PI / 2, 1.0;  // the point (0, 0, 1)
  for (Direction d : {Direction::kForward, Direction::kBackward}) {
    MarchResult r = tracer.march_until_event(on_curve(P, x), d, tracer.limits(), &stats);
    EXPECT_EQ(r.event.kind, EventKind::kDomainEdge);
    const double u = r.points.back().x[0];
    EXPECT_NEAR(std::min(u, M_PI - u), 0.0, 1e-14);
  }
}

TEST(MarchUntilEvent, AStartAtASingularPointIsReported) {
  // Viviani's node (0, -2, 0): no tangent there.
  Problem P(testing::cylinder_f2(), testing::sphere_g2_implicit(), PairKind::kParametricImplicit);
  const Tracer tracer(P, options());
  TraceStats stats;
  VecX node(2);
  node << -M_PI / 2, 0.0;
  const CurvePoint start{node, P.point(node), Vec3(1, 0, 0)};
  MarchResult r = tracer.march_until_event(start, Direction::kForward, tracer.limits(), &stats);
  EXPECT_EQ(r.event.kind, EventKind::kSingularSuspected);
  EXPECT_EQ(r.points.size(), 1u);
}

}  // namespace
}  // namespace ssimarch
