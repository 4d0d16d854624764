// Pairs of the seeded stress run (scripts/stress, docs/topology.md "Stress run") that failed
// issue 11's "every branch exactly once", kept as scenes in tests/trace/data:
//  * loops missed when the certified search is not certified (39 torus x torus implicit-implicit,
//    146 torus x torus parametric-implicit, 314 sphere x ellipsoid parametric-parametric): the
//    trace must find the curves that the other formulation (surface A parametric, B implicit)
//    finds by sampling its whole domain, a different start-point path;
//  * 336 sphere x sphere parametric-parametric, whose circle was traced twice as one open curve:
//    one closed curve of the closed-form length;
//  * 74 paraboloid x blob parametric-implicit, whose curve leaves the domain edge u = lo for a
//    short excursion that one step from a start on that edge jumped over (a closed loop came
//    back): open curves ending on the edge where h(lo, v) changes sign (dense sampling);
//  * seed 12 pair 2649 sphere x ellipsoid parametric-implicit, a loop round the sphere's pole
//    whose first step from its start crossed the pole row, where the pole passage found no curve
//    point beyond the pole and the curve stopped at one point: the loop the other formulation
//    (sphere implicit, ellipsoid parametric: no pole near the curve) traces.
//  * over issue 11's 2 s CPU bound in the certified search of a parametric-parametric pair (4
//    unknowns; docs/topology.md "The 10,000 pairs"): seed 12 pair 4236, two nested spheres (no
//    curve, not certified in 20,502 boxes), now decided by the patch exclusion
//    (start/patch_exclusion.hpp); seed 11 pair 1570, torus x sphere with two closed curves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "testing/matchers.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {
namespace {

constexpr double kRelativeLength = 2e-3;  // curve lengths at the default spacing (circular-arc estimate)

std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(SSIMARCH_SOURCE_DIR) / "tests" / "trace" / "data" / name;
}

nlohmann::json read(const std::string& name) {
  std::ifstream in(data(name));
  return nlohmann::json::parse(in);
}

TraceResult trace(const nlohmann::json& scene_json, const std::string& source) {
  const Scene scene = parse_scene(scene_json.dump(), source);
  TraceJobResult r = trace_scene(scene);
  EXPECT_EQ(r.runs.size(), 1u);
  return r.runs.front().result;
}

// The same pair with A parametric and B implicit and start points by sampling the domain.
nlohmann::json sampled_reference(nlohmann::json scene) {
  for (auto& i : scene["intersections"]) {
    i["as"] = {"parametric", "implicit"};
    i["options"]["certified_start_points"] = false;
  }
  return scene;
}

std::vector<std::pair<bool, double>> summary(const TraceResult& r) {
  std::vector<std::pair<bool, double>> out;
  for (const TracedCurve& c : r.curves) out.push_back({c.closed, c.length});
  std::sort(out.begin(), out.end());
  return out;
}

class MissedLoops : public ::testing::TestWithParam<std::string> {};

