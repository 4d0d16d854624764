// Scene files: valid scenes, pair-kind choice, and every error with its location.
#include "ssimarch/io/scene.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ssimarch/core/error.hpp"

namespace ssimarch {
namespace {

using ::testing::HasSubstr;

const char* kIssueScene = R"json({
  "constants": {"R": 2},
  "surfaces": {
    "sphere":   {"sphere": {"center": [0,0,0], "radius": "R"}},
    "cyl":      {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]},
    "cyl2":     {"implicit": "x^2+y^2-x", "box": [[-2,2],[-2,2],[-2,2]]}
  },
  "intersections": [
    {"name": "viviani", "surfaces": ["sphere", "cyl"], "start": [1, 0, 0], "options": {"step_length": 0.05}}
  ]
})json";

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Scene, TheIssueExampleParses) {
  Scene s = parse_scene(kIssueScene, "s.json");
  EXPECT_EQ(s.constants.at("R"), 2.0);
  EXPECT_EQ(s.surface_names, (std::vector<std::string>{"cyl", "cyl2", "sphere"}));  // JSON objects are sorted
  ASSERT_EQ(s.intersections.size(), 1u);
  const IntersectionSpec& i = s.intersections[0];
  EXPECT_EQ(i.name, "viviani");
  // The sphere (a primitive) is used implicitly against the parametric cylinder.
  EXPECT_EQ(i.kind, PairKind::kParametricImplicit);
  EXPECT_TRUE(i.swapped);
  ASSERT_EQ(i.starts.size(), 1u);
  EXPECT_EQ(i.starts[0], Vec3(1, 0, 0));
  EXPECT_EQ(i.options.trace.step_length, 0.05);
  Problem P = s.problem(i);
  EXPECT_EQ(P.dim(), 2);
  EXPECT_EQ(P.first().type_name(), "parametric");
}

TEST(Scene, PairKindsAndTheAsOverride) {
  Scene s = parse_scene(R"json({
    "surfaces": {"a": {"sphere": {"center": [0,0,0], "radius": 1}}, "b": {"implicit": "z", "box": [[-2,2],[-2,2],[-2,2]]},
                 "c": {"parametric": ["u","v","0"], "u": [-2,2], "v": [-2,2]}},
    "intersections": [
      {"name": "ii", "surfaces": ["a", "b"]},
      {"name": "pp", "surfaces": ["a", "c"], "as": ["parametric", "parametric"]},
      {"name": "pi", "surfaces": ["a", "c"], "as": ["implicit", "parametric"]},
      {"name": "pi2", "surfaces": ["c", "b"], "start": [[1, 0, 0], [0, "1/2", 0]]}
    ]})json", "s.json");
  EXPECT_EQ(s.intersections[0].kind, PairKind::kImplicitImplicit);
  EXPECT_EQ(s.intersections[1].kind, PairKind::kParametricParametric);
  EXPECT_EQ(s.intersections[2].kind, PairKind::kParametricImplicit);
  EXPECT_TRUE(s.intersections[2].swapped);
  EXPECT_EQ(s.intersections[3].kind, PairKind::kParametricImplicit);
  EXPECT_FALSE(s.intersections[3].swapped);
  EXPECT_EQ(s.intersections[3].starts.size(), 2u);
  EXPECT_EQ(s.intersections[3].starts[1].y(), 0.5);
}

TEST(Scene, ConstantsMayReferToEachOtherInAnyOrder) {
  Scene s = parse_scene(R"json({"constants": {"a": "b*2", "b": "c+1", "c": "pi"},
    "surfaces": {"s": {"sphere": {"center": [0,0,0], "radius": "a"}}}})json", "s.json");
  EXPECT_DOUBLE_EQ(s.constants.at("a"), 2 * (M_PI + 1));
  EXPECT_THAT(error_of(R"json({"constants": {"a": "b", "b": "a"}, "surfaces": {}})json"), HasSubstr("constants.a"));
  EXPECT_THAT(error_of(R"json({"constants": {"a": "zz+1"}, "surfaces": {}})json"), HasSubstr("zz"));
}

