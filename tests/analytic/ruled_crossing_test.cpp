// The nodes of ruled sections reported from the closed form (analytic/ruled_crossing.hpp) against
// the general machinery on the same pairs: the point located by singular/locate and classified
// with its half-branches by trace/singular_registry (local curve of degree 10, Milnor number,
// Puiseux expansions) — same type, position to 1e-12, same tangents up to order, same expansions.
#include "ssimarch/analytic/ruled_crossing.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "ssimarch/analytic/closed_form.hpp"
#include "ssimarch/singular/locate.hpp"
#include "ssimarch/surface/primitives.hpp"
#include "ssimarch/trace/singular_registry.hpp"

namespace ssimarch {
namespace {

// The general report at the singular point nearest `guess`.
SingularPointReport general_report(const Problem& P, const Vec3& guess, Vec3* located) {
  const SingularLocation at = locate_singular_point(P, VecX(guess));
  EXPECT_EQ(at.status, LocateStatus::kConverged);
  *located = at.point;
  SingularRegistry registry(P, 1e-6 * P.scale());
  const SingularNode& node = registry.node(registry.add(at));
  return make_report(node);
}

double term(const std::vector<SingularPointReport::HalfBranch::Term>& e, double exponent) {
  for (const auto& t : e)
    if (t.exponent == exponent) return t.coefficient;
  return 0.0;
}

// Every node of the closed form against the general report at the same point.
void expect_nodes_as_classified(const Problem& P, std::size_t nodes) {
  const auto r = closed_form_intersection(P, TraceOptions{});
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->pair, "ruled-quadric");
  ASSERT_EQ(r->result.singular_points.size(), nodes);
  for (const SingularPointReport& cf : r->result.singular_points) {
    Vec3 located;
    // Start the general search off the point, so that it finds the point itself.
    const SingularPointReport gen = general_report(P, cf.p + Vec3(2e-3, -1e-3, 1.5e-3), &located);
    EXPECT_THAT(located, testing::IsNear(cf.p, 1e-12 * std::max(1.0, P.scale())));
    EXPECT_EQ(cf.type, SingularType::kNode);
    EXPECT_EQ(gen.type, cf.type);
    EXPECT_EQ(gen.ak, cf.ak);
    EXPECT_EQ(gen.multiplicity, cf.multiplicity);
    EXPECT_EQ(gen.milnor, cf.milnor);
    EXPECT_FALSE(cf.curves.empty());
    ASSERT_EQ(cf.half_branches.size(), 4u);
    ASSERT_EQ(gen.half_branches.size(), 4u);
    std::vector<int> match(4, -1);
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = 0; j < 4; ++j)
        if (cf.half_branches[i].tangent.dot(gen.half_branches[j].tangent) > 1 - 1e-10) match[i] = static_cast<int>(j);
      ASSERT_GE(match[i], 0) << "half-branch " << i << " tangent " << cf.half_branches[i].tangent.transpose();
    }
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& a = cf.half_branches[i];
      EXPECT_NEAR(a.tangent.norm(), 1, 1e-14);
      EXPECT_NEAR(a.normal.dot(a.tangent), 0, 1e-14);
      const auto& b = gen.half_branches[static_cast<std::size_t>(match[i])];
      EXPECT_THAT(a.normal, testing::IsNear(b.normal, 1e-10));
      // Continuations correspond, and the expansions agree term by term (absent = 0).
      ASSERT_GE(a.continuation, 0);
      EXPECT_EQ(match[static_cast<std::size_t>(a.continuation)], b.continuation);
      for (double e = 2; e <= 6; ++e) {
        const double x = term(a.expansion, e), y = term(b.expansion, e);
        EXPECT_NEAR(x, y, 1e-7 * (1 + std::fabs(y))) << "exponent " << e;
      }
      // The leading term: the general code measures it at 1e-2 from the point (O(1e-2) relative).
      EXPECT_EQ(a.exponent, b.exponent);
      if (a.exponent > 0) {
        EXPECT_NEAR(a.coefficient, b.coefficient, 0.05 * std::fabs(b.coefficient));
      }
    }
  }
}

// A sphere of radius R touching `surface` from its inner side at p0 (the sphere's centre along
// -n at distance R, n the surface's unit gradient there): a node where the sphere curves less
// than the surface across it and more along it.
Sphere touching(const Vec3& p0, const Vec3& n, double R) { return Sphere(Vec3(p0 - R * n.normalized()), R); }

TEST(RuledCrossing, SteinmetzNodesAsClassified) {
  expect_nodes_as_classified(Problem(Cylinder(Vec3::Zero(), Vec3::UnitX(), 1, {-2, 2}),
                                     Cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-2, 2}), PairKind::kImplicitImplicit),
                             2);
}

TEST(RuledCrossing, EqualCylindersAtSixtyDegreesAsClassified) {
  expect_nodes_as_classified(Problem(Cylinder(Vec3(0.1, 0, 0.2), Vec3(std::cos(1.0), 0, std::sin(1.0)), 0.8, {-3, 3}),
                                     Cylinder(Vec3(0.1, 0, 0.2), Vec3::UnitZ(), 0.8, {-3, 3}), PairKind::kImplicitImplicit),
                             2);
}

TEST(RuledCrossing, VivianiNodeAsClassified) {
  expect_nodes_as_classified(Problem(Sphere(Vec3::Zero(), 2), Cylinder(Vec3(0, -1, 0), Vec3::UnitZ(), 1, {-3, 3}),
                                     PairKind::kImplicitImplicit),
                             1);
}

