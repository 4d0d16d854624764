// The local curve h(s,t) of every pair kind against closed forms (thesis Ex. 18 graphs) and
// against the surfaces themselves at small (s, t) (docs/math/singular_local_curve.md §2).
#include "ssimarch/singular/local_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "singular/pairs.hpp"
#include "testing/matchers.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/singular/half_branches.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

using testing::graph_vs_plane_pi;
using testing::implicit_surface;
using testing::param;

constexpr const char* kEx18Difference = "0.2*u^4+0.1*v^4-0.3*u^2*v+0.1*v^2-0.2*v^3";

// h of thesis Ex. 18 at the tacnode (0,0) is the polynomial itself: (F - G).N with N = e_z.
void expect_ex18_polynomial(const LocalJet& h, double tol) {
  const LocalJet want = testing::germ({{4, 0, 0.2}, {0, 4, 0.1}, {2, 1, -0.3}, {0, 2, 0.1}, {0, 3, -0.2}});
  for (int i = 0; i < LocalJet::kSize; ++i) EXPECT_NEAR(h[i], want[i], tol) << "coefficient " << i;
}

TEST(LocalCurve, ParametricImplicitGraphIsTheHeightDifference) {
  Problem pr = graph_vs_plane_pi(kEx18Difference);
  LocalCurve c = local_curve(pr, VecX::Zero(2));
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  expect_ex18_polynomial(c.h, 1e-14);
}

TEST(LocalCurve, ParametricParametricEx18IsTheHeightDifference) {
  Problem pr(param("u", "v", "0.2*u^4+0.1*v^4"), param("u", "v", "0.3*u^2*v-0.1*v^2+0.2*v^3"),
             PairKind::kParametricParametric);
  LocalCurve c = local_curve(pr, VecX::Zero(4));
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  expect_ex18_polynomial(c.h, 1e-14);
  // G is a graph over the same plane: p(s,t) = s, q(s,t) = t exactly.
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  for (int i = 0; i < LocalJet::kSize; ++i) {
    EXPECT_NEAR(c.unknowns[2][i], S[i], 1e-14);
    EXPECT_NEAR(c.unknowns[3][i], T[i], 1e-14);
  }
}

