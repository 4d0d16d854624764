// The published table of docs/singular.md: every singular point of the thesis' ch. 5 and 6
// examples and of Viviani's curve, hunted over the whole domain, against closed forms (thesis
// ch. 5-6; oracle s003.ex18.all_singular, s003.ex21.singular_points). Prints the table:
//   build/bin/singular_tests --gtest_filter='SingularTable.*'
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "singular/pairs.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/singular/half_branches.hpp"

namespace ssimarch {
namespace {

struct Expected {
  Vec3 xyz;
  const char* type;
};
struct Row {
  const char* example;
  const char* scene;
  Problem problem;
  std::vector<Expected> expected;
};

Problem graph(const std::string& f, double lo, double hi, const std::string& level = "0") {
  return Problem(testing::param("u", "v", f, {lo, hi}, {lo, hi}), testing::implicit_surface("z-(" + level + ")", Box{{-9, 9}, {-9, 9}, {-9, 9}}),
                 PairKind::kParametricImplicit);
}
Problem graphs(const std::string& f, const std::string& g, double lo, double hi) {
  return Problem(testing::param("u", "v", f, {lo, hi}, {lo, hi}), testing::param("u", "v", g, {lo, hi}, {lo, hi}),
                 PairKind::kParametricParametric);
}

std::vector<Row> rows() {
  const double r2 = std::sqrt(0.5);
  Problem ellipsoids(testing::param("1.2*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
                     testing::param("0.9*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2.5*cos(v)", {0, 2 * M_PI}, {0, M_PI}, true),
                     PairKind::kParametricParametric);
  Problem viv_pi(testing::param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true),
                 testing::implicit_surface("(x^2+y^2+z^2-4)/4"), PairKind::kParametricImplicit);
  Problem viv_pp(testing::param("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true),
                 testing::param("2*sin(u)", "2*cos(u)*cos(v)", "2*cos(u)*sin(v)", {-M_PI / 2, M_PI / 2}, {0, 2 * M_PI}, false, true),
                 PairKind::kParametricParametric);
  Problem viv_ii(testing::implicit_surface("(x^2+(y+1)^2-1)/2"), testing::implicit_surface("(x^2+y^2+z^2-4)/4"),
                 PairKind::kImplicitImplicit);
  return {
      {"Ex. 12 3-petal relief", "thesis_ex12_three_petals", graph("(u^2+v^2)^2+3*u^2*v-v^3", -1.5, 1.5), {{{0, 0, 0}, "triple_point"}}},
      {"Ex. 13 4-petal relief", "thesis_ex13_four_petals", graph("(u^2+v^2)^3-4*u^2*v^2", -1.5, 1.5), {{{0, 0, 0}, "quadruple_point"}}},
      {"Ex. 14/15 ramphoid cusp", "thesis_ex14_ramphoid_cusp", graph("u^4+u^2*v^2-2*u^2*v-u*v^2+v^2", -1.5, 1.5),
       {{{0, 0, 0}, "ramphoid_cusp"}}},
      {"Ex. 16/30 A5 (x^2+y^6)", "thesis_ex16_isolated_point", graph("3*u^4/4+u^3+u^2/4+7*u^2*v^2/2+u*v^2+v^4", -1.5, 1.5),
       {{{0, 0, 0}, "isolated"}}},
      {"Ex. 17/26 ellipsoids", "thesis_ex17_ellipsoids", ellipsoids, {{{0, 1.6, 0}, "node"}, {{0, -1.6, 0}, "node"}}},
      {"Ex. 18/27 tacnode + node", "thesis_ex18_tacnode_node", graphs("0.2*u^4+0.1*v^4", "0.3*u^2*v-0.1*v^2+0.2*v^3", -2, 2),
       {{{0, 0, 0}, "tacnode"}, {{0, 1, 0.1}, "node"}}},
      {"Ex. 19/23 tacnode", "thesis_ex19_tacnode", graphs("-u^4-v^4", "-v^2", -1.5, 1.5), {{{0, 0, 0}, "tacnode"}}},
      {"Ex. 20/28 cardioid", "thesis_ex20_cardioid", graph("u^4+v^4-4*u^3-4*u*v^2+2*u^2*v^2-4*v^2", -5, 5), {{{0, 0, 0}, "cusp"}}},
      {"Ex. 21/24 double eight, z = 11/12", "thesis_ex21_double_eight", graph("u^6/6-5*u^4/4+2*u^2+v^2", -3, 3, "11/12"),
       {{{-1, 0, 11.0 / 12}, "node"}, {{1, 0, 11.0 / 12}, "node"}}},
      {"Ex. 21/36 at the printed 0.917", "thesis_ex21_double_eight", graph("u^6/6-5*u^4/4+2*u^2+v^2", -3, 3, "0.917"), {}},
      {"Ex. 22/25 cusp", "thesis_ex22_cusp", graph("u^3-v^2", -1.5, 1.5), {{{0, 0, 0}, "cusp"}}},
      {"Ex. 35 tacnode loops", "thesis_ex35_tacnode_loops", graph("-u^4+v^2-v^4", -1.5, 1.5), {{{0, 0, 0}, "tacnode"}}},
      {"Ex. 40 four nodes", "thesis_ex40_four_nodes", graph("u^4-u^2+v^4-v^2", -1.5, 1.5, "-0.25"),
       {{{0, r2, -0.25}, "node"}, {{0, -r2, -0.25}, "node"}, {{r2, 0, -0.25}, "node"}, {{-r2, 0, -0.25}, "node"}}},
      {"Ex. 41 devil's curve", "thesis_ex41_devils_curve", graph("v^4-v^2-u^4+2*u^2", -2, 2), {{{0, 0, 0}, "node"}}},
      {"Viviani R = 2 (param.-implicit)", "viviani", viv_pi, {{{0, -2, 0}, "node"}}},
      {"Viviani R = 2 (param.-param.)", "viviani", viv_pp, {{{0, -2, 0}, "node"}}},
      {"Viviani R = 2 (implicit-implicit)", "viviani", viv_ii, {{{0, -2, 0}, "node"}}},
  };
}

TEST(SingularTable, ThesisExamplesAndViviani) {
  std::printf("\n| example | scene (examples/) | pair | found / expected | types | max location error | half-branches | time |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows()) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<SingularLocation> found = hunt_singular_points(r.problem);
    std::string types;
    double worst = 0;
    int matched = 0, halves = 0;
    for (const SingularLocation& s : found) {
      const LocalCurve c = local_curve(r.problem, s.x);
      const Classification k = classify(c.h);
      halves += static_cast<int>(half_branches(r.problem, c, k).size());
      types += std::string(types.empty() ? "" : ", ") + std::string(to_string(k.type)) + (k.ak.empty() ? "" : " " + k.ak);
      for (const Expected& e : r.expected)
        if ((s.point - e.xyz).norm() < 1e-6) {
          ++matched;
          worst = std::max(worst, (s.point - e.xyz).norm());
          EXPECT_EQ(to_string(k.type), e.type) << r.example;
        }
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("| %s | %s | %s | %zu / %zu | %s | %.1e | %d | %.0f ms |\n", r.example, r.scene,
                std::string(to_string(r.problem.kind())).c_str(), found.size(), r.expected.size(),
                types.empty() ? "-" : types.c_str(), worst, halves, ms);
    EXPECT_EQ(found.size(), r.expected.size()) << r.example;
    EXPECT_EQ(matched, static_cast<int>(r.expected.size())) << r.example;
    EXPECT_LE(worst, 1e-10) << r.example;
  }
}

}  // namespace
}  // namespace ssimarch
