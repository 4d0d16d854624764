// A sphere just above a plane, traced (no closed form; issue 13, "closure detection that works for
// curves of any size relative to the step"): gaps above the tracer's tolerance give the whole tiny
// circle, closed once, of length 2 pi sqrt(g (2R - g)) (the reference); a gap within the tolerance
// gives the contact point alone (through_singular.cpp, locate_near; trace_all.cpp,
// absorb_contact_loops). The closed form gives the circle there since the third wave (issue 26:
// tests/analytic/tangency_gap_test.cpp, a cut within the tolerance is the circle it cuts); the
// tracer's certificate still calls a loop within kIsolatedBoxRadius of its contact point that
// point (start/start_tolerances.hpp, docs/topology.md), which issue 26 leaves to do.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "ssimarch/surface/plane.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/trace/trace_all.hpp"

namespace ssimarch {
namespace {

TraceResult trace_sphere_above_plane(double gap) {
  const Problem P(Sphere(Vec3(0, 0, 1), 1), Plane(Vec3(0, 0, gap), Vec3::UnitZ(), ParamDomain{{-2, 2}, {-2, 2}}),
                  PairKind::kImplicitImplicit);
  TraceOptions o;
  o.max_points = 500;
  o.tolerance = 1e-12;  // stated: the gaps below are measured against it (the default is relative)
  return trace_all(P, o);
}

TEST(NearContact, TinyCirclesAboveTheToleranceCloseOnce) {
  for (double gap : {1e-9, 1e-10, 1e-11, 3e-12}) {
    SCOPED_TRACE(gap);
    const TraceResult r = trace_sphere_above_plane(gap);
    const double radius = std::sqrt(gap * (2 - gap));
    ASSERT_EQ(r.curves.size(), 1u);
    EXPECT_TRUE(r.curves[0].closed);
    EXPECT_TRUE(r.isolated_points.empty());
    EXPECT_TRUE(r.singular_points.empty());
    // The points are known to tolerance / sin(theta) across the curve, sin(theta) = radius:
    // 1e-12 / radius relative to the radius, and the chord sum is 1e-6 short at most.
    EXPECT_THAT(r.curves[0], testing::HasLength(2 * std::numbers::pi * radius,
                                                2 * std::numbers::pi * radius * (1e-6 + 1e-12 / (radius * radius))));
    for (const CurvePoint& p : r.curves[0].points) EXPECT_NEAR(p.p.z(), gap, 1e-12);
  }
}

TEST(NearContact, AGapWithinTheToleranceIsTheContactPoint) {
  for (double gap : {1e-12, 5e-13}) {
    SCOPED_TRACE(gap);
    const TraceResult r = trace_sphere_above_plane(gap);
    EXPECT_TRUE(r.curves.empty());
    EXPECT_TRUE(r.singular_points.empty());
    ASSERT_EQ(r.isolated_points.size(), 1u);
    EXPECT_NEAR(r.isolated_points[0].p.norm(), 0, 1e-12);
  }
}

}  // namespace
}  // namespace ssimarch