// For a general pair: at (s,t) small, x(s,t) puts F - G along N with length h (pp), and h is g
// at the chart point (pi, ii). Truncation error O(|st|^11) ~ 1e-22 at |st| = 0.01.
TEST(LocalCurve, ParametricParametricEllipsoidsMatchTheSurfaces) {
  Problem pr(param("1.2*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
             param("0.9*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2.5*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
             PairKind::kParametricParametric);
  VecX x(4);
  x << M_PI / 2 + 0.1, M_PI / 2 - 0.2, M_PI / 2, M_PI / 2 + 0.1;  // off the curve on purpose
  LocalCurve c = local_curve(pr, x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  for (int i = 0; i < 3; ++i) {  // (s, t) are orthonormal tangent coordinates at first order
    EXPECT_NEAR(c.point[static_cast<std::size_t>(i)].d(0), c.e1[i], 1e-14);
    EXPECT_NEAR(c.point[static_cast<std::size_t>(i)].d(1), c.e2[i], 1e-14);
  }
  for (Vec2 st : {Vec2(0.01, 0.0), Vec2(-0.007, 0.006), Vec2(0.0, -0.012)}) {
    VecX y = c.unknowns_at(st);
    Vec3T<double> F = pr.first().point(y[0], y[1]), G = pr.second().point(y[2], y[3]);
    Vec3 d(F.x - G.x, F.y - G.y, F.z - G.z);
    const double h = evaluate(c.h, st).value;
    EXPECT_THAT(d, testing::IsNear(h * c.normal, 1e-13));
  }
}

TEST(LocalCurve, ImplicitImplicitVivianiMatchesTheSurfaces) {
  Surface sphere = implicit_surface("(x^2+y^2+z^2-4)/4"), cyl = implicit_surface("(x^2+(y+1)^2-1)/2");
  Problem pr(cyl, sphere, PairKind::kImplicitImplicit);
  VecX x(3);
  x << 0.05, -1.98, 0.04;
  LocalCurve c = local_curve(pr, x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  const double grad_g = (c.origin / 2).norm();  // |grad (|x|^2 - 4)/4| = |x|/2
  for (Vec2 st : {Vec2(0.01, 0.0), Vec2(-0.007, 0.006), Vec2(0.0, -0.012)}) {
    VecX P = c.unknowns_at(st);
    EXPECT_NEAR((P[0] * P[0] + (P[1] + 1) * (P[1] + 1) - 1) / 2, 0.0, 1e-14);  // on f = 0
    EXPECT_NEAR(evaluate(c.h, st).value, (P.squaredNorm() - 4) / 4 / grad_g, 1e-14);
  }
}

TEST(LocalCurve, ParametricImplicitVivianiMatchesTheSurfaces) {
  Problem pr(param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true), implicit_surface("(x^2+y^2+z^2-4)/4"),
             PairKind::kParametricImplicit);
  VecX x(2);
  x << 1.5 * M_PI + 0.03, 0.02;
  LocalCurve c = local_curve(pr, x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  const Vec3 P0 = c.origin;
  for (Vec2 st : {Vec2(0.01, 0.0), Vec2(-0.007, 0.006)}) {
    VecX uv = c.unknowns_at(st);
    Vec3 P(std::cos(uv[0]), std::sin(uv[0]) - 1, uv[1]);
    EXPECT_NEAR(evaluate(c.h, st).value, (P.squaredNorm() - 4) / 4 / (P0.norm() / 2), 1e-14);
  }
}

}  // namespace
}  // namespace ssimarch

namespace ssimarch {
namespace {

// Degenerate parametrisations (docs/math/singular_local_curve.md §6). The double cone x^2 + y^2 =
// z^2 (apex at the origin, both nappes) in its parametric form, against the cylinder
// (x - 1)^2 + y^2 = 1 through the apex: at the apex row v = 0, where F_u = 0, the local curve is
// built over the cylinder with the cone's implicit form, and the apex is a node of the curve in 3D
// with tangents (0, -1, -+1)/sqrt2 (examples/cone_apex_cylinder.json: z = 2 cos(t/2)).
TEST(LocalCurve, ParametricConeApexIsANodeOfTheCurveIn3D) {
  const Surface cone = Cone(Vec3::Zero(), Vec3::UnitZ(), M_PI / 4, Interval{-2.5, 2.5}, Vec3::UnitX());
  const Surface cyl = Cylinder(Vec3(1, 0, 0), Vec3::UnitZ(), 1.0, Interval{-3, 3}, Vec3::UnitX());
  const Problem P(cone, cyl, PairKind::kParametricImplicit);
  VecX x(2);
  x << M_PI / 2, 0.0;
  const LocalCurve c = local_curve(P, x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  EXPECT_TRUE(c.lifted());
  const Classification k = classify(c.h);
  EXPECT_EQ(k.type, SingularType::kNode);
  const auto hb = half_branches(P, c, k);
  ASSERT_EQ(hb.size(), 4u);
  const Vec3 t1 = Vec3(0, -1, -1).normalized(), t2 = Vec3(0, -1, 1).normalized();
  for (const HalfBranch& b : hb) {
    EXPECT_NEAR(std::max(std::fabs(b.tangent_3d.dot(t1)), std::fabs(b.tangent_3d.dot(t2))), 1.0, 1e-9);
    ASSERT_TRUE(b.exit_ok);
    EXPECT_LE(P.linearize(b.exit_x).h.norm(), 1e-12);
    // The exit's parameters are on the generator u = pi/2 or 3 pi/2 through the apex.
    EXPECT_NEAR(std::fabs(std::cos(b.exit_x[0])), 0.0, 0.05);
    ASSERT_GE(b.continuation, 0);
    EXPECT_NEAR(b.tangent_3d.dot(hb[static_cast<std::size_t>(b.continuation)].tangent_3d), -1.0, 1e-9);
  }
}

// OpenCASCADE bug21494_2 in parametric form: the cone (apex (0, 0, 10), half-angle atan 1.5, axis
// -z) touches the sphere of radius 10 at its north pole from inside; both parametrisations are
// degenerate there. The local curve over the sphere's implicit chart is definite: an isolated A1.
TEST(LocalCurve, ConeApexOnASpherePoleIsAnIsolatedPoint) {
  const Surface cone = Cone(Vec3(0, 0, 10), -Vec3::UnitZ(), std::atan(1.5), Interval{0, 10}, Vec3::UnitX());
  const Surface sphere = Sphere(Vec3::Zero(), 10.0);
  const Problem P(cone, sphere, PairKind::kParametricParametric);
  const std::vector<SingularLocation> at_poles = singular_points_at_poles(P);
  ASSERT_EQ(at_poles.size(), 1u);
  EXPECT_THAT(at_poles[0].point, testing::IsNear(Vec3(0, 0, 10), 1e-12));
  const LocalCurve c = local_curve(P, at_poles[0].x);
  ASSERT_EQ(c.status, LocalCurveStatus::kOk);
  const Classification k = classify(c.h);
  EXPECT_EQ(k.type, SingularType::kIsolated);
  EXPECT_EQ(k.ak, "A1");
}

}  // namespace
}  // namespace ssimarch
