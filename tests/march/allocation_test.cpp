// Heap allocations of the marching loop per accepted point (issue 12 item 4), counted with
// testing/allocation_counter.hpp: the difference of two marches of different lengths, less the
// output vector's own growth (counted separately with a vector of the same type), so one-off
// work (the tracer's set-up, its final event message) cancels. The kernels it calls are tested
// in tests/problem/allocation_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "testing/allocation_counter.hpp"
#include "testing/viviani_forms.hpp"
#include "testing/surface_pairs.hpp"

namespace ssimarch {
namespace {

using testing::allocations_of;

#define SSIMARCH_SKIP_WITHOUT_COUNTER() \
  if (!testing::counting_allocations()) GTEST_SKIP() << "allocations are not counted under AddressSanitizer"

using testing::start_on_viviani;
using testing::viviani_problems;

// Allocations per accepted point of Tracer::march_until_event: the difference between a march of
// 400 points and one of 200, less the growth of a std::vector<CurvePoint> from 200 to 400 points
// (the output itself); every point checked on both surfaces.
double march_allocations_per_point(const Problem& P) {
  TraceOptions o;
  o.step_length = 0.01;
  const Tracer tracer(P, o);
  const UnknownVec x0 = start_on_viviani(P);
  const CurvePoint start{x0, P.point(x0), curve_jet_dynamic(P, x0, 1).tangent()};
  auto run = [&](int n) {
    MarchLimits limits = tracer.limits();
    limits.max_points = n;
    limits.detect_closure = false;
    TraceStats stats;
    MarchResult r;
    const long a = allocations_of([&] { r = tracer.march_until_event(start, Direction::kForward, limits, &stats); });
    EXPECT_EQ(r.points.size(), static_cast<std::size_t>(n));
    for (const CurvePoint& c : r.points) {
      EXPECT_NEAR(c.p.norm(), 2.0, 1e-10);
      EXPECT_NEAR(std::hypot(c.p.x(), c.p.y() + 1), 1.0, 1e-10);
    }
    return a;
  };
  auto growth = [&P](int n) {
    return allocations_of([&] {
      CurvePoint point;
      point.x = UnknownVec::Zero(P.dim());
      point.p.setZero();
      point.t.setZero();
      std::vector<CurvePoint> v;
      for (int i = 0; i < n; ++i) v.push_back(point);
    });
  };
  run(200);  // warm-up: first-use allocations (caches, the pool) are not per point
  const long a200 = run(200), a400 = run(400);
  const long output = growth(400) - growth(200);
  std::printf("%s: %ld allocations for 200 points, %ld for 400 (output vector growth %ld)\n",
              std::string(to_string(P.kind())).c_str(), a200, a400, output);
  return static_cast<double>(a400 - a200 - output) / 200.0;
}

TEST(Allocation, MarchingLoopAllocatesNothingPerAcceptedPoint) {
  SSIMARCH_SKIP_WITHOUT_COUNTER();
  for (const Problem& P : viviani_problems()) {
    const double per_point = march_allocations_per_point(P);
    std::printf("%s marching loop: %.3f allocations per accepted point\n", std::string(to_string(P.kind())).c_str(),
                per_point);
    EXPECT_EQ(per_point, 0.0) << to_string(P.kind());
  }
}

}  // namespace
}  // namespace ssimarch
