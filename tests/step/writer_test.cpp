// The STEP AP242 writer and the JSON B-spline keys: the file is read back by a minimal
// ISO 10303-21 reader (entity instances, references, B_SPLINE_CURVE_WITH_KNOTS attributes) and
// checked structurally; the JSON spline evaluates to the same curve points.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>

#include "testing/matchers.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/step/writer.hpp"
#include "ssimarch/io/trace_writers.hpp"

namespace ssimarch {
namespace {

std::vector<IntersectionRun> spline_runs() {
  Scene s = parse_scene(R"json({
    "surfaces": {"sphere": {"sphere": {"center": [0,0,0], "radius": 2}},
                 "cyl": {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]},
                 "plane": {"implicit": "z - 0.5*y - 1", "box": [[-5,5],[-5,5],[-5,5]]},
                 "halfcyl": {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "pi"], "v": [-3, 3]}},
    "intersections": [
      {"name": "viviani", "surfaces": ["sphere", "cyl"], "start": [1, -1, 1.4142], "options": {"step_length": 0.1, "bspline": true}},
      {"name": "ellipse", "surfaces": ["cyl", "plane"], "start": [0, 0, 1], "options": {"step_length": 0.3, "bspline": true}},
      {"name": "open", "surfaces": ["halfcyl", "plane"], "start": [0, 0, 1], "options": {"step_length": 0.1, "bspline": true}}
    ]})json",
                        "s.json");
  std::vector<IntersectionRun> runs;
  for (const auto& spec : s.intersections) runs.push_back(run_intersection(s, spec));
  return runs;
}

// A minimal Part 21 reader: "#id=TEXT;" instances of the DATA section.
std::map<int, std::string> read_instances(const std::string& file) {
  std::map<int, std::string> out;
  const std::size_t data = file.find("DATA;");
  const std::size_t end = file.find("ENDSEC;", data);
  std::istringstream in(file.substr(data + 5, end - data - 5));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::size_t eq = line.find('=');
    EXPECT_EQ(line[0], '#');
    EXPECT_EQ(line.back(), ';');
    out[std::stoi(line.substr(1, eq - 1))] = line.substr(eq + 1, line.size() - eq - 2);
  }
  return out;
}

// The top-level parenthesised lists of "NAME(a,(b,c),...)" as strings.
std::vector<std::string> attributes(const std::string& instance) {
  std::vector<std::string> a;
  int depth = 0;
  std::string cur;
  for (char ch : instance.substr(instance.find('(') + 1, instance.rfind(')') - instance.find('(') - 1)) {
    if (ch == ',' && depth == 0) {
      a.push_back(cur);
      cur.clear();
      continue;
    }
    depth += ch == '(' ? 1 : (ch == ')' ? -1 : 0);
    cur += ch;
  }
  a.push_back(cur);
  return a;
}

std::vector<std::string> items(const std::string& list) { return attributes("X" + list); }

TEST(StepWriter, WritesEveryCurveAndPcurveAsConsistentBSplines) {
  const auto runs = spline_runs();
  std::ostringstream os;
  write_step(os, runs);
  const std::string file = os.str();
  EXPECT_EQ(file.rfind("ISO-10303-21;\nHEADER;", 0), 0u);
  EXPECT_NE(file.find("FILE_SCHEMA(('AP242_MANAGED_MODEL_BASED_3D_ENGINEERING_MIM_LF"), std::string::npos);
  EXPECT_EQ(file.substr(file.size() - 18), "END-ISO-10303-21;\n");
  const auto inst = read_instances(file);
  // Every reference resolves.
  const std::regex ref("#([0-9]+)");
  for (const auto& [id, text] : inst)
    for (auto it = std::sregex_iterator(text.begin(), text.end(), ref); it != std::sregex_iterator(); ++it)
      EXPECT_TRUE(inst.count(std::stoi((*it)[1]))) << "#" << id << " refers to " << (*it)[0];
  std::size_t expected = 0, expected_3d = 0;
  for (const auto& r : runs)
    for (const auto& s : r.splines) {
      ASSERT_TRUE(s);
      expected += 1 + s->pcurves.size();
      ++expected_3d;
    }
  std::size_t curves = 0, closed = 0, points_2d = 0;
  for (const auto& [id, text] : inst) {
    if (text.rfind("B_SPLINE_CURVE_WITH_KNOTS(", 0) != 0) continue;
    ++curves;
    const auto a = attributes(text);
    ASSERT_EQ(a.size(), 9u) << text;
    const int degree = std::stoi(a[1]);
    EXPECT_EQ(degree, 5);
    const auto cps = items(a[2]), mults = items(a[6]), knots = items(a[7]);
    int sum = 0;
    for (const auto& m : mults) sum += std::stoi(m);
    EXPECT_EQ(sum, static_cast<int>(cps.size()) + degree + 1) << text.substr(0, 60);
    EXPECT_EQ(mults.size(), knots.size());
    for (std::size_t k = 1; k < knots.size(); ++k) EXPECT_LT(std::stod(knots[k - 1]), std::stod(knots[k]));
    closed += a[4] == ".T.";
    const int dim = static_cast<int>(items(attributes(inst.at(std::stoi(cps[0].substr(1))))[1]).size());
    EXPECT_TRUE(dim == 2 || dim == 3);
    points_2d += dim == 2;
  }
  EXPECT_EQ(curves, expected);
  EXPECT_EQ(curves - points_2d, expected_3d);
  EXPECT_EQ(closed, 2u);  // viviani (periodic 3D) and the ellipse; p-curves winding the cylinder are not
}

TEST(StepWriter, JsonSplineMatchesTheCurvePoints) {
  const auto runs = spline_runs();
  const nlohmann::json j = to_json(runs[2]);  // the open half ellipse
  const auto& c = j["curves"][0];
  ASSERT_TRUE(c.contains("bspline"));
  ASSERT_EQ(c["pcurves"].size(), 1u);
  EXPECT_EQ(c["pcurves"][0]["surface"], "halfcyl");
  EXPECT_LE(c["max_deviation"].get<double>(), c["bspline"]["tolerance"].get<double>());
  BSplineCurve b{c["bspline"]["degree"], c["bspline"]["periodic"], c["bspline"]["knots"], {}};
  for (const auto& p : c["bspline"]["control_points"]) b.control_points.push_back(Vec3(p[0], p[1], p[2]));
  // The spline passes through the traced points at their arc lengths; the ends exactly.
  const auto& pts = c["points"];
  const Vec3 first(pts[0]["xyz"][0], pts[0]["xyz"][1], pts[0]["xyz"][2]);
  const auto& l = pts[pts.size() - 1]["xyz"];
  EXPECT_THAT(b.at(b.start()), testing::IsNear(first, 1e-14));
  EXPECT_THAT(b.at(b.end()), testing::IsNear(Vec3(l[0], l[1], l[2]), 1e-14));
  EXPECT_NEAR(b.end(), runs[2].result.curves[0].length, 1e-6);
}

TEST(StepWriter, RefusesRunsWithoutSplines) {
  std::vector<IntersectionRun> none;
  std::ostringstream os;
  EXPECT_THROW(write_step(os, none), InputError);
}

}  // namespace
}  // namespace ssimarch
