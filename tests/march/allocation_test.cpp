// Heap allocations of the evaluation kernels and of the marching loop (issue 12 item 4), counted
// by replacing the global operator new in this test program (its own executable: the
// replacement applies to everything linked into it).
//
// Kernels that run at every corrector iteration must allocate nothing: spline and Bezier surface
// points on doubles and jets (surface/spline_basis.hpp, PointScratch), Problem::linearize for the
// three pair kinds (fixed-maximum-size Eigen storage). The marching loop is measured per accepted
// point as the difference of two marches of different lengths, so one-off work (the tracer's
// set-up, the points vector's geometric growth) cancels.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "testing/surface_pairs.hpp"
#include "ssimarch/core/jet.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, std::align_val_t a) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  const std::size_t al = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(al, (n + al - 1) / al * al)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace ssimarch {
namespace {

// What the marching loop may allocate per accepted point (see MarchingLoopPerAcceptedPoint).
constexpr double kMaxMarchAllocationsPerPoint = 0.0;

// Allocations made by f().
template <class F>
long allocations_of(F&& f) {
  const long before = g_allocations.load();
  f();
  return g_allocations.load() - before;
}

TEST(Allocation, TheCounterSeesAVector) {  // the test can fail: a heap allocation is counted
  volatile double sink = 0;
  EXPECT_EQ(allocations_of([&] {
              std::vector<double> v(5, 1.0);
              sink = v[4];
            }),
            1);
  EXPECT_EQ(sink, 1.0);
}

// A bicubic NURBS patch with an interior knot each way (two spans), a rational bicubic Bezier
// patch and a polynomial one.
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
std::vector<Surface> patches() {
  const std::vector<double> U{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  return {BSplineSurface(3, 3, U, U, net(5, 5), weights(5, 5)), BSplineSurface(3, 3, U, U, net(5, 5)),
          BezierPatch(net(4, 4), weights(4, 4)), BezierPatch(net(4, 4))};
}

template <class T>
long evaluation_allocations(const Surface& s, int order_vars) {
  T u, v;
  if constexpr (std::is_same_v<T, double>) {
    u = 0.3, v = 0.7;
  } else {
    u = T::variable(0, 0.3);
    v = T::variable(order_vars > 1 ? 1 : 0, 0.7);
  }
  (void)s.point(u, v);  // first use: one-off static set-up (jet product tables)
  return allocations_of([&] {
    for (int k = 0; k < 50; ++k) {
      const Vec3T<T> p = s.point(u, v);
      ASSERT_TRUE(std::isfinite(primal(p.x)));
    }
  });
}

TEST(Allocation, SplineAndBezierPointsAllocateNothing) {
  for (const Surface& s : patches()) {
    EXPECT_EQ(evaluation_allocations<double>(s, 0), 0);
    EXPECT_EQ((evaluation_allocations<Jet<2, 1>>(s, 2)), 0);
    EXPECT_EQ((evaluation_allocations<Jet<2, 4>>(s, 2)), 0);
    EXPECT_EQ((evaluation_allocations<Taylor<6>>(s, 1)), 0);
  }
}

TEST(Allocation, LinearizeAllocatesNothingForEveryPairKind) {
  const std::vector<Surface> s = patches();
  const Sphere ball(Vec3(2, 2, 0), 1.5);
  const Torus ring(Vec3(2, 2, 0), Vec3::UnitZ(), 1.5, 0.5);
  const Problem pp(s[0], s[2], PairKind::kParametricParametric);
  const Problem pi(s[0], Surface(ball), PairKind::kParametricImplicit);
  const Problem ii(Surface(ball), Surface(ring), PairKind::kImplicitImplicit);
  VecX x4(4), x2(2), x3(3);
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

TEST(Allocation, CurveJetAllocatesNothing) {
  const Problem P(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit);
  VecX x(2);
  x << 0.3, 0.0;
  (void)curve_jet<4>(P, x);
  EXPECT_EQ(allocations_of([&] { ASSERT_EQ(curve_jet<4>(P, x).status, CurveJetStatus::kOk); }), 0);
}

// Allocations per accepted point of Tracer::march_until_event on thesis pair 1 (curve C1): the
// difference between a march of 400 points and one of 200.
double march_allocations_per_point(const Problem& P, const VecX& x0) {
  TraceOptions o;
  o.step_length = 0.02;
  const Tracer tracer(P, o);
  const CurvePoint start{x0, P.point(x0), curve_jet_dynamic(P, x0, 1).tangent()};
  auto run = [&](int n) {
    MarchLimits limits = tracer.limits();
    limits.max_points = n;
    limits.detect_closure = false;
    TraceStats stats;
    long a = 0;
    a = allocations_of([&] {
      const MarchResult r = tracer.march_until_event(start, Direction::kForward, limits, &stats);
      ASSERT_EQ(r.points.size(), static_cast<std::size_t>(n));
    });
    return a;
  };
  const long a200 = run(200), a400 = run(400);
  return static_cast<double>(a400 - a200) / 200.0;
}

TEST(Allocation, MarchingLoopPerAcceptedPoint) {
  const Problem P(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit);
  VecX x(2);
  x << 0.3, 0.0;
  const double per_point = march_allocations_per_point(P, x);
  RecordProperty("allocations_per_point", std::to_string(per_point));
  std::printf("marching loop: %.2f allocations per accepted point\n", per_point);
  EXPECT_LE(per_point, kMaxMarchAllocationsPerPoint);
}

}  // namespace
}  // namespace ssimarch
