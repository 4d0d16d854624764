// The certified B-splines of the thesis examples and of the benchmark pairs (bench/peers/scenes,
// every scene there) (issue 14 item 5): every curve's `max_deviation` is checked against a dense
// projection of its B-spline onto both true surfaces, independently of the fit (closest points on
// parametric surfaces, Newton along the gradient on implicit ones), and every p-curve mapped
// through its surface lands on the 3D curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch {
namespace {

// Distance from P to the implicit surface f = 0: Newton steps along the gradient (the foot of
// the perpendicular for the small distances checked here).
double distance_to_implicit(const Surface& s, const Vec3& P) {
  using J = Jet<3, 1>;
  Vec3 x = P;
  for (int it = 0; it < 20; ++it) {
    const J f = s.value(Vec3T<J>(J::variable(0, x.x()), J::variable(1, x.y()), J::variable(2, x.z())));
    const Vec3 g(f.d(0), f.d(1), f.d(2));
    const Vec3 step = f.value() / g.squaredNorm() * g;
    x -= step;
    if (step.norm() <= 1e-17) break;
  }
  return (x - P).norm();
}

double distance_to_surface(const Surface& s, const Vec3& P, const VecX* pcurve_guess) {
  if (pcurve_guess) {
    const Vec2 uv = refine_closest_parameters(s, P, Vec2((*pcurve_guess)[0], (*pcurve_guess)[1]));
    return (to_vec3(s.point(uv[0], uv[1])) - P).norm();
  }
  return distance_to_implicit(s, P);
}

struct Measured {
  double to_surfaces = 0;  // largest distance of a B-spline sample from either surface
  double pcurve_gap = 0;   // largest |S(pcurve(t)) - C(t)|
};

Measured measure(const IntersectionRun& run, const CurveSpline& sp) {
  const Problem& pr = run.problem;
  const Surface* surfaces[2] = {&pr.first(), &pr.second()};
  Measured m;
  const int samples = 16 * sp.pieces;
  for (int k = 0; k <= samples; ++k) {
    const double t = sp.curve.start() + (sp.curve.end() - sp.curve.start()) * k / samples;
    const Vec3 P = sp.curve.at(t);
    for (int i = 0; i < 2; ++i) {
      const bool parametric = static_cast<std::size_t>(i) < sp.pcurves.size();
      VecX w;
      if (parametric) {
        w = sp.pcurves[static_cast<std::size_t>(i)].at(t);
        m.pcurve_gap = std::max(m.pcurve_gap, (to_vec3(surfaces[i]->point(w[0], w[1])) - P).norm());
      }
      m.to_surfaces = std::max(m.to_surfaces, distance_to_surface(*surfaces[i], P, parametric ? &w : nullptr));
    }
  }
  return m;
}

// A scene file relative to the source tree, without ".json".
class ExampleSplines : public ::testing::TestWithParam<std::string> {};

// Every curve's spline: within its bound of both surfaces (dense), p-curves on the 3D curve,
// and within the tolerance asked. Returns how many curves and contact points the job found.
std::size_t check_splines(const TraceJobResult& job) {
  std::size_t answers = 0;
  for (const IntersectionRun& run : job.runs) {
    answers += run.result.curves.size() + run.result.isolated_points.size();
    EXPECT_EQ(run.splines.size(), run.result.curves.size());  // one spline per branch
    for (std::size_t c = 0; c < run.splines.size(); ++c) {
      if (!run.splines[c]) continue;
      const CurveSpline& sp = *run.splines[c];
      const double floor = 1e-13 * run.problem.scale();  // rounding of the projections
      const Measured m = measure(run, sp);
      EXPECT_LE(m.to_surfaces, sp.max_deviation + floor) << run.spec.name << " curve " << c;
      EXPECT_LE(m.pcurve_gap, 2 * sp.max_deviation + floor) << run.spec.name << " curve " << c;
      // A closed branch is one spline, periodic unless it passes a singular point.
      if (run.result.curves[c].closed) {
        EXPECT_EQ(sp.curve.periodic, sp.c0_knots == 0) << run.spec.name;
      }
      EXPECT_EQ(sp.curve.knots.size(), sp.curve.control_points.size() + 6);
      EXPECT_TRUE(sp.within_tolerance) << run.spec.name << " curve " << c << ": " << sp.max_deviation;
      EXPECT_LE(sp.max_deviation, sp.tolerance);
    }
  }
  return answers;
}

TEST_P(ExampleSplines, MaxDeviationBoundsTheDenseDistanceFromBothSurfaces) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/" + GetParam() + ".json");
  TraceRequest request;
  request.overrides.push_back({find_trace_option("bspline"), std::string("true"), "test"});
  // Every example and pair meets the default tolerance (1e-9 x scale) with the traced points
  // and at most a few halvings. A pair whose whole answer is a contact point (a sphere on a
  // plane) has no curve to fit, but has an answer.
  EXPECT_GT(check_splines(trace_scene(scene, request)), 0u);
}

