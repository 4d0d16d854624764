// A traced curve's length against its closed form where the curvature varies most: Bernoulli's
// lemniscate, the plane x = 1 on the torus R = 2, r = 1 (a = 2 sqrt 2, length 2 varpi a with
// varpi = Gamma(1/4)^2 / (2 sqrt(2 pi))). The circular-arc estimate alone loses 2e-8 .. 7e-8
// near the node (docs/marching.md, "Length."); with its shortfall added, under 1e-10.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {
namespace {

const char* kLemniscate = R"json({
  "surfaces": {"a": {"torus": {"center": [0,0,0], "axis": [0,0,1], "reference": [1,0,0], "major_radius": 2, "minor_radius": 1}},
               "b": {"plane": {"point": [1,0,0], "normal": [1,0,0], "u": [-5,5], "v": [-5,5]}}},
  "intersections": [
    {"name": "ii", "surfaces": ["a", "b"], "as": ["implicit", "implicit"]},
    {"name": "ip", "surfaces": ["a", "b"], "as": ["implicit", "parametric"]}
  ]})json";

// Relative error of the length (model units) at the default options: 1e-10, a tenth of what
// the longest-step form reaches (3e-11) being 1e-10 / 3.
constexpr double kLengthTolerance = 1e-10;

TEST(TracedLength, LemniscateInTwoFormsMatchesItsClosedForm) {
  const double varpi = std::pow(std::tgamma(0.25), 2) / (2 * std::sqrt(2 * std::numbers::pi));
  const double exact = 2 * varpi * 2 * std::sqrt(2.0);
  const TraceJobResult job = trace_scene(parse_scene(kLemniscate, "lemniscate.json"));
  ASSERT_EQ(job.runs.size(), 2u);
  for (const IntersectionRun& run : job.runs) {
    double length = 0;
    for (const TracedCurve& c : run.result.curves) length += c.length;
    EXPECT_NEAR(length, exact, kLengthTolerance * exact) << run.spec.name;
  }
}

}  // namespace
}  // namespace ssimarch
