// Coincident surfaces (pipeline/coincidence.hpp): samples of one surface measured against the
// other. The full test wants two rows of its 16 x 16 grid on the other surface; the probe before
// tracing tries a 4 x 4 grid of each surface in turn, so a short surface lying on a long one is
// found from its own samples.
#include "ssimarch/pipeline/coincidence.hpp"

#include <gtest/gtest.h>

#include "ssimarch/surface/primitives.hpp"
#include "testing/nurbs_cylinder.hpp"

namespace ssimarch {
namespace {

Surface cylinder(double h0, double h1, double radius = 1) {
  return Cylinder(Vec3::Zero(), Vec3::UnitZ(), radius, Interval{h0, h1});
}

TEST(Coincidence, TheSharedRegionIsWhereTheSamplesLieOnTheOtherSurface) {
  // The long cylinder's samples at z in [0, 1] lie on the short one: 4 rows of 16 of [-3, 1].
  const Problem p(cylinder(-3, 1), cylinder(0, 1), PairKind::kParametricParametric);
  const std::optional<Coincidence> c = find_coincidence(p, 1e-9);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->samples, 256);
  EXPECT_EQ(c->shared, 64);
  EXPECT_GT(c->region.z.lo, 0.0);
  EXPECT_LT(c->region.z.hi, 1.0);
  EXPECT_LE(c->max_distance, 1e-12);
  // A coaxial cylinder 1e-6 wider shares nothing at 1e-9; the same one does at 1e-5.
  const Problem wider(cylinder(-3, 1), cylinder(0, 1, 1 + 1e-6), PairKind::kParametricParametric);
  EXPECT_FALSE(find_coincidence(wider, 1e-9).has_value());
  EXPECT_TRUE(find_coincidence(wider, 1e-5).has_value());
}

TEST(Coincidence, TheProbeFindsAShortSurfaceOnALongOneFromItsOwnSamples) {
  // One coarse row of the long cylinder's 4 x 4 grid (z = -2.5, ..., 0.5) lies on the short
  // one: not enough; all of the short one's samples lie on the long one.
  const Problem p(cylinder(-3, 1), cylinder(0.2, 0.8), PairKind::kParametricParametric);
  EXPECT_FALSE(find_coincidence(p.first(), p.second(), p.first().box(), 1e-9, kCoincidenceProbeGrid).has_value());
  const std::optional<Coincidence> c = probe_coincidence(p, 1e-9);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->shared, c->samples);  // the short cylinder's full grid
  EXPECT_GT(c->region.z.lo, 0.2);
  EXPECT_LT(c->region.z.hi, 0.8);
  // Crossing cylinders share a curve, not a region.
  const Problem crossing(cylinder(-2, 2), Surface(Cylinder(Vec3::Zero(), Vec3::UnitX(), 1, Interval{-2, 2})),
                         PairKind::kParametricParametric);
  EXPECT_FALSE(probe_coincidence(crossing, 1e-9).has_value());
}

TEST(Coincidence, SamplesFarFromTheOtherSurfacesEnclosuresAreTheOnlyOnesSkipped) {
  // Samples outside the other surface's cell enclosures skip their closest-point solve: the
  // counts are those of the solves. A rational B-spline as the other surface (its enclosures by
  // its pieces' nets): the long cylinder's rows at z in [-1, 1], 8 of 16.
  const Problem on_spline(cylinder(-3, 1), testing::quarter_arc_cylinder(), PairKind::kParametricParametric);
  const std::optional<Coincidence> c = find_coincidence(on_spline, 1e-9);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->samples, 256);
  EXPECT_EQ(c->shared, 128);
  EXPECT_LE(c->max_distance, 1e-12);
  // The B-spline's own samples on a short cylinder (z in [0, 1]): its upper 8 rows.
  const Problem spline_on(testing::quarter_arc_cylinder(), cylinder(0, 1), PairKind::kParametricParametric);
  const std::optional<Coincidence> d = find_coincidence(spline_on, 1e-9);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->shared, 128);
  // 1e-6 apart: nothing shared at 1e-9, everything where the tolerance holds the gap.
  const Problem apart(cylinder(-1, 1, 1 + 1e-6), testing::quarter_arc_cylinder(), PairKind::kParametricParametric);
  EXPECT_FALSE(find_coincidence(apart, 1e-9).has_value());
  const std::optional<Coincidence> e = find_coincidence(apart, 1e-5);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->shared, 256);
}

}  // namespace
}  // namespace ssimarch
