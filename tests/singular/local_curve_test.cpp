// The local curve h(s,t) of every pair kind against closed forms (thesis Ex. 18 graphs) and
// against the surfaces themselves at small (s, t) (docs/math/singular_local_curve.md §2).
#include "ssimarch/singular/local_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "singular/pairs.hpp"

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
    EXPECT_NEAR((d - h * c.normal).norm(), 0.0, 1e-13);
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
