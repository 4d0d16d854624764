// Half-branches and their pairing at the thesis' singular points and Viviani's node, against
// closed-form tangents and branch expansions (thesis ch. 5 examples, issue 10 "Tracing through").
#include "ssimarch/singular/half_branches.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "singular/pairs.hpp"
#include "ssimarch/singular/locate.hpp"

namespace ssimarch {
namespace {

struct AtPoint {
  LocalCurve curve;
  Classification kind;
  std::vector<HalfBranch> hb;
};

AtPoint analyse(const Problem& pr, VecX guess) {
  SingularLocation s = locate_singular_point(pr, guess);
  EXPECT_EQ(s.status, LocateStatus::kConverged);
  AtPoint a;
  a.curve = local_curve(pr, s.x);
  a.kind = classify(a.curve.h, {.length = a.curve.germ_length});
  a.hb = half_branches(pr, a.curve, a.kind);
  return a;
}

VecX uv(double u, double v, int dim) {
  VecX x = VecX::Zero(dim);
  x[0] = u, x[1] = v;
  if (dim == 4) x[2] = u, x[3] = v;
  return x;
}

// Every exit point is on the curve, about epsilon germ lengths away (HalfBranchOptions::epsilon),
// and its direction points outwards.
void expect_good_exits(const Problem& pr, const AtPoint& a) {
  for (const HalfBranch& b : a.hb) {
    ASSERT_TRUE(b.exit_ok);
    EXPECT_LE(pr.linearize(b.exit_x).h.norm(), 1e-13);
    const double d = (b.exit_point - a.curve.origin).norm();
    EXPECT_GT(d, 0.5 * HalfBranchOptions{}.epsilon * a.curve.germ_length);
    EXPECT_LT(d, 0.2);
    EXPECT_GT(b.direction.dot(b.exit_point - a.curve.origin), 0.9 * d);
    EXPECT_GT(b.direction.dot(b.tangent_3d), 0.9);
  }
}

void expect_paired(const std::vector<HalfBranch>& hb) {
  for (std::size_t i = 0; i < hb.size(); ++i) {
    ASSERT_GE(hb[i].continuation, 0);
    EXPECT_EQ(hb[static_cast<std::size_t>(hb[i].continuation)].continuation, static_cast<int>(i));
    EXPECT_NE(hb[i].continuation, static_cast<int>(i));
  }
}

TEST(HalfBranches, VivianiNodeStraightAcross) {
  // Viviani's curve (sin s, -1 - cos s, 2 sin(s/2)) passes the node (0,-2,0) at s = 0 and 2 pi
  // with tangents (1,0,1)/sqrt2 and (1,0,-1)/sqrt2.
  Problem pr(testing::param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true),
             testing::implicit_surface("(x^2+y^2+z^2-4)/4"), PairKind::kParametricImplicit);
  AtPoint a = analyse(pr, uv(1.5 * M_PI + 0.03, 0.02, 2));
  EXPECT_EQ(a.kind.type, SingularType::kNode);
  ASSERT_EQ(a.hb.size(), 4u);
  expect_paired(a.hb);
  expect_good_exits(pr, a);
  const Vec3 t1 = Vec3(1, 0, 1).normalized(), t2 = Vec3(1, 0, -1).normalized();
  for (const HalfBranch& b : a.hb) {
    EXPECT_NEAR(std::max(std::fabs(b.tangent_3d.dot(t1)), std::fabs(b.tangent_3d.dot(t2))), 1.0, 1e-12);
    const HalfBranch& c = a.hb[static_cast<std::size_t>(b.continuation)];
    EXPECT_NEAR(b.tangent_3d.dot(c.tangent_3d), -1.0, 1e-12);  // straight across
  }
}

TEST(HalfBranches, VivianiNodeImplicitImplicitExits) {
  Problem pr(testing::implicit_surface("(x^2+(y+1)^2-1)/2"), testing::implicit_surface("(x^2+y^2+z^2-4)/4"),
             PairKind::kImplicitImplicit);
  VecX g(3);
  g << 0.02, -1.98, 0.01;
  AtPoint a = analyse(pr, g);
  EXPECT_EQ(a.kind.type, SingularType::kNode);
  ASSERT_EQ(a.hb.size(), 4u);
  expect_paired(a.hb);
  expect_good_exits(pr, a);
}

TEST(HalfBranches, Ex17EllipsoidNodeParametricParametric) {
  Problem pr(testing::param("1.2*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
             testing::param("0.9*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2.5*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
             PairKind::kParametricParametric);
  VecX g(4);
  g << M_PI / 2 + 0.02, M_PI / 2 - 0.01, M_PI / 2, M_PI / 2 + 0.01;
  AtPoint a = analyse(pr, g);
  ASSERT_EQ(a.hb.size(), 4u);
  expect_paired(a.hb);
  expect_good_exits(pr, a);
  for (const HalfBranch& b : a.hb)
    EXPECT_NEAR(b.tangent_3d.dot(a.hb[static_cast<std::size_t>(b.continuation)].tangent_3d), -1.0, 1e-12);
}

TEST(HalfBranches, Ex22CuspGoesOverTheTangentReversal) {
  // u^3 = v^2: v = +-u^(3/2), both halves leave along +u.
  for (PairKind kind : {PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
    Problem pr = kind == PairKind::kParametricImplicit ? testing::graph_vs_plane_pi("u^3-v^2") : testing::graph_vs_plane_pp("u^3-v^2");
    AtPoint a = analyse(pr, uv(0.02, 0.01, pr.dim()));
    ASSERT_EQ(a.hb.size(), 2u);
    expect_paired(a.hb);
    expect_good_exits(pr, a);
    for (const HalfBranch& b : a.hb) {
      EXPECT_NEAR(b.tangent_3d.x(), 1.0, 1e-12);
      EXPECT_NEAR(b.offset_exponent, 1.5, 1e-3);
      EXPECT_NEAR(std::fabs(b.offset_coefficient), 1.0, 1e-3);
    }
    EXPECT_LT(a.hb[0].offset_coefficient * a.hb[1].offset_coefficient, 0);
  }
}

TEST(HalfBranches, Ex18TacnodeKeepsEachBranchOnItsOwnSide) {
  // 0.1 (v - u^2)(v - 2u^2) + O(5): branches v = u^2 + ... and v = 2u^2 + ...
  Problem pr(testing::param("u", "v", "0.2*u^4+0.1*v^4"), testing::param("u", "v", "0.3*u^2*v-0.1*v^2+0.2*v^3"),
             PairKind::kParametricParametric);
  AtPoint a = analyse(pr, uv(0.03, 0.02, 4));
  EXPECT_EQ(a.kind.type, SingularType::kTacnode);
  ASSERT_EQ(a.hb.size(), 4u);
  expect_paired(a.hb);
  expect_good_exits(pr, a);
  for (const HalfBranch& b : a.hb) {
    const HalfBranch& c = a.hb[static_cast<std::size_t>(b.continuation)];
    EXPECT_NEAR(b.tangent.dot(c.tangent), -1.0, 1e-12);
    EXPECT_NEAR(b.offset_exponent, 2.0, 1e-3);
    EXPECT_NEAR(b.offset_coefficient, c.offset_coefficient, 1e-9);  // the same branch: v(-u) = v(u)
    const double a2 = std::fabs(b.offset_coefficient);  // O(epsilon^2) from the u^4 terms
    EXPECT_TRUE(std::fabs(a2 - 1) < 2e-3 || std::fabs(a2 - 2) < 2e-3) << a2;
  }
}

TEST(HalfBranches, Ex13FourPetalRosePairsByCurvature) {
  // (u^2+v^2)^3 = 4u^2v^2: branches v = +-u^2/2 and u = +-v^2/2 through the quadruple point.
  Problem pr = testing::graph_vs_plane_pi("(u^2+v^2)^3-4*u^2*v^2");
  AtPoint a = analyse(pr, uv(0.01, 0.02, 2));
  EXPECT_EQ(a.kind.type, SingularType::kQuadruplePoint);
  ASSERT_EQ(a.hb.size(), 8u);
  expect_paired(a.hb);
  expect_good_exits(pr, a);
  for (const HalfBranch& b : a.hb) {
    const HalfBranch& c = a.hb[static_cast<std::size_t>(b.continuation)];
    EXPECT_NEAR(b.tangent.dot(c.tangent), -1.0, 1e-12);
    EXPECT_NEAR(std::fabs(b.offset_coefficient), 0.5, 1e-3);
    EXPECT_NEAR(b.offset_coefficient, c.offset_coefficient, 1e-3);
  }
}

TEST(HalfBranches, Ex12TriplePointThreeBranchesStraightAcross) {
  Problem pr = testing::graph_vs_plane_pi("(u^2+v^2)^2+3*u^2*v-v^3");
  AtPoint a = analyse(pr, uv(0.02, -0.01, 2));
  ASSERT_EQ(a.hb.size(), 6u);
  expect_paired(a.hb);
  expect_good_exits(pr, a);
  for (const HalfBranch& b : a.hb)
    EXPECT_NEAR(b.tangent.dot(a.hb[static_cast<std::size_t>(b.continuation)].tangent), -1.0, 1e-12);
}

TEST(HalfBranches, CuspLikeBranchesAndIsolatedPoints) {
  struct Case {
    const char* f;
    std::size_t count;
  };
  for (Case c : {Case{"u^4+u^2*v^2-2*u^2*v-u*v^2+v^2", 2},             // Ex. 14 ramphoid cusp
                 Case{"u^4+v^4-4*u^3-4*u*v^2+2*u^2*v^2-4*v^2", 2},      // Ex. 20 cardioid cusp
                 Case{"3*u^4/4+u^3+u^2/4+7*u^2*v^2/2+u*v^2+v^4", 0}}) {  // Ex. 16 isolated (A5, x^2+y^6)
    Problem pr = testing::graph_vs_plane_pi(c.f);
    AtPoint a = analyse(pr, uv(0.02, 0.01, 2));
    ASSERT_EQ(a.hb.size(), c.count) << c.f;
    expect_paired(a.hb);
    expect_good_exits(pr, a);
    for (const HalfBranch& b : a.hb) EXPECT_NEAR(b.tangent.dot(a.hb[static_cast<std::size_t>(b.continuation)].tangent), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace ssimarch
