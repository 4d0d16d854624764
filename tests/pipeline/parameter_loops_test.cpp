// A face's loops in its surface's parameter plane (pipeline/parameter_loops.hpp): the side of
// points far from the boundary, where face_region's 3D sign takes the nearest edge's side.
#include "ssimarch/pipeline/parameter_loops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

// Boundary curves given as functions on [0, 1] (their side is not used here).
class Curves final : public FaceRegion {
 public:
  explicit Curves(std::vector<std::function<Vec3(double)>> c) : c_(std::move(c)) {}
  Side side(const Vec3&, const Vec3&) const override { return {}; }
  int boundary_curves() const override { return static_cast<int>(c_.size()); }
  std::array<double, 2> boundary_range(int) const override { return {0.0, 1.0}; }
  Vec3 boundary_point(int i, double s) const override { return c_[static_cast<std::size_t>(i)](s); }
  std::string name() const override { return "test loops"; }

 private:
  std::vector<std::function<Vec3(double)>> c_;
};

std::function<Vec3(double)> segment(const Vec3& a, const Vec3& b) {
  return [a, b](double s) { return Vec3(a + s * (b - a)); };
}

bool inside(const ParameterLoops& l, const Surface& s, const Vec3& p) { return l.contains(*closest_parameters(s, p)); }

// A hexagon in z = 0 with a hole of radius 0.5; the plane's rectangle is the hexagon's box, so a
// point level with the leftmost vertex lies on the domain's edge (a ray through the vertex).
TEST(ParameterLoops, AHexagonWithAHole) {
  std::vector<Vec3> v;
  for (int k = 0; k < 6; ++k) v.emplace_back(std::cos(kPi + k * kPi / 3), std::sin(kPi + k * kPi / 3), 0.0);
  std::vector<std::function<Vec3(double)>> c;
  for (int k = 0; k < 6; ++k)
    c.push_back(segment(v[static_cast<std::size_t>(k)], v[static_cast<std::size_t>((k + 1) % 6)]));
  c.push_back([](double s) { return Vec3(0.5 * std::cos(2 * kPi * s), -0.5 * std::sin(2 * kPi * s), 0.0); });
  const Surface plane = Plane(Vec3::Zero(), Vec3::UnitZ(), ParamDomain{{-1, 1}, {-0.9, 0.9}});
  const std::optional<ParameterLoops> l = ParameterLoops::build(Curves(c), plane);
  ASSERT_TRUE(l.has_value());
  EXPECT_TRUE(inside(*l, plane, Vec3(0.75, 0, 0)));
  EXPECT_TRUE(inside(*l, plane, Vec3(0, 0.7, 0)));
  EXPECT_FALSE(inside(*l, plane, Vec3(0, 0, 0)));     // in the hole
  EXPECT_FALSE(inside(*l, plane, Vec3(-1, 0.4, 0)));  // level with the vertex (-1, 0), outside
  EXPECT_FALSE(inside(*l, plane, Vec3(-1, -0.4, 0)));
  EXPECT_FALSE(inside(*l, plane, Vec3(0.95, 0.8, 0)));                 // beyond an edge
  EXPECT_LE(l->resolution(), 0.5 * (1 - std::cos(kPi / 64)) + 1e-12);  // the hole's chords
  EXPECT_LE(l->edge_gap(), 1e-12);
}

// A quarter of the outer half of a torus (R = 2, r = 0.5): u in [0, pi/2], v in [-pi/2, pi/2].
// Both parameters are periodic; the loops span less than a turn in v, so the ray runs along v.
TEST(ParameterLoops, ATorusPatchAndTheRestOfTheTorus) {
  const Surface torus = Torus(Vec3::Zero(), Vec3::UnitZ(), 2.0, 0.5);
  auto at = [](double u, double v) {
    return Vec3((2 + 0.5 * std::cos(v)) * std::cos(u), (2 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v));
  };
  const Curves region(
      {[&](double s) { return at(s * kPi / 2, -kPi / 2); }, [&](double s) { return at(kPi / 2, -kPi / 2 + s * kPi); },
       [&](double s) { return at(kPi / 2 * (1 - s), kPi / 2); }, [&](double s) { return at(0, kPi / 2 - s * kPi); }});
  const std::optional<ParameterLoops> l = ParameterLoops::build(region, torus);
  ASSERT_TRUE(l.has_value());
  EXPECT_TRUE(inside(*l, torus, at(kPi / 4, 0)));
  EXPECT_TRUE(inside(*l, torus, at(0.1, 1.2)));
  EXPECT_FALSE(inside(*l, torus, at(kPi / 4, kPi)));   // the inner half
  EXPECT_FALSE(inside(*l, torus, at(kPi, 0)));         // half a turn round the ring
  EXPECT_FALSE(inside(*l, torus, at(-kPi / 2, 0.3)));  // a quarter turn the other way
  EXPECT_FALSE(inside(*l, torus, at(3 * kPi / 2 + 0.01, 0)));
}

}  // namespace
}  // namespace ssimarch