// The cusps of the thesis examples at 1e-11 x scale from a coarse trace (constant step scale/25,
// as bench/spline-table): the pieces at the cusp in sqrt(s) and the traced points put back on
// the curve before their jets are taken (docs/math/curve_spline.md §1) make the bound reachable;
// it stopped at 1.4e-10 x scale on ex22 before.
class CoarseCuspSplines : public ::testing::TestWithParam<std::string> {};

TEST_P(CoarseCuspSplines, MeetATightToleranceFromACoarseTrace) {
  const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/examples/" + GetParam() + ".json");
  ASSERT_EQ(scene.intersections.size(), 1u);
  const double scale = scene.problem(scene.intersections[0]).scale();
  TraceRequest request;
  const std::vector<std::pair<const char*, OptionValue>> options{
      {"bspline", std::string("true")}, {"bspline_tolerance", 1e-11 * scale}, {"step", std::string("constant")},
      {"step_length", scale / 25}};
  for (const auto& [key, value] : options)
    request.overrides.push_back({find_trace_option(key), value, "test"});
  const TraceJobResult job = trace_scene(scene, request);
  EXPECT_GT(check_splines(job), 0u);
  int c1 = 0;
  for (const IntersectionRun& run : job.runs)
    for (const std::optional<CurveSpline>& sp : run.splines) c1 += sp ? sp->c1_knots : 0;
  EXPECT_GT(c1, 0);  // the pieces at the cusp are in sqrt(s)
}

INSTANTIATE_TEST_SUITE_P(Cusps, CoarseCuspSplines,
                         ::testing::Values("thesis_ex22_cusp", "thesis_ex14_ramphoid_cusp", "thesis_ex20_cardioid"));

std::vector<std::string> in_folder(const std::string& folder, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& n : names) out.push_back(folder + "/" + n);
  return out;
}

// Every scene of the peer benchmark (bench/peers/scenes), found when the test starts.
std::vector<std::string> benchmark_pairs() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SSIMARCH_SOURCE_DIR) + "/bench/peers/scenes"))
    if (e.path().extension() == ".json") out.push_back("bench/peers/scenes/" + e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& i) {
  std::string name = i.param.substr(i.param.rfind('/') + 1);
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(
    Examples, ExampleSplines,
    ::testing::ValuesIn(in_folder(
        "examples",
        {"viviani", "s000_ex2_cubic_surfaces", "s000_ex3_paraboloid_cylinder", "s000_ex4_plane_ellipsoid",
         "s000_ex5_two_cylinders", "s004_viviani_implicit", "thesis_pair1_ruled_torus", "thesis_pair2_cylinder_sphere",
         "thesis_ex12_three_petals", "thesis_ex13_four_petals", "thesis_ex14_ramphoid_cusp", "thesis_ex17_ellipsoids",
         "thesis_ex18_tacnode_node", "thesis_ex19_tacnode", "thesis_ex20_cardioid", "thesis_ex21_double_eight",
         "thesis_ex22_cusp", "thesis_ex35_tacnode_loops", "thesis_ex38_two_loops", "thesis_ex39_paraboloid_sine",
         "thesis_ex40_four_nodes", "thesis_ex41_devils_curve"})),
    test_name);

INSTANTIATE_TEST_SUITE_P(BenchmarkPairs, ExampleSplines, ::testing::ValuesIn(benchmark_pairs()), test_name);

}  // namespace
}  // namespace ssimarch
