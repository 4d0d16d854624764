// Points of a face's boundary on another surface (pipeline/edge_surface_points.hpp): the unit
// circle z = 0 as the boundary, met by planes, a thin cylinder and a sphere; references are the
// closed forms of circle against plane and circle against circle.
#include "ssimarch/pipeline/edge_surface_points.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

// The unit circle about the z axis as one boundary curve (its side is not used here).
class UnitCircle final : public FaceRegion {
 public:
  Side side(const Vec3& p, const Vec3&) const override { return {1.0 - p.norm(), p.normalized()}; }
  int boundary_curves() const override { return 1; }
  std::array<double, 2> boundary_range(int) const override { return {0.0, 2 * std::numbers::pi}; }
  Vec3 boundary_point(int, double s) const override { return {std::cos(s), std::sin(s), 0.0}; }
  std::string name() const override { return "the unit circle"; }
};

const EdgeSurfaceTolerances kTolerances{1e-12, 1e-6};

Surface plane_x(double x) { return Plane(Vec3(x, 0, 0), Vec3::UnitX(), ParamDomain{{-3, 3}, {-3, 3}}); }

// The points sorted by y, to compare with the closed forms.
std::vector<Vec3> by_y(std::vector<Vec3> p) {
  std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a.y() < b.y(); });
  return p;
}

TEST(EdgeSurfacePoints, APlaneAcrossTheCircleMeetsItTwice) {
  const std::vector<Vec3> p = by_y(edge_surface_points(UnitCircle(), plane_x(0.3), kTolerances));
  ASSERT_EQ(p.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(p[static_cast<std::size_t>(k)].x(), 0.3, 1e-12);
    EXPECT_NEAR(p[static_cast<std::size_t>(k)].y(), (k == 0 ? -1 : 1) * std::sqrt(1 - 0.09), 1e-12);
  }
}

// The plane x = 1 - d meets the circle at angles +-acos(1 - d): 0.089 apart for d = 1e-3, 0.0028
// for d = 1e-6, both inside one of the 16 initial pieces (0.39), found by the Lipschitz split;
// at x = 1 + d none.
TEST(EdgeSurfacePoints, TwoPointsWithinOnePieceAreBothFound) {
  for (double d : {1e-3, 1e-6}) {
    SCOPED_TRACE(d);
    const std::vector<Vec3> p = by_y(edge_surface_points(UnitCircle(), plane_x(1 - d), kTolerances));
    ASSERT_EQ(p.size(), 2u);
    const double y = std::sqrt(1 - (1 - d) * (1 - d));
    EXPECT_NEAR(p[0].y(), -y, 1e-10);
    EXPECT_NEAR(p[1].y(), y, 1e-10);
    EXPECT_TRUE(edge_surface_points(UnitCircle(), plane_x(1 + d), kTolerances).empty());
  }
}

// A cylinder of radius 0.05 about (0.98, 0, z) cuts a short arc out of the circle: the
// circle-circle points x = (1 + 0.98^2 - 0.05^2) / (2 0.98).
TEST(EdgeSurfacePoints, AThinCylinderCutsAShortArc) {
  const Surface thin = Cylinder(Vec3(0.98, 0, 0), Vec3::UnitZ(), 0.05, Interval{-1, 1});
  const std::vector<Vec3> p = by_y(edge_surface_points(UnitCircle(), thin, kTolerances));
  ASSERT_EQ(p.size(), 2u);
  const double x = (1 + 0.98 * 0.98 - 0.05 * 0.05) / (2 * 0.98);
  for (const Vec3& q : p) {
    EXPECT_NEAR(q.x(), x, 1e-12);
    EXPECT_NEAR(std::abs(q.y()), std::sqrt(1 - x * x), 1e-11);
  }
}

// A boundary lying on the surface (a rod in a hole of its radius): the search ends, every point
// it returns is on the surface, and none is closer than the band to another.
TEST(EdgeSurfacePoints, ABoundaryOnTheSurfaceEnds) {
  const Surface sphere = Sphere(Vec3::Zero(), 1.0);
  const std::vector<Vec3> p = edge_surface_points(UnitCircle(), sphere, kTolerances);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p[i].norm(), 1.0, 1e-12);
    for (std::size_t j = 0; j < i; ++j) EXPECT_GT((p[i] - p[j]).norm(), kTolerances.band);
  }
}

}  // namespace
}  // namespace ssimarch
