// Two quadrics neither of which is ruled, answered along the rulings of a real cone or cylinder of
// their pencil (analytic/quadric_pencil.hpp; docs/math/closed_form_quadrics.md "The pencil"),
// against the closed form of the peers case and against the tracer (closed_form off).
#include "ssimarch/analytic/quadric_pencil.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "testing/matchers.hpp"
#include "ssimarch/analytic/closed_form.hpp"
#include "ssimarch/analytic/quadric_form.hpp"
#include "ssimarch/surface/primitives.hpp"
#include "ssimarch/trace/trace_all.hpp"

namespace ssimarch {
namespace {

// The closed form, with every point on both surfaces to 1e-12.
ClosedFormResult solve(const Problem& problem) {
  auto r = closed_form_intersection(problem, TraceOptions{});
  EXPECT_TRUE(r.has_value());
  if (!r) return {};
  EXPECT_EQ(r->pair.rfind("pencil-", 0), 0u) << r->pair;
  for (const TracedCurve& c : r->result.curves)
    for (const CurvePoint& p : c.points) EXPECT_LE(problem.linearize(p.x).distance, 1e-12) << p.p.transpose();
  return *r;
}

double total_length(const std::vector<TracedCurve>& curves) {
  double s = 0;
  for (const TracedCurve& c : curves) s += c.length;
  return s;
}

TEST(QuadricPencil, DiagonalPencilHasTwoRealCylinders) {
  // x^2/1.44 + y^2/2.56 + z^2/4 = 1 and x^2/0.81 + y^2/2.56 + z^2/6.25 = 1: A - lambda B is
  // diagonal, singular at lambda = 0.5625 (a cylinder along x), 1 (twice: the plane pair
  // z = +-k x, rank 2) and 1.5625 (a cylinder along z) in the unscaled matrices.
  const auto A = quadric_matrix(Ellipsoid(Vec3::Zero(), {1.2, 1.6, 2}));
  const auto B = quadric_matrix(Ellipsoid(Vec3::Zero(), {0.9, 1.6, 2.5}));
  const auto members = ruled_members(*A, *B, Vec3::Zero(), 2.5);
  ASSERT_EQ(members.size(), 2u);
  std::vector<Vec3> axes;
  for (const PencilMember& m : members) {
    EXPECT_TRUE(m.cylinder);
    axes.push_back(m.rulings.d[0].head<3>().normalized().cwiseAbs());
  }
  EXPECT_NEAR((axes[0] - Vec3::UnitX()).norm() * (axes[0] - Vec3::UnitZ()).norm(), 0, 1e-12);
  EXPECT_NEAR(std::fabs(axes[0].dot(axes[1])), 0, 1e-12);
}

TEST(QuadricPencil, PeersEllipsoidsAreTwoEllipsesThroughTwoNodes) {
  // The curve is the two ellipses in the planes z = +-k x, k^2 = (1/0.81 - 1/1.44) / (1/4 - 1/6.25):
  // on each, x^2 (1/1.44 + k^2/4) + y^2/2.56 = 1, an ellipse of semi-axes 1.6 and
  // sqrt(1 + k^2) / sqrt(1/1.44 + k^2/4) (in its plane); they cross at (0, +-1.6, 0).
  const Problem P(Ellipsoid(Vec3::Zero(), {1.2, 1.6, 2}), Ellipsoid(Vec3::Zero(), {0.9, 1.6, 2.5}), PairKind::kImplicitImplicit);
  const ClosedFormResult r = solve(P);
  ASSERT_EQ(r.result.curves.size(), 2u);
  const double k2 = (1 / 0.81 - 1 / 1.44) / (1 / 4.0 - 1 / 6.25);
  const double a = std::sqrt(1 + k2) / std::sqrt(1 / 1.44 + k2 / 4), b = 1.6;
  const int n = 200000;
  double perimeter = 0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * 2 * M_PI / n;
    perimeter += std::hypot(a * std::sin(t), b * std::cos(t)) * 2 * M_PI / n;
  }
  for (const TracedCurve& c : r.result.curves) {
    EXPECT_TRUE(c.closed);
    EXPECT_NEAR(c.length, perimeter, 1e-10);
  }
  EXPECT_NEAR(total_length(r.result.curves), 21.2912863011, 1e-9);  // shared/peers/cases.jsonl
  ASSERT_EQ(r.result.singular_points.size(), 2u);
  for (const SingularPointReport& s : r.result.singular_points) {
    EXPECT_EQ(s.type, SingularType::kNode);
    EXPECT_THAT(s.p.cwiseAbs(), testing::IsNear(Vec3(0, 1.6, 0), 1e-12));
    EXPECT_EQ(s.curves.size(), 2u);
  }
}

// Every tangent, the nodes' included, lies in its own ellipse's plane z = +-k x, in both orders of
// the pair: at a node the loop changes sheet of the rulings' quadratic, and a difference of its
// square root there gave the bisector of the two ellipses (edges 1.1e-3 too long, order dependent).
TEST(QuadricPencil, TangentsAtTheNodesFollowTheirOwnEllipse) {
  const Ellipsoid e1(Vec3::Zero(), {1.2, 1.6, 2}), e2(Vec3::Zero(), {0.9, 1.6, 2.5});
  const double k = std::sqrt((1 / 0.81 - 1 / 1.44) / (1 / 4.0 - 1 / 6.25));
  for (const Problem& P : {Problem(e1, e2, PairKind::kImplicitImplicit), Problem(e2, e1, PairKind::kImplicitImplicit)}) {
    const ClosedFormResult r = solve(P);
    ASSERT_EQ(r.result.curves.size(), 2u);
    for (const TracedCurve& c : r.result.curves) {
      // The curve's plane from its point farthest from the y axis.
      const auto far = std::max_element(c.points.begin(), c.points.end(), [](const CurvePoint& p, const CurvePoint& q) {
        return std::hypot(p.p.x(), p.p.z()) < std::hypot(q.p.x(), q.p.z());
      });
      const Vec3 normal = Vec3(far->p.z() / far->p.x() > 0 ? k : -k, 0, -1).normalized();
      int at_nodes = 0;
      for (const CurvePoint& p : c.points) {
        EXPECT_NEAR(p.t.norm(), 1, 1e-12);
        EXPECT_NEAR(p.t.dot(normal), 0, 1e-9) << "at " << p.p.transpose();
        at_nodes += (p.p.cwiseAbs() - Vec3(0, 1.6, 0)).norm() <= 1e-12;
      }
      EXPECT_GE(at_nodes, 2);  // both nodes are points of the curve
    }
  }
}

// The pencil's answer against the tracer: curve count, closed flags, total length to 1e-6.
void expect_as_traced(const Problem& P, std::size_t curves) {
  const ClosedFormResult exact = solve(P);
  TraceOptions o;
  o.step_length = 0.01;
  const TraceResult traced = trace_all(P, o);
  ASSERT_EQ(exact.result.curves.size(), curves);
  ASSERT_EQ(traced.curves.size(), curves);
  int closed_exact = 0, closed_traced = 0;
  for (std::size_t i = 0; i < curves; ++i) {
    closed_exact += exact.result.curves[i].closed;
    closed_traced += traced.curves[i].closed;
  }
  EXPECT_EQ(closed_exact, closed_traced);
  EXPECT_NEAR(total_length(exact.result.curves) / total_length(traced.curves) - 1, 0, 1e-6);
}

TEST(QuadricPencil, TiltedEllipsoidsAsTraced) {
  expect_as_traced(Problem(Ellipsoid(Vec3::Zero(), {1, 1.5, 2}), Ellipsoid(Vec3(0.5, 0.3, 0.2), {1.2, 0.8, 1.6}, Vec3(0.3, 0.2, 1)),
                           PairKind::kImplicitImplicit),
                   1);
}

TEST(QuadricPencil, SphereThroughAnEllipsoidAsTraced) {
  expect_as_traced(Problem(Sphere(Vec3(0.2, 0.1, 0.3), 1.3), Ellipsoid(Vec3::Zero(), {0.8, 1.5, 2.0}, Vec3(1, 0.2, 0.1)),
                           PairKind::kImplicitImplicit),
                   2);
}

TEST(QuadricPencil, SphereAndTiltedEllipsoidAsTraced) {
  // The pair that the closed forms left to the tracer before the pencil: one closed curve.
  expect_as_traced(Problem(Sphere(Vec3(0.3, 0, 0), 2), Ellipsoid(Vec3::Zero(), {1, 2, 3}, Vec3(1, 0, 1)), PairKind::kImplicitImplicit),
                   1);
}

TEST(QuadricPencil, ConcentricSpheresHaveNoRealRuledMember) {
  // diag(1, 1, 1, -1) - lambda diag(1, 1, 1, -4): lambda = 1 (rank 1) and 1/4, a cone with a
  // definite quadratic part (x^2 + y^2 + z^2 = 0: imaginary, only its vertex real).
  const auto A = quadric_matrix(Sphere(Vec3::Zero(), 1)), B = quadric_matrix(Sphere(Vec3::Zero(), 2));
  EXPECT_TRUE(ruled_members(*A, *B, Vec3::Zero(), 2).empty());
}

TEST(QuadricPencil, CrossedEllipsoidsAsTraced) {
  expect_as_traced(Problem(Ellipsoid(Vec3::Zero(), {2, 1, 1}), Ellipsoid(Vec3(0.3, 0.1, 0), {1, 2, 1.2}, Vec3(0, 0.3, 1)),
                           PairKind::kImplicitImplicit),
                   2);
}

}  // namespace
}  // namespace ssimarch
