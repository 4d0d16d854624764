// Curve jets by the implicit function theorem against the closed-form curves.
#include "ssimarch/problem/curve_jet.hpp"

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "testing/surface_pairs.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"

namespace ssimarch {
namespace {

// Frenet data of a curve c(s) (any parameter) from its first three derivatives.
struct Frenet {
  Vec3 t;
  double kappa, tau;
};
Frenet frenet(const Vec3& d1, const Vec3& d2, const Vec3& d3) {
  Vec3 c = d1.cross(d2);
  return {d1.normalized(), c.norm() / std::pow(d1.norm(), 3), c.dot(d3) / c.squaredNorm()};
}
Frenet frenet_c1(double s) {
  double c4 = std::cos(4 * s), s4 = std::sin(4 * s), c = std::cos(s), sn = std::sin(s);
  double r = 4 + c4, r1 = -4 * s4, r2 = -16 * c4, r3 = 64 * s4;
  Vec3 d1(r1 * c - r * sn, r1 * sn + r * c, 4 * c4);
  Vec3 d2(r2 * c - 2 * r1 * sn - r * c, r2 * sn + 2 * r1 * c - r * sn, -16 * s4);
  Vec3 d3(r3 * c - 3 * r2 * sn - 3 * r1 * c + r * sn, r3 * sn + 3 * r2 * c - 3 * r1 * sn - r * c, -64 * c4);
  return frenet(d1, d2, d3);
}

void expect_matches(const CurveJet<6>& j, const Frenet& f) {
  ASSERT_EQ(j.status, CurveJetStatus::kOk);
  Vec3 a1 = j.derivative(1), a2 = j.derivative(2), a3 = j.derivative(3);
  EXPECT_NEAR(a1.norm(), 1.0, 1e-13);
  EXPECT_NEAR(a1.dot(a2), 0.0, 1e-12);  // unit speed
  Frenet g = frenet(a1, a2, a3);
  EXPECT_THAT(g.t, testing::IsNear(f.t, 1e-12));
  EXPECT_NEAR(g.kappa, f.kappa, 1e-11);
  EXPECT_NEAR(g.tau, f.tau, 1e-10);
}

TEST(CurveJet, TorusCurveFromEveryPairKindMatchesFrenetValues) {
  for (double s : {0.0, 0.37, 1.9, 4.4}) {
    Vec3 p = testing::c1(s);
    Frenet f = frenet_c1(s);
    Problem pp(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
    VecX x(4);
    x << s, 0.0, 4 * s, M_PI / 2 - s;
    expect_matches(curve_jet<6>(pp, x, &f.t), f);
    Problem pi(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit);
    VecX y(2);
    y << s, 0.0;
    auto jy = curve_jet<6>(pi, y, &f.t);
    expect_matches(jy, f);
    EXPECT_THAT(jy.alpha[0], testing::IsNear(p, 1e-14));
  }
  // Seed value at C1(0): kappa = 0.512195, standard torsion -0.125436 (thesis Table 3.3).
  Problem pp(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  VecX x(4);
  x << 0.0, 0.0, 0.0, M_PI / 2;
  auto j = curve_jet<4>(pp, x);
  Vec3 c = j.derivative(1).cross(j.derivative(2));
  EXPECT_NEAR(j.derivative(2).norm(), 0.512195, 5e-7);
  EXPECT_NEAR(c.dot(j.derivative(3)) / c.squaredNorm(), -0.125436, 5e-7);
}

TEST(CurveJet, VivianiImplicitImplicitMatchesSeed004) {
  // Seed 004: unit sphere and x^2 + y^2 - x = 0 at (1/2, 1/2, sqrt2/2): kappa = 2 sqrt(39)/9,
  // tau = 6 sqrt(2)/13, t = (-sqrt6/3, 0, sqrt3/3) up to orientation.
  Problem P(testing::implicit("x^2+y^2+z^2-1", Box{{-2, 2}, {-2, 2}, {-2, 2}}),
            testing::implicit("x^2+y^2-x", Box{{-2, 2}, {-2, 2}, {-2, 2}}), PairKind::kImplicitImplicit);
  VecX x(3);
  x << 0.5, 0.5, std::sqrt(0.5);
  Vec3 hint(-1, 0, 1);
  auto j = curve_jet<5>(P, x, &hint);
  ASSERT_EQ(j.status, CurveJetStatus::kOk);
  EXPECT_THAT(j.derivative(1), testing::IsNear(Vec3(-std::sqrt(6.0) / 3, 0, std::sqrt(3.0) / 3), 1e-14));
  EXPECT_THAT(j.derivative(2), testing::IsNear(Vec3(-2.0 / 9, -4.0 / 3, -2 * std::sqrt(2.0) / 9), 1e-13));
  Vec3 c = j.derivative(1).cross(j.derivative(2));
  EXPECT_NEAR(j.derivative(2).norm(), 2 * std::sqrt(39.0) / 9, 1e-13);
  EXPECT_NEAR(std::fabs(c.dot(j.derivative(3)) / c.squaredNorm()), 6 * std::sqrt(2.0) / 13, 1e-12);
}

TEST(CurveJet, TaylorPolynomialErrorShrinksAtItsOrder) {
  Problem P(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
  // Viviani at s = pi/2: cylinder u = s - pi/2 = 0, v = 2 sin(pi/4).
  VecX x(2);
  x << 0.0, std::sqrt(2.0);
  auto j = curve_jet<4>(P, x);
  ASSERT_EQ(j.status, CurveJetStatus::kOk);
  // Distance of alpha(h) from the sphere ~ C h^5.
  double e1 = std::fabs(j.alpha_at(0.1).norm() - 2), e2 = std::fabs(j.alpha_at(0.05).norm() - 2);
  EXPECT_GT(e1 / e2, 20.0);  // 2^5 = 32 in the limit
  EXPECT_LT(e1 / e2, 45.0);
}

TEST(CurveJet, SingularPointIsReported) {
  // The sphere and cylinder touch at (0,-2,0): Viviani's node, J_H = 0 there.
  Problem P(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
  VecX x(2);
  x << -M_PI / 2, 0.0;
  EXPECT_EQ(curve_jet<3>(P, x).status, CurveJetStatus::kSingular);
}

}  // namespace
}  // namespace ssimarch
