// A coarse constant step gives the curve network of the default trace (issues 10 and 11: every
// singular point located, never stepped over; every branch exactly once). The scenes with
// singular points of the thesis' chapters 5 and 6 and the Viviani curves, traced with the
// constant rule at scale/25 and scale/10 (scale = the problem's region diagonal, the coarse
// trace of bench/spline-table), against the default (chordal) trace of the same scene: the same
// number of curves, the same closed flags, the same singular points (type and point), the total
// length to kLengthTolerance relative, and no more points than the default trace.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/start/start_points.hpp"
#include "ssimarch/start/start_tolerances.hpp"

namespace ssimarch {
namespace {

// Relative tolerance on a network's total length. Both traces sum circular-arc estimates over
// their chords (march/tracer.hpp, arc_length_estimate), whose error falls like the fourth power
// of the step: at scale/10 the coarse sum is measured 1e-4 relative off on the cardioid, so the
// test asks what the estimate can give at these steps, and the exact bound of the issue (1e-6)
// is reported in docs/benchmarks.md.
constexpr double kLengthTolerance = 2e-3;
// Singular points of two traces are the same point when this close (model units): both are
// located to 1e-10 from their own traced neighbourhoods (singular/locate.hpp).
constexpr double kSingularPointTolerance = 1e-7;

struct Summary {
  std::vector<bool> closed;
  std::vector<std::pair<SingularType, Vec3>> singular;
  double length = 0;
  long points = 0;
};

Summary summary(const IntersectionRun& run) {
  Summary s;
  for (const TracedCurve& c : run.result.curves) {
    s.closed.push_back(c.closed);
    s.length += c.length;
    s.points += static_cast<long>(c.points.size());
  }
  std::sort(s.closed.begin(), s.closed.end());
  for (const SingularPointReport& r : run.result.singular_points) s.singular.push_back({r.type, r.p});
  return s;
}

void expect_same_singular_points(const Summary& a, const Summary& b) {
  ASSERT_EQ(a.singular.size(), b.singular.size());
  for (const auto& [type, p] : a.singular) {
    const bool found = std::any_of(b.singular.begin(), b.singular.end(), [&](const auto& q) {
      return q.first == type && (q.second - p).norm() <= kSingularPointTolerance;
    });
    EXPECT_TRUE(found) << to_string(type) << " at " << p.transpose() << " is not found by the coarse trace";
  }
}

struct CoarseCase {
  std::string scene;
  double fraction;  // the constant step, a fraction of the problem's scale
};

void PrintTo(const CoarseCase& c, std::ostream* os) { *os << c.scene << " at step " << c.fraction << " scale"; }

class CoarseStep : public ::testing::TestWithParam<CoarseCase> {};

TEST_P(CoarseStep, SameNetworkAsTheDefaultTrace) {
  const Scene scene =
      load_scene(std::filesystem::path(SSIMARCH_SOURCE_DIR) / "examples" / (GetParam().scene + ".json"));
  for (const IntersectionSpec& spec : scene.intersections) {
    SCOPED_TRACE(spec.name);
    const IntersectionRun fine = run_intersection(scene, spec);
    IntersectionSpec coarse_spec = spec;
    coarse_spec.options.trace.step = StepRule::kConstant;
    coarse_spec.options.trace.step_length = GetParam().fraction * fine.problem.scale();
    const IntersectionRun coarse = run_intersection(scene, coarse_spec);
    const Summary a = summary(fine), b = summary(coarse);
    EXPECT_EQ(b.closed.size(), a.closed.size());
    EXPECT_EQ(b.closed, a.closed);
    expect_same_singular_points(a, b);
    EXPECT_NEAR(b.length, a.length, kLengthTolerance * a.length);
    EXPECT_LE(b.points, a.points) << "the coarse trace takes more points than the default one";
  }
}

std::vector<CoarseCase> cases() {
  std::vector<CoarseCase> out;
  for (const char* s : {"thesis_ex12_three_petals", "thesis_ex13_four_petals", "thesis_ex20_cardioid",
                        "thesis_ex21_double_eight", "thesis_ex22_cusp", "thesis_ex35_tacnode_loops",
                        "thesis_ex40_four_nodes", "thesis_ex41_devils_curve", "viviani"})
    for (double f : {1.0 / 25, 1.0 / 10}) out.push_back({s, f});
  return out;
}

std::string case_name(const ::testing::TestParamInfo<CoarseCase>& c) {
  return c.param.scene + "_scale_over_" + std::to_string(static_cast<int>(std::lround(1 / c.param.fraction)));
}

INSTANTIATE_TEST_SUITE_P(SingularScenes, CoarseStep, ::testing::ValuesIn(cases()), case_name);

// Whether a start is on a singular point is decided in model units (start_tolerances.hpp), not
// by the rank ratio alone nor by the step: on the four-petal rose r = |sin 2 phi| (Ex. 13, curve
// points (r cos phi, r sin phi) with sin 2 phi = r), a point 0.03 from the quadruple point has a
// rank ratio below kSuspectSingularRankRatio (it falls like d^3) but is a regular start at the
// coarse step; one 1e-7 from it (inside the radius, 0.0245 here) is moved off it.
TEST(CoarseStep, StartNearTheQuadruplePointIsSingularOnlyWithinTheRadius) {
  const Scene scene =
      load_scene(std::filesystem::path(SSIMARCH_SOURCE_DIR) / "examples" / "thesis_ex13_four_petals.json");
  const IntersectionSpec& spec = scene.intersections.at(0);
  const IntersectionRun run = run_intersection(scene, spec);
  TraceOptions o = spec.options.trace;
  o.step = StepRule::kConstant;
  o.step_length = run.problem.scale() / 25;
  o.tolerance = 1e-12;  // stated: the radius 0.0245 is for it (the default, 1e-13 x 71 here, gives 0.04)
  const Tracer tracer(run.problem, o);
  const double radius = singular_start_radius(tracer.options().tolerance, run.problem.scale());
  auto curve_point = [](double r) {
    const double phi = 0.5 * std::asin(r);
    VecX x(2);
    x << r * std::cos(phi), r * std::sin(phi);
    return x;
  };
  const VecX far = curve_point(0.03), near = curve_point(1e-7);
  ASSERT_GT(0.03, radius);
  ASSERT_LT(Problem::rank_ratio(run.problem.linearize(far)), kSuspectSingularRankRatio);
  std::vector<std::string> warnings;
  EXPECT_EQ((regular_start(tracer, far, &warnings) - far).norm(), 0.0);
  EXPECT_TRUE(warnings.empty());
  EXPECT_GT((regular_start(tracer, near, &warnings) - near).norm(), 0.0);
  EXPECT_EQ(warnings.size(), 1u);
}

}  // namespace
}  // namespace ssimarch
