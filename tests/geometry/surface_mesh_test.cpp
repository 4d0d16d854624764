// Display meshes against closed forms: vertices on the surface, areas converging to 4 pi r^2 (sphere)
// and 4 pi^2 R r (torus), both for the parametric grid and for marching tetrahedra.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "ssimarch/core/error.hpp"
#include "ssimarch/geometry/surface_mesh.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

Box cube(double h) { return {{-h, h}, {-h, h}, {-h, h}}; }

TEST(SurfaceMesh, MarchingSphereVerticesLieOnTheSphereAndAreaConverges) {
  const Vec3 c(0.3, -0.2, 0.1);
  const double r = 1.7;
  const Surface s = Sphere(c, r);
  double previous_error = 1e300;
  for (int cells : {12, 24, 48}) {
    const TriangleMesh m = mesh_implicit(s, {{-2, 2.5}, {-2.5, 2}, {-2, 2.2}}, cells);
    ASSERT_GT(m.triangles.size(), 100u);
    for (const Vec3& p : m.vertices) ASSERT_NEAR((p - c).norm(), r, 1e-10);
    const double error = std::fabs(m.area() / (4 * kPi * r * r) - 1);
    EXPECT_LT(error, previous_error) << cells;  // inscribed triangles: O(h^2)
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.01);
}

TEST(SurfaceMesh, MarchingTrianglesPointOutward) {
  const Surface s = Sphere(Vec3::Zero(), 1.0);
  const TriangleMesh m = mesh_implicit(s, cube(1.3), 16);
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    EXPECT_GE((b - a).cross(c - a).dot(a + b + c), 0.0);  // f = |p|^2 - 1 grows outward
  }
}

TEST(SurfaceMesh, MarchingMeshIsClosedInsideTheBox) {
  // Every edge of a closed surface's mesh borders exactly two triangles (no cracks between cubes).
  const TriangleMesh m = mesh_implicit(Sphere(Vec3::Zero(), 1.0), cube(1.21), 20);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  for (const auto& [edge, n] : uses) ASSERT_EQ(n, 2);
}

TEST(SurfaceMesh, TorusAreaBothWays) {
  const double R = 3, r = 1;
  const Surface s = Torus(Vec3::Zero(), Vec3::UnitZ(), R, r);
  const double exact = 4 * kPi * kPi * R * r;
  const TriangleMesh grid = mesh_parametric(s, 128, 64);
  EXPECT_NEAR(grid.area() / exact, 1.0, 2e-3);
  for (const Vec3& p : grid.vertices) ASSERT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()), r, 1e-12);
  const TriangleMesh marched = mesh_implicit(s, {{-4.2, 4.2}, {-4.2, 4.2}, {-1.2, 1.2}}, 64);
  for (const Vec3& p : marched.vertices) ASSERT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()), r, 1e-9);
  EXPECT_NEAR(marched.area() / exact, 1.0, 0.02);
}

TEST(SurfaceMesh, SurfaceMeshPicksTheFormAndRejectsBadResolution) {
  const Surface s = Sphere(Vec3::Zero(), 2.0);
  const TriangleMesh m = surface_mesh(s, {.grid = 8, .cells = 8});
  EXPECT_EQ(m.vertices.size(), 81u);  // parametric: (8 + 1)^2 grid points
  EXPECT_THROW(mesh_parametric(s, 0, 4), InputError);
  EXPECT_THROW(mesh_implicit(s, cube(2.5), 1), InputError);
}

}  // namespace
}  // namespace ssimarch