TEST(Scene, ALongChainOfConstantsResolvesInDependencyOrder) {
  // c0 = 1, c_k = c_(k-1) + 1, so c_k = k + 1. Trial passes took cubic time (500 constants > 20 s);
  // the dependency order compiles each constant once.
  const int n = 5000;
  std::string constants = "\"c0\": 1";
  for (int k = 1; k < n; ++k) constants += ", \"c" + std::to_string(k) + "\": \"c" + std::to_string(k - 1) + " + 1\"";
  const Scene s = parse_scene("{\"constants\": {" + constants +
                                  "}, \"surfaces\": {\"s\": {\"sphere\": {\"center\": [0,0,0], \"radius\": \"c" +
                                  std::to_string(n - 1) + "\"}}}}",
                              "s.json");
  EXPECT_EQ(s.constants.at("c" + std::to_string(n - 1)), n);
  EXPECT_EQ(s.constants.at("c1234"), 1235);
}

TEST(Scene, ACycleOfConstantsIsNamedWithItsMembers) {
  EXPECT_THAT(error_of(R"json({"constants": {"a": "c+1", "b": "a*2", "c": "b-1", "d": 4}, "surfaces": {}})json"),
              HasSubstr("constants.a: the constants refer to each other in a cycle: a -> c -> b -> a"));
  EXPECT_THAT(error_of(R"json({"constants": {"x": "x+1"}, "surfaces": {}})json"), HasSubstr("cycle: x -> x"));
}

TEST(Scene, ErrorsSayWhatAndWhere) {
  // JSON syntax: line and column.
  EXPECT_THAT(error_of("{\n  \"surfaces\": {,}\n}"), HasSubstr("s.json:2:"));
  EXPECT_THAT(error_of("[1, 2]"), HasSubstr("must be a JSON object"));
  EXPECT_THAT(error_of(R"json({"surfaces": {}})json"), HasSubstr("surfaces: must be a non-empty object"));
  EXPECT_THAT(error_of(R"json({"surfacez": {}})json"), HasSubstr("s.json: surfacez: unknown key 'surfacez'"));
  const std::string surfaces = R"json("surfaces": {"a": {"sphere": {"center": [0,0,0], "radius": 1}},
                                                "b": {"plane": {"point": [0,0,0], "normal": [0,0,1]}}})json";
  auto scene = [&](const std::string& intersection) { return "{" + surfaces + ", \"intersections\": [" + intersection + "]}"; };
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "nope"]})json")),
              HasSubstr("intersections[0].surfaces[1]: unknown surface \"nope\" (the scene defines: a, b)"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a"]})json")), HasSubstr("must be a list of the names of 2 surfaces"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "start": [1, 2]})json")),
              HasSubstr("intersections[0].start: must be a list of 3 numbers [x, y, z], got 2 components"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "start": [1, 2, "sin("]})json")), HasSubstr("start[2]"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "options": {"step_lenght": 1}})json")),
              HasSubstr("options.step_lenght: unknown option"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "options": {"tolerance": -1}})json")), HasSubstr("tolerance"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "options": {"predictor": "magic"}})json")),
              HasSubstr("unknown predictor \"magic\""));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "options": {"max_points": 2.5}})json")), HasSubstr("must be an integer"));
  EXPECT_THAT(error_of(scene(R"json({"surfaces": ["a", "b"], "as": ["implicit", "sideways"]})json")),
              HasSubstr("as[1]: must be \"parametric\" or \"implicit\""));
  EXPECT_THAT(error_of(scene(R"json({"name": "x", "surfaces": ["a", "b"]}, {"name": "x", "surfaces": ["a", "b"]})json")),
              HasSubstr("duplicate intersection name \"x\""));
}

TEST(Scene, FilesThatAreMissingEmptyOrDirectories) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "ssimarch_scene_test";
  fs::create_directories(dir);
  EXPECT_THROW(load_scene(dir / "missing.json"), InputError);
  { std::ofstream(dir / "empty.json") << "  \n"; }
  try {
    load_scene(dir / "empty.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("empty"));
  }
  EXPECT_THROW(load_scene(dir), InputError);
  { std::ofstream(dir / "ok.json") << kIssueScene; }
  EXPECT_EQ(load_scene(dir / "ok.json").intersections.size(), 1u);
  fs::remove_all(dir);
}

TEST(Scene, EveryShippedExampleLoads) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SSIMARCH_SOURCE_DIR) + "/examples")) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_NO_THROW(load_scene(entry.path())) << entry.path();
    ++n;
  }
  EXPECT_GE(n, 20);
}

}  // namespace
}  // namespace ssimarch
