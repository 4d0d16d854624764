// The slabs trimming a primitive's implicit form (surface/trims.hpp): a cylinder's axial range,
// a plane's and a paraboloid's parameter rectangle (u, v are the coordinates along e0, e1), none
// for closed surfaces. A point of the parametric form inside its domain lies in every slab, one
// outside the domain in some direction lies outside that slab.
#include "ssimarch/surface/trims.hpp"

#include <gtest/gtest.h>

#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

Vec3 at(const Surface& s, double u, double v) {
  const Vec3T<double> p = s.point(u, v);
  return {p.x, p.y, p.z};
}

bool in_every(const std::vector<Slab>& slabs, const Vec3& p) {
  for (const Slab& s : slabs)
    if (!s.contains(p, 1e-12)) return false;
  return true;
}

TEST(ImplicitTrims, ARectangleIsTwoSlabsAlongItsAxes) {
  const Vec3 normal = Vec3(1, 2, 2).normalized();
  const Surface plane(Plane(Vec3(0.5, -1, 2), normal, ParamDomain{{-1, 3}, {0.25, 2}}, Vec3(0, 0, 1)));
  const Surface bowl(Paraboloid(Vec3(1, 1, 1), Vec3(0, 0, 1), 0.5, 0.25, ParamDomain{{-2, 1}, {-0.5, 0.5}}));
  for (const Surface* s : {&plane, &bowl}) {
    const std::vector<Slab> slabs = implicit_trims(*s);
    ASSERT_EQ(slabs.size(), 2u);
    const ParamDomain& d = s->domain();
    for (double a : {0.0, 0.5, 1.0})
      for (double b : {0.0, 0.5, 1.0})
        EXPECT_TRUE(in_every(slabs, at(*s, d.u.lo + a * d.u.width(), d.v.lo + b * d.v.width())));
    // 1e-6 past each edge of the rectangle: outside that edge's slab only.
    EXPECT_FALSE(in_every(slabs, at(*s, d.u.lo - 1e-6, d.v.lo)));
    EXPECT_FALSE(in_every(slabs, at(*s, d.u.hi + 1e-6, d.v.hi)));
    EXPECT_FALSE(in_every(slabs, at(*s, d.u.lo, d.v.lo - 1e-6)));
    EXPECT_FALSE(in_every(slabs, at(*s, d.u.hi, d.v.hi + 1e-6)));
  }
}

TEST(ImplicitTrims, AnAxialRangeIsOneSlabAndClosedSurfacesHaveNone) {
  const Surface cylinder(Cylinder(Vec3(1, 0, 0), Vec3(0, 1, 0), 2, Interval{-1, 4}));
  const std::vector<Slab> slabs = implicit_trims(cylinder);
  ASSERT_EQ(slabs.size(), 1u);
  EXPECT_NEAR(std::abs(slabs[0].normal.y()), 1.0, 1e-15);
  EXPECT_TRUE(in_every(slabs, at(cylinder, 0.3, 3.9)));
  EXPECT_FALSE(in_every(slabs, at(cylinder, 0.3, 4 + 1e-6)));
  EXPECT_TRUE(implicit_trims(Surface(Sphere(Vec3::Zero(), 1))).empty());
}

}  // namespace
}  // namespace ssimarch
