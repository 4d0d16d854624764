// Heap allocations of the evaluation kernels that run at every corrector iteration (issue 12
// item 4, issue 14 item 3), counted with testing/allocation_counter.hpp after a warm-up call:
// spline and Bezier surface points on doubles and jets to order 2 (surface/spline_basis.hpp,
// PointScratch), the expression tape (expr/program.hpp, registers on the stack),
// Problem::linearize for the three pair kinds and the curve jet (fixed-maximum-size Eigen
// storage, problem/problem.hpp UnknownVec). Values against the evaluation path before the
// scratch buffers and against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"
#include "testing/allocation_counter.hpp"
#include "testing/viviani_forms.hpp"
#include "testing/surface_pairs.hpp"

namespace ssimarch {
namespace {

using testing::allocations_of;

#define SSIMARCH_SKIP_WITHOUT_COUNTER() \
  if (!testing::counting_allocations()) GTEST_SKIP() << "allocations are not counted under AddressSanitizer"

TEST(Allocation, TheCountersSeeAVectorAndAnEigenVector) {  // the test can fail: allocations are counted
  SSIMARCH_SKIP_WITHOUT_COUNTER();
  volatile double sink = 0;
  EXPECT_EQ(allocations_of([&] {
              std::vector<double> v(5, 1.0);
              sink = v[4];
            }),
            1);
  EXPECT_EQ(allocations_of([&] {
              VecX v = VecX::Constant(5, 2.0);
              sink = v[4];
            }),
            1);
  EXPECT_EQ(allocations_of([&] {
              UnknownVec v = UnknownVec::Constant(4, 3.0);
              sink = v[3];
            }),
            0);
  EXPECT_EQ(sink, 3.0);
}

// A bicubic NURBS surface with an interior knot each way (two spans), the same polynomial, a
// rational bicubic Bezier patch and a polynomial one.
ControlNet net(int nu, int nv) {
  ControlNet p(static_cast<std::size_t>(nu), std::vector<Vec3>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = Vec3(i, j, std::sin(i + 2.0 * j));
  return p;
}
WeightNet weights(int nu, int nv) {
  WeightNet w(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) w[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = 1.0 + 0.1 * ((i + j) % 3);
  return w;
}
const std::vector<double> kKnots{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
std::vector<Surface> patches() {
  return {BSplineSurface(3, 3, kKnots, kKnots, net(5, 5), weights(5, 5)), BSplineSurface(3, 3, kKnots, kKnots, net(5, 5)),
          BezierPatch(net(4, 4), weights(4, 4)), BezierPatch(net(4, 4))};
}

// The evaluation path before the scratch buffers (std::vector per call): de Boor on the p + 1
// rows active in u, then along u, in homogeneous coordinates; Bezier = de Boor on Bezier knots.
template <class T>
Vec3T<T> reference_point(const ControlNet& P, const WeightNet& W, const std::vector<double>& U, int p, const T& u,
                         const T& v) {
  const int n = static_cast<int>(P.size());
  const int ku = internal::find_span(U, p, n, primal(u)), kv = internal::find_span(U, p, n, primal(v));
  std::vector<std::array<T, 4>> row(static_cast<std::size_t>(p) + 1), col(static_cast<std::size_t>(p) + 1);
  for (int a = 0; a <= p; ++a) {
    for (int b = 0; b <= p; ++b) {
      const auto i = static_cast<std::size_t>(ku - p + a), j = static_cast<std::size_t>(kv - p + b);
      const double w = W.empty() ? 1.0 : W[i][j];
      row[static_cast<std::size_t>(b)] = {T(w * P[i][j].x()), T(w * P[i][j].y()), T(w * P[i][j].z()), T(w)};
    }
    internal::de_boor<T, 4>(row, U, p, kv, v);
    col[static_cast<std::size_t>(a)] = row[static_cast<std::size_t>(p)];
  }
  internal::de_boor<T, 4>(col, U, p, ku, u);
  const auto& q = col[static_cast<std::size_t>(p)];
  return {q[0] / q[3], q[1] / q[3], q[2] / q[3]};
}

using J22 = Jet<2, 2>;

// Evaluates s at (u, v) n times after a first call (one-off static set-up: jet product tables)
// and returns the allocations of the n calls; *out is the last value.
template <class T>
long evaluation_allocations(const Surface& s, const T& u, const T& v, Vec3T<T>* out) {
  *out = s.point(u, v);
  return allocations_of([&] {
    for (int k = 0; k < 50; ++k) *out = s.point(u, v);
  });
}

TEST(Allocation, BezierBSplineAndNurbsPointsToOrderTwoAllocateNothing) {
  SSIMARCH_SKIP_WITHOUT_COUNTER();
  const std::vector<Surface> s = patches();
  const std::vector<double> bezier_knots{0, 0, 0, 0, 1, 1, 1, 1};
  // Points in both spans of the B-splines, and on the interior knot (the right-hand piece).
  for (const auto& [u0, v0] : {std::pair{0.3, 0.7}, std::pair{0.5, 0.2}, std::pair{0.85, 0.45}}) {
    const J22 u = J22::variable(0, u0), v = J22::variable(1, v0);
    for (std::size_t k = 0; k < s.size(); ++k) {
      Vec3T<J22> F;
      Vec3T<double> f;
      EXPECT_EQ(evaluation_allocations(s[k], u, v, &F), 0) << s[k].type_name() << " " << k;
      EXPECT_EQ(evaluation_allocations(s[k], u0, v0, &f), 0) << s[k].type_name() << " " << k;
      EXPECT_EQ((evaluation_allocations(s[k], Jet<2, 1>::variable(0, u0), Jet<2, 1>::variable(1, v0),
                                        std::make_unique<Vec3T<Jet<2, 1>>>().get())),
                0);
      EXPECT_EQ(evaluation_allocations(s[k], Taylor<6>::variable(0, u0), Taylor<6>(v0),
                                       std::make_unique<Vec3T<Taylor<6>>>().get()),
                0);
      const bool bezier = k >= 2, rational = k % 2 == 0;
      const Vec3T<J22> R = bezier ? reference_point(net(4, 4), rational ? weights(4, 4) : WeightNet{}, bezier_knots, 3, u, v)
                                  : reference_point(net(5, 5), rational ? weights(5, 5) : WeightNet{}, kKnots, 3, u, v);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(f[c], R[c].value(), 1e-14);
        // 5e-14: the Bezier pieces' differences and the reference's sums round differently (issue 27).
        for (int i = 0; i < J22::kSize; ++i) EXPECT_NEAR(F[c][i], R[c][i], 5e-14 * (1 + std::fabs(R[c][i])));
      }
    }
  }
}

TEST(Allocation, ExpressionTapeToOrderTwoAllocatesNothing) {
  SSIMARCH_SKIP_WITHOUT_COUNTER();
  const Surface f = testing::implicit("x^2 + sin(y)*z - exp(x*z)/(1 + y^2)", Box{{-3, 3}, {-3, 3}, {-3, 3}});
  using J = Jet<3, 2>;
  const Vec3T<J> p(J::variable(0, 0.3), J::variable(1, -0.4), J::variable(2, 0.9));
  J value = f.value(p);
  EXPECT_EQ(allocations_of([&] {
              for (int k = 0; k < 50; ++k) value = f.value(p);
            }),
            0);
  // Closed form: value and the order-2 coefficients at (x, y, z) = (0.3, -0.4, 0.9).
  const double x = 0.3, y = -0.4, z = 0.9, e = std::exp(x * z), d = 1 + y * y;
  EXPECT_NEAR(value.value(), x * x + std::sin(y) * z - e / d, 1e-14);
  EXPECT_NEAR(value.derivative({1, 0, 0}), 2 * x - z * e / d, 1e-14);
  EXPECT_NEAR(value.derivative({0, 1, 0}), std::cos(y) * z + e * 2 * y / (d * d), 1e-14);
  EXPECT_NEAR(value.derivative({2, 0, 0}), 2 - z * z * e / d, 1e-14);
  EXPECT_NEAR(value.derivative({1, 0, 1}), -(1 + x * z) * e / d, 1e-14);
  EXPECT_NEAR(value.derivative({0, 1, 1}), std::cos(y) + x * e * 2 * y / (d * d), 1e-14);
}

TEST(Allocation, LinearizeAllocatesNothingForEveryPairKind) {
  SSIMARCH_SKIP_WITHOUT_COUNTER();
  const std::vector<Surface> s = patches();
  const Sphere ball(Vec3(2, 2, 0), 1.5);
  const Torus ring(Vec3(2, 2, 0), Vec3::UnitZ(), 1.5, 0.5);
  const Problem pp(s[0], s[2], PairKind::kParametricParametric);
  const Problem pi(s[0], Surface(ball), PairKind::kParametricImplicit);
  const Problem ii(Surface(ball), Surface(ring), PairKind::kImplicitImplicit);
  UnknownVec x4(4), x2(2), x3(3);
  x4 << 0.3, 0.4, 0.5, 0.6;
  x2 << 0.3, 0.4;
  x3 << 2.5, 2.1, 0.2;
  for (const auto& [P, x] : {std::pair{&pp, x4}, std::pair{&pi, x2}, std::pair{&ii, x3}}) {
    (void)P->linearize(x);
    EXPECT_EQ(allocations_of([&] {
                for (int k = 0; k < 20; ++k) ASSERT_TRUE(P->linearize(x).h.allFinite());
              }),
              0)
        << to_string(P->kind());
  }
}

using testing::start_on_viviani;
using testing::viviani_problems;

TEST(Allocation, CurveJetAllocatesNothing) {
  SSIMARCH_SKIP_WITHOUT_COUNTER();
  for (const Problem& P : viviani_problems()) {
    const UnknownVec x = start_on_viviani(P);
    (void)curve_jet_dynamic(P, x, 4);
    EXPECT_EQ(allocations_of([&] { ASSERT_EQ(curve_jet_dynamic(P, x, 4).status, CurveJetStatus::kOk); }), 0)
        << to_string(P.kind());
  }
}

}  // namespace
}  // namespace ssimarch