TEST_P(MissedLoops, EveryCurveOfTheSampledReferenceOnce) {
  const nlohmann::json scene = read(GetParam());
  const TraceResult got = trace(scene, GetParam());
  const TraceResult ref = trace(sampled_reference(scene), GetParam() + " (parametric-implicit, sampled)");
  const auto g = summary(got), e = summary(ref);
  ASSERT_FALSE(e.empty());
  ASSERT_EQ(g.size(), e.size()) << GetParam();
  for (std::size_t k = 0; k < g.size(); ++k) {
    EXPECT_EQ(g[k].first, e[k].first) << GetParam() << " curve " << k;
    EXPECT_NEAR(g[k].second, e[k].second, kRelativeLength * e[k].second) << GetParam() << " curve " << k;
  }
  // The certificate stays honest: sampled start points are no guarantee.
  if (!got.start_search.certified) {
    EXPECT_NE(got.start_search.note.find("sampling"), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(StressSeed1, MissedLoops,
                         ::testing::Values("stress_seed1_39.json", "stress_seed1_146.json", "stress_seed1_314.json",
                                           "stress_seed11_1570.json"));

Vec3 vec(const nlohmann::json& a) { return Vec3(a[0].get<double>(), a[1].get<double>(), a[2].get<double>()); }

// Two spheres meet in a circle of radius sqrt(r1^2 - x^2), x = (d^2 + r1^2 - r2^2) / (2 d) the
// distance of its plane from the first centre, d the distance of the centres.
TEST(StressRegression, SphereSphereCircleTracedOnceAndClosed) {
  const nlohmann::json scene = read("stress_seed1_336.json");
  const auto& a = scene["surfaces"]["A"]["sphere"];
  const auto& b = scene["surfaces"]["B"]["sphere"];
  const double r1 = a["radius"].get<double>(), r2 = b["radius"].get<double>();
  const double d = (vec(a["center"]) - vec(b["center"])).norm();
  const double x = (d * d + r1 * r1 - r2 * r2) / (2 * d);
  const double length = 2 * M_PI * std::sqrt(r1 * r1 - x * x);
  const TraceResult got = trace(scene, "stress_seed1_336.json");
  ASSERT_EQ(got.curves.size(), 1u);
  EXPECT_TRUE(got.curves[0].closed);
  EXPECT_THAT(got.curves[0], testing::HasLength(length, kRelativeLength * length));
}

// The inner sphere lies inside the outer one when the centres' distance plus the smaller radius
// is below the larger radius: no curve, and the search proves it (certified, no region left).
TEST(StressRegression, NestedSpheresGiveNoCurveCertified) {
  const nlohmann::json scene = read("stress_seed12_4236.json");
  const auto& a = scene["surfaces"]["A"]["sphere"];
  const auto& b = scene["surfaces"]["B"]["sphere"];
  const double r1 = a["radius"].get<double>(), r2 = b["radius"].get<double>();
  const double d = (vec(a["center"]) - vec(b["center"])).norm();
  ASSERT_LT(d + std::min(r1, r2), std::max(r1, r2));  // nested: the reference says no curve
  const TraceResult got = trace(scene, "stress_seed12_4236.json");
  EXPECT_TRUE(got.curves.empty());
  EXPECT_TRUE(got.start_search.certified) << got.start_search.note;
  EXPECT_TRUE(got.start_search.uncertain_regions.empty());
  EXPECT_TRUE(got.isolated_points.empty());
}

TEST(StressRegression, LoopRoundAPoleIsFollowedWithShorterSteps) {
  const nlohmann::json scene = read("stress_seed12_2649.json");
  nlohmann::json swapped = scene;
  swapped["intersections"][0]["as"] = {"implicit", "parametric"};
  const auto g = summary(trace(scene, "stress_seed12_2649.json"));
  const auto e = summary(trace(swapped, "stress_seed12_2649.json (swapped forms)"));
  ASSERT_EQ(e.size(), 1u);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_TRUE(g[0].first);
  EXPECT_TRUE(e[0].first);
  EXPECT_NEAR(g[0].second, e[0].second, kRelativeLength * e[0].second);
}

TEST(StressRegression, ExcursionOutsideTheDomainIsNotJumped) {
  const nlohmann::json json = read("stress_seed1_74.json");
  const Scene scene = parse_scene(json.dump(), "stress_seed1_74.json");
  const Problem P = scene.problem(scene.intersections.at(0));
  ASSERT_EQ(P.kind(), PairKind::kParametricImplicit);
  // The sign changes of h on the edge u = lo, by sampling (the reference).
  const Interval U = P.bounds()[0], V = P.bounds()[1];
  std::vector<double> roots;
  constexpr int kSamples = 20000;
  double previous = 0;
  for (int i = 0; i <= kSamples; ++i) {
    // Sized for every pair kind (Problem::residual indexes up to 4 unknowns and 3 equations).
    const double x[4] = {U.lo, V.lo + V.width() * i / kSamples, 0, 0};
    double h[3] = {0, 0, 0};
    P.residual(x, h);
    if (i > 0 && (h[0] > 0) != (previous > 0)) roots.push_back(x[1] - 0.5 * V.width() / kSamples);
    previous = h[0];
  }
  ASSERT_GE(roots.size(), 2u);
  const TraceResult got = trace(json, "stress_seed1_74.json");
  std::vector<double> edge_ends;
  for (const TracedCurve& c : got.curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_EQ(c.start_end, Termination::kLeftDomain);
    EXPECT_EQ(c.end_end, Termination::kLeftDomain);
    for (const CurvePoint* e : {&c.points.front(), &c.points.back()})
      if (std::fabs(e->x[0] - U.lo) <= 1e-9) edge_ends.push_back(e->x[1]);
  }
  std::sort(edge_ends.begin(), edge_ends.end());
  ASSERT_EQ(edge_ends.size(), roots.size());
  for (std::size_t k = 0; k < roots.size(); ++k) EXPECT_NEAR(edge_ends[k], roots[k], V.width() / kSamples);
}

}  // namespace
}  // namespace ssimarch
