// Saddle boxes (start/saddle_box.hpp, docs/topology.md): boxes around nodes decided without
// deciding the node, against closed forms of the crossings; boxes around isolated points never.
#include "ssimarch/start/saddle_box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "testing/surface_pairs.hpp"
#include "ssimarch/trace/trace_all.hpp"

namespace ssimarch {
namespace {

using testing::implicit;
using testing::parametric;

using testing::plane_against;

// The crossings sorted, and expected points (each sorted the same way) to `tol`.
void expect_points(std::vector<VecX> got, std::vector<std::vector<double>> expected, double tol) {
  auto less = [](const VecX& a, const VecX& b) {
    return std::lexicographical_compare(a.data(), a.data() + a.size(), b.data(), b.data() + b.size());
  };
  std::sort(got.begin(), got.end(), less);
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    for (std::size_t j = 0; j < expected[i].size(); ++j)
      EXPECT_NEAR(got[i][static_cast<Eigen::Index>(j)], expected[i][j], tol) << "point " << i;
}

TEST(SaddleBox, NodeOfTwoLinesInTheParameterPlane) {
  // u^2 - v^2 = 0: the lines v = +-u crossing at the origin (a node, Hessian diag(2, -2)).
  const Problem P = plane_against("x^2-y^2");
  const IntervalBox box{{-0.1, 0.1}, {-0.05, 0.05}};
  EXPECT_TRUE(saddle_everywhere(P, box));
  SaddleBoxResult r = decide_saddle_box(P, box, RootSearchOptions{});
  EXPECT_TRUE(r.saddle);
  EXPECT_TRUE(r.decided);
  expect_points(r.crossings, {{-0.05, -0.05}, {-0.05, 0.05}, {0.05, -0.05}, {0.05, 0.05}}, 1e-12);
}

TEST(SaddleBox, IsolatedPointAndSmallLoopAreNeverDecided) {
  // u^2 + v^2 = 0 is an isolated point, and u^2 + v^2 = 1e-6 a loop of radius 1e-3 that no face
  // of the box meets: an extremum, so neither box is a saddle box.
  const IntervalBox box{{-0.01, 0.01}, {-0.01, 0.01}};
  for (const char* q : {"x^2+y^2", "x^2+y^2-1e-6"}) {
    const Problem P = plane_against(q);
    EXPECT_FALSE(saddle_everywhere(P, box)) << q;
    EXPECT_FALSE(decide_saddle_box(P, box, RootSearchOptions{}).decided) << q;
  }
  // A tacnode v^2 - u^4 = 0: the Hessian determinant vanishes at the point, nothing is proven.
  EXPECT_FALSE(saddle_everywhere(plane_against("y^2-x^4"), box));
  // |u| + v^2 + 3uv has a strict minimum at the kink (along (a, b): t|a| + t^2 (b^2 + 3ab)),
  // though its Hessian off the kink is [[0, 3], [3, 2]] (determinant -9): the kink must count.
  EXPECT_FALSE(saddle_everywhere(plane_against("abs(x)+y^2+3*x*y-1e-6"), box));
}

TEST(SaddleBox, NodeOfTwoCylinders) {
  // x^2 + z^2 = 1 and y^2 + z^2 = 1 cross at (0, 0, 1); near it the curves are x = +-y,
  // z = sqrt(1 - x^2): on the faces y = +-0.03 of the box, x = +-0.03.
  Problem P(implicit("x^2+z^2-1", Box{{-2, 2}, {-2, 2}, {-2, 2}}),
            implicit("y^2+z^2-1", Box{{-2, 2}, {-2, 2}, {-2, 2}}), PairKind::kImplicitImplicit);
  const IntervalBox box{{-0.05, 0.05}, {-0.03, 0.03}, {0.95, 1.05}};
  SaddleBoxResult r = decide_saddle_box(P, box, RootSearchOptions{});
  EXPECT_TRUE(r.decided);
  const double z = std::sqrt(1 - 0.03 * 0.03);
  expect_points(r.crossings, {{-0.03, -0.03, z}, {-0.03, 0.03, z}, {0.03, -0.03, z}, {0.03, 0.03, z}}, 1e-12);
  // A box the surfaces do not reach (g > 0 on both faces z = 1.1, 1.2) is decided, empty.
  SaddleBoxResult empty =
      decide_saddle_box(P, IntervalBox{{-0.05, 0.05}, {-0.03, 0.03}, {1.1, 1.2}}, RootSearchOptions{});
  EXPECT_TRUE(empty.decided);
  EXPECT_TRUE(empty.crossings.empty());
}

TEST(SaddleBox, VivianisCurveIsCertifiedThroughItsNode) {
  // Cylinder (parametric) against the sphere (implicit): the node at (0, -2, 0) used to leave the
  // turning systems undecided; its saddle box decides it, and the figure eight is traced once.
  Problem P(testing::cylinder_f2(), testing::sphere_g2_implicit(), PairKind::kParametricImplicit);
  TraceResult r = trace_all(P, TraceOptions{});
  EXPECT_TRUE(r.start_search.certified) << r.start_search.note;
  EXPECT_NE(r.start_search.note.find("saddle boxes"), std::string::npos) << r.start_search.note;
  EXPECT_TRUE(r.start_search.uncertain_regions.empty());
  double length = 0;
  for (const TracedCurve& c : r.curves) length += c.length;
  EXPECT_NEAR(length, testing::kVivianiLength, 1e-6 * testing::kVivianiLength);
}

}  // namespace
}  // namespace ssimarch