TEST(RuledCrossing, TiltedCylinderTouchingASphereAsClassified) {
  // Cylinder of radius 0.7 along (sin 0.4, 0.2 ..., cos 0.4) through p0 = (0, -1, 0.3) + ...: the
  // sphere of radius 2.3 touching it from inside at p0 curves less across the cylinder and more along it.
  const Vec3 axis = Vec3(std::sin(0.4), 0.1, std::cos(0.4)).normalized();
  const Vec3 across = axis.cross(Vec3(1, 0, 0)).normalized();
  const Vec3 centre(0.2, -0.3, 0.1);
  const Vec3 p0 = centre + 0.7 * across;
  expect_nodes_as_classified(Problem(touching(p0, across, 2.3), Cylinder(centre, axis, 0.7, {-4, 4}), PairKind::kImplicitImplicit), 1);
}

TEST(RuledCrossing, CylinderInsideAnEllipsoidAsClassified) {
  // x^2/1.44 + y^2/2.56 + z^2/4 = 1 and the z-cylinder of radius 0.6 touching it at (0, 1.6, 0):
  // more curved across (1/0.6 > 1.6/1.44), straight along: a node.
  expect_nodes_as_classified(Problem(Ellipsoid(Vec3::Zero(), {1.2, 1.6, 2}), Cylinder(Vec3(0, 1.0, 0), Vec3::UnitZ(), 0.6, {-3, 3}),
                                     PairKind::kImplicitImplicit),
                             1);
}

TEST(RuledCrossing, SphereTouchingAConeAsClassified) {
  // Along the cone's rulings (no cylinder in the pair): cone z^2 tan^2(0.5) = x^2 + y^2 about
  // (0.1, 0.2, 1), apex (0, 0, -2); a sphere touching it from inside at the point of the ruling
  // at h = 2, with R > rho / cos(alpha) (less curved across than the cone).
  const Vec3 apex(0, 0, -2), axis = Vec3(0.1, 0.2, 1).normalized();
  const double alpha = 0.5, h = 2;
  const Vec3 e0 = axis.cross(Vec3::UnitX()).normalized();
  const Vec3 p0 = apex + h * axis + h * std::tan(alpha) * e0;
  const Vec3 n = (std::cos(alpha) * e0 - std::sin(alpha) * axis);  // outward unit normal there
  const double R = 1.5 * h * std::tan(alpha) / std::cos(alpha);
  expect_nodes_as_classified(Problem(Cone(apex, axis, alpha, {-5, 5}), touching(p0, n, R), PairKind::kImplicitImplicit), 1);
}

TEST(RuledCrossing, RootsOfMultiplicityFourAreLeftToTheGeneralClassifier) {
  // On the rulings (cos s, sin s, t) of x^2 + y^2 = 1, the plane pair z^2 = (1 - x)^2 gives
  // t^2 - (1 - cos s)^2 = 0: Delta = 4 (1 - cos s)^2 has a root of multiplicity 4 at s = 0, where
  // the two ellipses z = +-(1 - x) touch (a tacnode at (1, 0, 0)). The closed form does not vouch
  // for it (the caller classifies such points by the general machinery); the node beside it does.
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), 1, {-3, 3});
  Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();  // z^2 - (1 - x)^2 = -x^2 + 2x + z^2 - 1
  Q(0, 0) = -1, Q(0, 3) = Q(3, 0) = 1, Q(2, 2) = 1, Q(3, 3) = -1;
  const RuledCurves rc(*rulings_of(Surface(cylinder)), Q);
  const auto section = rc.section();
  ASSERT_TRUE(section.has_value());
  ASSERT_EQ(section->crossings.size(), 1u);
  EXPECT_NEAR(std::remainder(section->crossings[0], 2 * M_PI), 0, 1e-6);
  const Problem P(Sphere(Vec3::Zero(), 2), cylinder, PairKind::kImplicitImplicit);
  EXPECT_FALSE(ruled_node(P, rc, section->crossings[0], section->scale).has_value());
  // z^2 = (1 - x)^2 / 4 - ... : the planes z = +-(x - 0.5) cut the cylinder in two ellipses that
  // cross at (0.5, +-sqrt(3)/2, 0): two roots of multiplicity 2, two nodes.
  Q(0, 3) = Q(3, 0) = 0.5, Q(3, 3) = -0.25;  // z^2 - (x - 0.5)^2
  const RuledCurves crossing(*rulings_of(Surface(cylinder)), Q);
  const auto nodes = crossing.section();
  ASSERT_TRUE(nodes.has_value());
  ASSERT_EQ(nodes->crossings.size(), 2u);
  for (double theta : nodes->crossings) {
    const auto r = ruled_node(P, crossing, theta, nodes->scale);
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(r->p.x(), 0.5, 1e-14);
    EXPECT_NEAR(std::fabs(r->p.y()), std::sqrt(0.75), 1e-14);
    EXPECT_NEAR(r->p.z(), 0, 1e-14);
    // The ellipses' tangents there: along (dx, dy, dz) with dz = +-dx on the circle's tangent.
    for (const auto& h : r->half_branches) EXPECT_NEAR(std::fabs(h.tangent.z()), std::fabs(h.tangent.x()), 1e-13);
  }
}

}  // namespace
}  // namespace ssimarch
