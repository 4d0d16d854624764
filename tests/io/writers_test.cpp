// Result writers: JSON keys other tools rely on, CSV and OBJ structure.
#include <gtest/gtest.h>

#include <algorithm>

#include <sstream>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/trace_writers.hpp"
#include "ssimarch/io/svg_plot.hpp"

namespace ssimarch {
namespace {

std::vector<IntersectionRun> viviani_runs() {
  Scene s = parse_scene(R"json({
    "surfaces": {"sphere": {"sphere": {"center": [0,0,0], "radius": 2}},
                 "cyl": {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]},
                 "plane": {"implicit": "z - 0.5*y - 1", "box": [[-5,5],[-5,5],[-5,5]]},
                 "halfcyl": {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "pi"], "v": [-3, 3]}},
    "intersections": [
      {"name": "viviani", "surfaces": ["sphere", "cyl"], "start": [1, -1, 1.4142], "options": {"step_length": 0.1}},
      {"name": "open", "surfaces": ["halfcyl", "plane"], "start": [0, 0, 1], "options": {"step_length": 0.1}}
    ]})json", "s.json");
  std::vector<IntersectionRun> runs;
  for (const auto& spec : s.intersections) runs.push_back(run_intersection(s, spec));
  return runs;
}

TEST(Writers, JsonHasTheDocumentedKeys) {
  auto runs = viviani_runs();
  std::ostringstream os;
  write_json(os, runs);
  auto j = nlohmann::json::parse(os.str());
  ASSERT_EQ(j["intersections"].size(), 2u);
  const auto& v = j["intersections"][0];
  EXPECT_EQ(v["name"], "viviani");
  EXPECT_EQ(v["pair_kind"], "parametric-implicit");
  EXPECT_EQ(v["unknowns"], nlohmann::json({"u", "v"}));
  ASSERT_EQ(v["curves"].size(), 1u);
  const auto& c = v["curves"][0];
  EXPECT_TRUE(c["closed"].get<bool>());
  EXPECT_NEAR(c["length"].get<double>(), 15.2807911561, 1e-5);
  EXPECT_EQ(c["points"][0]["xyz"].size(), 3u);
  EXPECT_EQ(c["points"][0]["params"].size(), 2u);
  EXPECT_EQ(c["points"].front(), c["points"].back());
  for (const char* k : {"1", "2", "3", "4", "5+"}) EXPECT_TRUE(v["stats"]["iterations"].contains(k)) << k;
  long total = 0;
  for (const auto& [k, n] : v["stats"]["iterations"].items()) total += n.get<long>();
  EXPECT_EQ(total, v["stats"]["points"].get<long>());
  EXPECT_TRUE(v["stats"].contains("time_ms"));
  EXPECT_TRUE(v["stats"].contains("rejected_steps"));
  // The work per accepted point is the two surfaces' evaluation counts over the points.
  const auto& e = v["stats"]["surface_evaluations"];
  ASSERT_EQ(e.size(), 2u);
  EXPECT_GT(e[0].get<long>(), 0);
  EXPECT_DOUBLE_EQ(v["stats"]["evaluations_per_point"].get<double>(),
                   static_cast<double>(e[0].get<long>() + e[1].get<long>()) / v["stats"]["points"].get<double>());
  const auto& o = j["intersections"][1]["curves"][0];
  EXPECT_FALSE(o["closed"].get<bool>());
  EXPECT_EQ(o["ends"]["start"]["reason"], "domain_edge");
  EXPECT_EQ(o["ends"]["end"]["reason"], "domain_edge");
}

TEST(Writers, CsvAndObj) {
  auto runs = viviani_runs();
  std::ostringstream csv, obj;
  write_csv(csv, runs);
  write_obj(obj, runs);
  std::istringstream in(csv.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "intersection,curve,point,closed,x,y,z,u,v,p,q");
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 10) << line;
  }
  EXPECT_EQ(rows, runs[0].result.curves[0].points.size() + runs[1].result.curves[0].points.size());
  // OBJ: closed curve written once, polyline back to its first vertex.
  std::string o = obj.str();
  std::size_t vertices = static_cast<std::size_t>(std::count(o.begin(), o.end(), '\n'));
  EXPECT_NE(o.find("o viviani_curve0\n"), std::string::npos);
  EXPECT_NE(o.find("o open_curve0\n"), std::string::npos);
  std::size_t n0 = runs[0].result.curves[0].points.size() - 1;  // closed: last = first
  // (built with += : GCC 12 warns falsely on " " + std::string + "..." under -O3, bug 105651)
  std::string closing = " ";
  closing += std::to_string(n0);
  closing += " 1\n";
  EXPECT_NE(o.find(closing), std::string::npos);
  EXPECT_GT(vertices, n0);
}

TEST(Writers, SvgIsWellFormed) {
  auto runs = viviani_runs();
  std::ostringstream os;
  write_svg(os, runs[0]);
  std::string s = os.str();
  EXPECT_EQ(s.rfind("<?xml", 0), 0u);
  EXPECT_NE(s.find("<polyline"), std::string::npos);
  EXPECT_NE(s.find("</svg>"), std::string::npos);
  EXPECT_EQ(s.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace ssimarch
