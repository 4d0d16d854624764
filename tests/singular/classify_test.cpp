// Classification against the oracle (tests/reference/oracle.json: s003.t21.codimensions,
// s003.sec2.*, s003.alg1.classification, s003.ex12.tangent_slopes, s003.ex13.quartic,
// s003.ch5.*) and the real forms of docs/math/singular_local_curve.md §3 (Ex. 16 is an isolated point).
#include "ssimarch/singular/classify.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "singular/pairs.hpp"
#include "ssimarch/singular/half_branches.hpp"
#include "ssimarch/singular/local_curve.hpp"
#include "ssimarch/singular/locate.hpp"

namespace ssimarch {
namespace {

using testing::germ;
using Terms = std::vector<std::tuple<int, int, double>>;

struct GermCase {
  const char* name;
  Terms terms;
  SingularType type;
  const char* ak;
  int milnor;
  int multiplicity;
};

class ClassifyGerm : public ::testing::TestWithParam<GermCase> {};

TEST_P(ClassifyGerm, TypeMilnorAndName) {
  const GermCase& c = GetParam();
  Classification k = classify(germ(c.terms));
  EXPECT_EQ(k.type, c.type) << to_string(k.type);
  EXPECT_EQ(k.ak, c.ak);
  EXPECT_EQ(k.milnor, c.milnor);
  EXPECT_EQ(k.multiplicity, c.multiplicity);
}

// The same germ as a gap in model units of a model scaled by lambda: the coefficient of degree d
// times lambda^(1 - d). Classified over its own germ length it is the same singular point at every
// scale (issue 26: at lambda = 1e-6 the order-12 terms made a Viviani node a contact point, at
// 1e6 the higher terms were cleaned as if negligible).
LocalJet scaled_germ(const LocalJet& h, double lambda) {
  LocalJet r = h;
  for (int d = 0; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) set_coef(r, d - j, j, coef(h, d - j, j) * std::pow(lambda, 1 - d));
  return r;
}

TEST_P(ClassifyGerm, TheSameAtEveryScaleOverItsGermLength) {
  const GermCase& c = GetParam();
  // Terms of every degree up to the jet's order, small at the unit length, as a real germ has.
  LocalJet h = germ(c.terms);
  for (int d = 7; d <= kLocalOrder; ++d) set_coef(h, d - 1, 1, coef(h, d - 1, 1) + 1e-3 / d);
  const Classification at_one = classify(h);
  for (const double lambda : {1e-6, 1e-3, 1e3, 1e6}) {
    SCOPED_TRACE(lambda);
    const LocalJet hl = scaled_germ(h, lambda);
    const double length = germ_length(hl, 1e300);
    EXPECT_NEAR(length / lambda, germ_length(h, 1e300), 1e-12 * germ_length(h, 1e300));
    const Classification k = classify(hl, {.length = length});
    EXPECT_EQ(k.type, at_one.type) << to_string(k.type);
    EXPECT_EQ(k.ak, at_one.ak);
    EXPECT_EQ(k.milnor, at_one.milnor);
    EXPECT_EQ(k.multiplicity, at_one.multiplicity);
  }
}

TEST(GermLength, IsTheRadiusAtWhichATermIsAsLargeAsTheGap) {
  // A sphere of radius R over its tangent plane: the gap (s^2 + t^2) / (2R) + (s^2 + t^2)^2 / (8R^3)
  // + ...: the quadratic term equals the distance at 2R, the quartic's largest coefficient
  // (2 s^2 t^2 / (8R^3)) at cbrt(4) R, the smaller.
  for (const double R : {1e-5, 1.0, 3e4}) {
    const LocalJet h = germ({{2, 0, 0.5 / R},
                             {0, 2, 0.5 / R},
                             {4, 0, 0.125 / (R * R * R)},
                             {2, 2, 0.25 / (R * R * R)},
                             {0, 4, 0.125 / (R * R * R)}});
    EXPECT_NEAR(germ_length(h, 1e300), std::cbrt(4.0) * R, 1e-12 * R);
    EXPECT_EQ(germ_length(h, R), R);  // the cap
  }
  // A product of two gaps (units length^2): the degree-2 part carries no length, the cubic does.
  const LocalJet two = germ({{1, 1, 1.0}, {3, 0, 1e-4}});
  EXPECT_NEAR(germ_length(two, 1e300, 2), 1e4, 1e-8);
}

using T = SingularType;
INSTANTIATE_TEST_SUITE_P(
    Oracle, ClassifyGerm,
    ::testing::Values(
        // s003.t21.codimensions (Thom's germs; cuspoids with y^2 added): 2, 3, 4, 5, 4, 4, 5
        GermCase{"t21_x3", {{3, 0, 1}, {0, 2, 1}}, T::kCusp, "A2", 2, 2},
        GermCase{"t21_x4", {{4, 0, 1}, {0, 2, 1}}, T::kIsolated, "A3", 3, 2},
        GermCase{"t21_x5", {{5, 0, 1}, {0, 2, 1}}, T::kRamphoidCusp, "A4", 4, 2},
        GermCase{"t21_x6", {{6, 0, 1}, {0, 2, 1}}, T::kIsolated, "A5", 5, 2},
        GermCase{"t21_elliptic_umbilic", {{3, 0, 1}, {1, 2, -1}}, T::kTriplePoint, "D4", 4, 3},
        GermCase{"t21_hyperbolic_umbilic", {{3, 0, 1}, {0, 3, 1}}, T::kTriplePoint, "D4", 4, 3},
        GermCase{"t21_parabolic_umbilic", {{2, 1, 1}, {0, 4, 1}}, T::kTriplePoint, "D5", 5, 3},
        // s003.sec2.Ex4, Ex9 (k=4), Ex10, Ex11
        GermCase{"ex4", {{2, 0, 1}, {1, 1, 2}, {0, 2, 1}, {3, 0, 1}, {2, 1, 1}, {0, 3, 1}, {5, 0, 3}, {0, 6, 1}}, T::kCusp, "A2", 2, 2},
        GermCase{"ex9_k4", {{5, 0, 1}, {0, 2, 1}}, T::kRamphoidCusp, "A4", 4, 2},
        GermCase{"ex10", {{2, 1, 1}, {0, 4, 1}}, T::kTriplePoint, "D5", 5, 3},
        GermCase{"ex11", {{4, 0, 1}, {2, 2, 1}, {2, 1, -2}, {1, 2, -1}, {0, 2, 1}}, T::kRamphoidCusp, "A4", 4, 2},
        // s003.alg1.classification (Examples 23-30 and two rotated germs)
        GermCase{"ex23", {{4, 0, -1}, {0, 4, -1}, {0, 2, 1}}, T::kTacnode, "A3", 3, 2},
        GermCase{"ex24", {{2, 0, 5.99}, {0, 2, -2}}, T::kNode, "A1", 1, 2},
        GermCase{"ex25", {{3, 0, 1}, {0, 2, -1}}, T::kCusp, "A2", 2, 2},
        GermCase{"ex26", {{2, 0, -1.24}, {0, 2, 1.6}}, T::kNode, "A1", 1, 2},
        GermCase{"ex27_node", {{2, 0, 0.55}, {0, 2, -0.18}}, T::kNode, "A1", 1, 2},
        GermCase{"ex27_tacnode", {{4, 0, 0.2}, {0, 4, 0.1}, {2, 1, -0.3}, {0, 2, 0.1}, {0, 3, -0.2}}, T::kTacnode, "A3", 3, 2},
        GermCase{"ex28_cardioid", {{4, 0, 1}, {0, 4, 1}, {3, 0, -4}, {1, 2, -4}, {2, 2, 2}, {0, 2, -4}}, T::kCusp, "A2", 2, 2},
        GermCase{"ex29_ramphoid", {{0, 2, 1}, {2, 1, -2}, {1, 2, -1}, {4, 0, 1}, {2, 2, 1}}, T::kRamphoidCusp, "A4", 4, 2},
        GermCase{"ex30_a5_isolated", {{2, 0, 0.25}, {3, 0, 1}, {1, 2, 1}, {4, 0, 0.75}, {2, 2, 3.5}, {0, 4, 1}}, T::kIsolated, "A5", 5, 2},
        // (x+y)^2 + (x-y)^4: a sum of squares, isolated; (x+y)^2 + (x-y)^3: cusp
        GermCase{"rotated_a3", {{2, 0, 1}, {1, 1, 2}, {0, 2, 1}, {4, 0, 1}, {3, 1, -4}, {2, 2, 6}, {1, 3, -4}, {0, 4, 1}}, T::kIsolated, "A3", 3, 2},
        GermCase{"rotated_a2", {{2, 0, 1}, {1, 1, 2}, {0, 2, 1}, {3, 0, 1}, {2, 1, -3}, {1, 2, 3}, {0, 3, -1}}, T::kCusp, "A2", 2, 2},
        // real forms with branches (thesis Fig. 2.6): x^2 - y^4 tacnode, x^2 - y^6 oscnode
        GermCase{"tacnode", {{2, 0, 1}, {0, 4, -1}}, T::kTacnode, "A3", 3, 2},
        GermCase{"oscnode", {{2, 0, 1}, {0, 6, -1}}, T::kOscnode, "A5", 5, 2},
        GermCase{"isolated_a1", {{2, 0, 1}, {0, 2, 2}}, T::kIsolated, "A1", 1, 2},
        // E6, E7, E8 and the ordinary quadruple point X9
        GermCase{"e6", {{3, 0, 1}, {0, 4, 1}}, T::kTriplePoint, "E6", 6, 3},
        GermCase{"e7", {{3, 0, 1}, {1, 3, 1}}, T::kTriplePoint, "E7", 7, 3},
        GermCase{"e8", {{3, 0, 1}, {0, 5, 1}}, T::kTriplePoint, "E8", 8, 3},
        GermCase{"x9", {{3, 1, 1}, {1, 3, -1}}, T::kQuadruplePoint, "X9", 9, 4},
        GermCase{"five_lines", {{5, 0, 1}, {3, 2, -5}, {1, 4, 4}}, T::kMultiplePoint, "", 16, 5},
        // curves of tangential contact: a double line; crossed by a transversal branch
        GermCase{"contact", {{2, 0, 1}}, T::kTangentialContact, "", -1, 2},
        GermCase{"contact_crossed", {{2, 1, 1}}, T::kTangentLineCrossing, "", -1, 3}),
    [](const ::testing::TestParamInfo<GermCase>& i) { return std::string(i.param.name); });

TEST(Classify, Ex12TriplePointTangents) {
  // h = (u^2+v^2)^2 + 3u^2 v - v^3: slopes v'/u' = 0, +-sqrt(3) (oracle s003.ex12.tangent_slopes).
  Classification k = classify(germ({{4, 0, 1}, {2, 2, 2}, {0, 4, 1}, {2, 1, 3}, {0, 3, -1}}));
  EXPECT_EQ(k.type, SingularType::kTriplePoint);
  EXPECT_EQ(k.ak, "D4");
  EXPECT_EQ(k.milnor, 4);
  ASSERT_EQ(k.tangent_cone.size(), 3u);
  std::vector<double> angles;
  for (const auto& l : k.tangent_cone) angles.push_back(std::atan2(l.direction[1], l.direction[0]));
  EXPECT_NEAR(angles[0], 0.0, 1e-12);
  EXPECT_NEAR(angles[1], M_PI / 3, 1e-12);
  EXPECT_NEAR(angles[2], 2 * M_PI / 3, 1e-12);
  EXPECT_TRUE(k.crossing);
}

TEST(Classify, Ex13QuadruplePointHasTwoDoubleLines) {
  // h = (u^2+v^2)^3 - 4u^2v^2: quartic -4 u^2 v^2 (oracle s003.ex13.quartic: |c| = 4), mu = 13.
  LocalJet h = germ({{6, 0, 1}, {4, 2, 3}, {2, 4, 3}, {0, 6, 1}, {2, 2, -4}});
  Classification k = classify(h);
  EXPECT_EQ(k.type, SingularType::kQuadruplePoint);
  EXPECT_EQ(k.multiplicity, 4);
  EXPECT_EQ(k.milnor, 13);
  ASSERT_EQ(k.tangent_cone.size(), 2u);
  EXPECT_EQ(k.tangent_cone[0].multiplicity, 2);
  EXPECT_EQ(k.tangent_cone[1].multiplicity, 2);
  EXPECT_NEAR(std::fabs(k.tangent_cone[0].direction[0]), 1.0, 1e-12);  // v' = 0
  EXPECT_NEAR(std::fabs(k.tangent_cone[1].direction[1]), 1.0, 1e-12);  // u' = 0
  EXPECT_NEAR(std::fabs(coef(h, 2, 2)), 4.0, 1e-9);
}

TEST(Classify, MilnorRowsMatchGibsonPyramid) {
  // s003.ch5.Ex15/29 cod_k rows [1,1,1,1,0,...]: dims of Q/(J + M^N) are 1, 2, 3, 4, 4.
  std::vector<int> rows;
  EXPECT_EQ(milnor_number(germ({{4, 0, 1}, {2, 2, 1}, {2, 1, -2}, {1, 2, -1}, {0, 2, 1}}), 1e-9, &rows), 4);
  EXPECT_EQ(rows, (std::vector<int>{1, 2, 3, 4, 4}));
}

// Located thesis points classified from the surfaces (not from the printed polynomials).
struct PointCase {
  const char* name;
  const char* f;
  const char* level;
  double u, v;
  SingularType type;
  const char* ak;
  int milnor;
};
class ClassifyPoint : public ::testing::TestWithParam<PointCase> {};

TEST_P(ClassifyPoint, FromTheSurfaces) {
  const PointCase& c = GetParam();
  for (PairKind kind : {PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
    Problem pr = kind == PairKind::kParametricImplicit ? testing::graph_vs_plane_pi(c.f, c.level)
                                                       : testing::graph_vs_plane_pp(c.f, c.level);
    VecX x = VecX::Zero(pr.dim());
    x[0] = c.u + 0.01, x[1] = c.v - 0.02;
    if (pr.dim() == 4) x[2] = x[0], x[3] = x[1];
    SingularLocation s = locate_singular_point(pr, x);
    ASSERT_EQ(s.status, LocateStatus::kConverged);
    Classification k = classify(local_curve(pr, s.x).h);
    EXPECT_EQ(k.type, c.type) << to_string(k.type) << " " << to_string(kind);
    EXPECT_EQ(k.ak, c.ak);
    EXPECT_EQ(k.milnor, c.milnor);
  }
}

INSTANTIATE_TEST_SUITE_P(
    ThesisCh5, ClassifyPoint,
    ::testing::Values(PointCase{"ex12", "(u^2+v^2)^2+3*u^2*v-v^3", "0", 0, 0, T::kTriplePoint, "D4", 4},
                      PointCase{"ex13", "(u^2+v^2)^3-4*u^2*v^2", "0", 0, 0, T::kQuadruplePoint, "", 13},
                      PointCase{"ex14", "u^4+u^2*v^2-2*u^2*v-u*v^2+v^2", "0", 0, 0, T::kRamphoidCusp, "A4", 4},
                      PointCase{"ex16", "3*u^4/4+u^3+u^2/4+7*u^2*v^2/2+u*v^2+v^4", "0", 0, 0, T::kIsolated, "A5", 5},
                      PointCase{"ex19", "-u^4-v^4+v^2", "0", 0, 0, T::kTacnode, "A3", 3},
                      PointCase{"ex20", "u^4+v^4-4*u^3-4*u*v^2+2*u^2*v^2-4*v^2", "0", 0, 0, T::kCusp, "A2", 2},
                      PointCase{"ex21", "u^6/6-5*u^4/4+2*u^2+v^2", "11/12", 1, 0, T::kNode, "A1", 1},
                      PointCase{"ex22", "u^3-v^2", "0", 0, 0, T::kCusp, "A2", 2},
                      PointCase{"ex40", "u^4-u^2+v^4-v^2", "-0.25", 0, 0.70710678118654752, T::kNode, "A1", 1}),
    [](const ::testing::TestParamInfo<PointCase>& i) { return std::string(i.param.name); });

TEST(ClassifyPoint, Ex17EllipsoidNodeQuadraticForm) {
  // oracle s003.ex17: (d^2G - d^2F).N in (du, dv) = -1.24444 du^2 + 0.576 dv^2 (no 1/2), a node.
  Problem pr(testing::param("1.2*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
             testing::param("0.9*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2.5*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
             PairKind::kParametricParametric);
  const double h = M_PI / 2;
  VecX x(4);
  x << h + 0.02, h - 0.01, h, h + 0.02;
  SingularLocation s = locate_singular_point(pr, x);
  ASSERT_EQ(s.status, LocateStatus::kConverged);
  LocalCurve c = local_curve(pr, s.x);
  Classification k = classify(c.h);
  EXPECT_EQ(k.type, SingularType::kNode);
  // Back to (du, dv): (s, t) = M (du, dv), M = [e_i . F_u, e_i . F_v].
  Eigen::Matrix2d M = c.unknowns_jacobian().topRows(2).inverse();
  LocalJet huv = linear_substitution(c.h, M);
  // h = (F - G).N = -(1/2)(d^2G - d^2F).N up to the orientation of N.
  const double a = 2 * coef(huv, 2, 0), b = 2 * coef(huv, 1, 1), d = 2 * coef(huv, 0, 2);
  const double sign = a > 0 ? -1.0 : 1.0;
  EXPECT_NEAR(sign * a, -1.24444444444, 1e-9);
  EXPECT_NEAR(b, 0.0, 1e-9);
  EXPECT_NEAR(sign * d, 0.576, 1e-9);
}

}  // namespace
}  // namespace ssimarch

namespace ssimarch {
namespace {

// Curves of tangential contact (issue 10 item 5): a cylinder lying on a plane (h = v^2), and the
// same contact curve crossed by a transversal branch (h = v^2 (u - 0.1)).
TEST(ClassifyPoint, TangentialContactAndTangentLineCrossing) {
  Problem contact = testing::graph_vs_plane_pi("v^2");
  VecX x(2);
  x << 0.3, 0.02;
  SingularLocation s = locate_singular_point(contact, x);
  ASSERT_EQ(s.status, LocateStatus::kConverged);
  EXPECT_LE(std::fabs(s.x[1]), 1e-12);
  EXPECT_EQ(classify(local_curve(contact, s.x).h).type, SingularType::kTangentialContact);

  Problem crossed = testing::graph_vs_plane_pi("v^2*(u-0.1)");
  x << 0.13, 0.02;
  s = locate_singular_point(crossed, x);
  ASSERT_EQ(s.status, LocateStatus::kConverged);
  EXPECT_LE(std::fabs(s.x[1]), 1e-12);  // on the contact line v = 0
  VecX at(2);
  at << 0.1, 0.0;
  EXPECT_EQ(classify(local_curve(crossed, at).h).type, SingularType::kTangentLineCrossing);
  at << 0.3, 0.0;
  EXPECT_EQ(classify(local_curve(crossed, at).h).type, SingularType::kTangentialContact);
}

}  // namespace
}  // namespace ssimarch

namespace ssimarch {
namespace {

// A_k for every k the degree-10 jet resolves (issue 10; docs/math/singular_local_curve.md §3):
// x^2 -+ y^(k+1), also after a shear and a rotation of the coordinates (the classification is
// invariant; the splitting lemma must find the same k). Names: node/isolated (k = 1), cusp (2),
// tacnode/isolated (3), ramphoid_cusp (4), oscnode/isolated (5), higher_double_point (6..9, two
// real branches for odd k with x^2 - y^(k+1)) or isolated (odd k with x^2 + y^(k+1)); ak = "A<k>",
// Milnor number k, two real branches crossing iff (k+1)/2 is odd.
TEST(Classify, AkSeriesUpToTheJetOrder) {
  Eigen::Matrix2d shear_rotate;
  const double a = 0.7;
  shear_rotate << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  shear_rotate = shear_rotate * (Eigen::Matrix2d() << 1, 0.3, 0, 1.2).finished();
  for (int k = 1; k <= kLocalOrder - 1; ++k)
    for (const double sign : {-1.0, 1.0})
      for (const bool transformed : {false, true}) {
        LocalJet h = testing::germ({{2, 0, 1}, {0, k + 1, sign}});
        if (transformed) h = linear_substitution(h, shear_rotate);
        const Classification c = classify(h);
        SCOPED_TRACE("k = " + std::to_string(k) + ", sign " + std::to_string(sign) + (transformed ? ", transformed" : ""));
        // (a string literal + to_string trips GCC 12's -Wrestrict false positive, PR 105329)
        EXPECT_EQ(c.ak, std::string("A").append(std::to_string(k)));
        EXPECT_EQ(c.ak_index, k);
        EXPECT_EQ(c.milnor, k);
        EXPECT_EQ(c.multiplicity, 2);
        const bool two = k % 2 == 1 && sign < 0;
        EXPECT_EQ(c.real_branches, k % 2 == 0 ? 1 : (two ? 2 : 0));
        EXPECT_EQ(c.crossing, two && ((k + 1) / 2) % 2 == 1);
        SingularType expected = SingularType::kHigherDoublePoint;
        if (k % 2 == 1 && !two) expected = SingularType::kIsolated;
        else if (k == 1) expected = SingularType::kNode;
        else if (k == 2) expected = SingularType::kCusp;
        else if (k == 3) expected = SingularType::kTacnode;
        else if (k == 4) expected = SingularType::kRamphoidCusp;
        else if (k == 5) expected = SingularType::kOscnode;
        EXPECT_EQ(c.type, expected) << to_string(c.type);
      }
}

// A10 and A11 (issue 10: A_k beyond A9) realised as intersections: the graph (u, v, v^2 - s u^(k+1))
// against the plane z = 0 (parametric-implicit and parametric-parametric), whose local curve at the
// origin is v^2 - s u^(k+1). A10: one real branch, two half-branches v = +-u^(11/2) leaving along
// +u (s = 1) or -u (s = -1); A11 with s = 1: two real branches v = +-u^6 crossing the circle
// 1e-12 apart at epsilon = 0.01, four half-branches; s = -1: an isolated point.
TEST(Classify, A10AndA11RealisedAsIntersections) {
  for (const int k : {10, 11})
    for (const double s : {1.0, -1.0})
      for (const PairKind kind : {PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
        const std::string f = std::string("v^2").append(s > 0 ? "-" : "+").append("u^").append(std::to_string(k + 1));
        const Problem P = kind == PairKind::kParametricImplicit ? testing::graph_vs_plane_pi(f) : testing::graph_vs_plane_pp(f);
        SCOPED_TRACE(std::string(f).append(kind == PairKind::kParametricImplicit ? " pi" : " pp"));
        const VecX x = VecX::Zero(P.dim());
        const LocalCurve c = local_curve(P, x);
        ASSERT_EQ(c.status, LocalCurveStatus::kOk);
        const Classification kd = classify(c.h);
        EXPECT_EQ(kd.ak, std::string("A").append(std::to_string(k)));
        EXPECT_EQ(kd.milnor, k);
        const bool isolated = k == 11 && s < 0;
        EXPECT_EQ(kd.type, isolated ? SingularType::kIsolated : SingularType::kHigherDoublePoint);
        EXPECT_EQ(kd.real_branches, k == 10 ? 1 : (isolated ? 0 : 2));
        const std::vector<HalfBranch> hb = half_branches(P, c, kd);
        ASSERT_EQ(hb.size(), k == 10 ? 2u : (isolated ? 0u : 4u));
        for (const HalfBranch& b : hb) {
          ASSERT_GE(b.continuation, 0);
          EXPECT_NE(hb[static_cast<std::size_t>(b.continuation)].branch, -1);
          ASSERT_FALSE(b.expansion.terms.empty());
          const PuiseuxTerm& t = b.expansion.terms[0];
          if (k == 10) {  // v = +-u^(11/2) for s u > 0: along +-u, W = +-X^(11/2)
            EXPECT_NEAR(b.tangent[0], s, 1e-9);
            EXPECT_NEAR(t.exponent, 5.5, 1e-12);
            EXPECT_NEAR(std::fabs(t.coefficient), 1.0, 1e-9);
          } else {  // v = +-u^6 on both sides
            EXPECT_NEAR(std::fabs(b.tangent[0]), 1.0, 1e-9);
            EXPECT_NEAR(t.exponent, 6.0, 1e-12);
            EXPECT_NEAR(std::fabs(t.coefficient), 1.0, 1e-9);
            // The continuation is the same branch v = c u^6 on the other side: straight on.
            const HalfBranch& o = hb[static_cast<std::size_t>(b.continuation)];
            EXPECT_LT(b.tangent.dot(o.tangent), -0.99);
            EXPECT_NEAR(o.expansion.terms[0].coefficient, -t.coefficient, 1e-9);
          }
        }
        if (k == 10) {
          EXPECT_LT(hb[0].expansion.terms[0].coefficient * hb[1].expansion.terms[0].coefficient, 0);
        }
      }
}

}  // namespace
}  // namespace ssimarch
