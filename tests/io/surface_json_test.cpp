// Scene-file surfaces: every type, constants and expressions as numbers, errors with JSON paths.
#include "ssimarch/io/surface_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "testing/matchers.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch {
namespace {

using nlohmann::json;
constexpr double kPi = std::numbers::pi;

const Constants kConstants{{"R", 2.0}, {"h", 0.5}};

Surface parse(const char* text) { return surface_from_json(json::parse(text), kConstants, "surfaces.s"); }

double f(const Surface& s, const Vec3& p) { return s.value<double>(Vec3T<double>(p)); }

TEST(SurfaceJson, IssueExampleScene) {
  const json scene = json::parse(R"j({
    "sphere": {"sphere": {"center": [0,0,0], "radius": "R"}},
    "cyl":    {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]},
    "cyl2":   {"implicit": "x^2+y^2-x", "box": [[-2,2],[-2,2],[-2,2]]}})j");
  const Surface sphere = surface_from_json(scene["sphere"], kConstants, "surfaces.sphere");
  EXPECT_EQ(sphere.type_name(), "sphere");
  EXPECT_DOUBLE_EQ(sphere.get_if<Sphere>()->radius(), 2.0);
  EXPECT_NEAR(f(sphere, Vec3(0, 2, 0)), 0, 1e-15);
  const Surface cyl = surface_from_json(scene["cyl"], kConstants, "surfaces.cyl");
  EXPECT_EQ(cyl.type_name(), "parametric");
  EXPECT_FALSE(cyl.is_implicit());
  EXPECT_TRUE(cyl.domain().periodic_u);
  EXPECT_FALSE(cyl.domain().periodic_v);
  EXPECT_DOUBLE_EQ(cyl.domain().u.hi, 2 * kPi);
  EXPECT_EQ(cyl.domain().v.lo, -3);
  EXPECT_THAT(point(cyl, kPi / 2, 0.25), testing::IsNear(Vec3(0, 0, 0.25), 1e-15));
  const Surface cyl2 = surface_from_json(scene["cyl2"], kConstants, "surfaces.cyl2");
  EXPECT_EQ(cyl2.type_name(), "implicit");
  EXPECT_FALSE(cyl2.is_parametric());
  EXPECT_EQ(cyl2.box().y.lo, -2);
  EXPECT_NEAR(f(cyl2, Vec3(1, 0, 5)), 0, 1e-15);
  EXPECT_NEAR(f(cyl2, Vec3(2, 1, 0)), 3, 1e-15);
}

TEST(SurfaceJson, EveryPrimitive) {
  struct Case {
    const char* text;
    const char* type;
    Vec3 on;  // a point on the surface
  };
  const Case cases[] = {
      {R"j({"plane": {"point": [0,0,"h"], "normal": [0,0,2], "u": [-2, 2]}})j", "plane", Vec3(1.5, 0.3, 0.5)},
      {R"j({"sphere": {"center": [1,0,0], "radius": 1, "axis": [1,1,0], "reference": [0,0,1]}})j", "sphere", Vec3(2, 0, 0)},
      {R"j({"cylinder": {"point": [0,0,0], "axis": [1,0,0], "radius": "h", "range": [-1, 4]}})j", "cylinder",
       Vec3(7, 0, -0.5)},
      {R"j({"cone": {"apex": [0,0,1], "axis": [0,0,-1], "half_angle": "pi/4", "range": [0, 2]}})j", "cone",
       Vec3(0.5, 0, 0.5)},
      {R"j({"torus": {"center": [0,0,0], "axis": [0,0,1], "major_radius": "R", "minor_radius": "h"}})j", "torus",
       Vec3(0, 2.5, 0)},
      {R"j({"ellipsoid": {"center": [0,0,0], "radii": [1, 2, "R+1"]}})j", "ellipsoid", Vec3(0, 0, 3)},
      {R"j({"paraboloid": {"vertex": [0,0,0], "axis": [0,0,1], "focal_length": 0.25}})j", "paraboloid", Vec3(1, 0, 1)},
      {R"j({"paraboloid": {"vertex": [0,0,0], "axis": [0,0,1], "focal_length": [0.25, 1], "v": [0, 3]}})j", "paraboloid",
       Vec3(1, 2, 2)},
      {R"j({"capsule": {"center": [0,0,0], "axis": [0,1,0], "radius": 1, "length": 2}})j", "capsule", Vec3(0, 2, 0)},
      {R"j({"spherocylinder": {"center": [0,0,0], "axis": [0,1,0], "radius": 1, "length": 2}})j", "capsule",
       Vec3(1, -1, 0)},
  };
  for (const Case& c : cases) {
    const Surface s = parse(c.text);
    EXPECT_EQ(s.type_name(), c.type) << c.text;
    EXPECT_TRUE(s.is_parametric() && s.is_implicit());
    EXPECT_NEAR(f(s, c.on), 0, 1e-15) << c.text;
  }
  EXPECT_DOUBLE_EQ(parse(R"j({"plane": {"point": [0,0,0], "normal": [0,0,1], "u": [-2, 2]}})j").domain().u.lo, -2);
  EXPECT_DOUBLE_EQ(parse(R"j({"plane": {"point": [0,0,0], "normal": [0,0,1]}})j").domain().v.hi, 1);
  EXPECT_DOUBLE_EQ(parse(R"j({"cone": {"apex": [0,0,0], "axis": [0,0,1], "half_angle": 0.3}})j").domain().v.lo, 0);
  const Surface sph = parse(R"j({"sphere": {"center": [1,0,0], "radius": 1, "axis": [1,1,0], "reference": [0,0,1]}})j");
  EXPECT_THAT(sph.get_if<Sphere>()->frame().e0, testing::IsNear(Vec3::UnitZ(), 1e-15));
}

TEST(SurfaceJson, Patches) {
  const Surface b = parse(R"j({"bezier": {"control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,"R/2"]]]}})j");
  EXPECT_EQ(b.type_name(), "bezier");
  EXPECT_THAT(point(b, 0.5, 0.5), testing::IsNear(Vec3(0.5, 0.5, 0.25), 1e-15));
  const Surface rb = parse(R"j({"bezier": {"control_points": [[[1,0,0],[1,0,1]],[[1,1,0],[1,1,1]],[[0,1,0],[0,1,1]]],
                                           "weights": [[1,1],["sqrt(2)/2","sqrt(2)/2"],[1,1]]}})j");
  const Vec3 p = point(rb, 0.3, 0.6);
  EXPECT_NEAR(std::hypot(p.x(), p.y()), 1, 1e-15);
  const Surface n = parse(R"j({"nurbs": {"degree": [2, 1], "knots_u": [0,0,0,1,1,1], "knots_v": [0,0,1,1],
                                        "control_points": [[[1,0,0],[1,0,1]],[[1,1,0],[1,1,1]],[[0,1,0],[0,1,1]]],
                                        "weights": [[1,1],[0.7071067811865476,0.7071067811865476],[1,1]]}})j");
  EXPECT_EQ(n.type_name(), "bspline");
  EXPECT_THAT(point(n, 0.3, 0.6), testing::IsNear(p, 1e-15));
  const Surface bs = parse(R"j({"bspline": {"degree": 1, "knots_u": [0,0,1,1], "knots_v": [0,0,"h",1,1],
                                         "control_points": [[[0,0,0],[0,1,0],[0,2,1]],[[1,0,0],[1,1,0],[1,2,1]]]}})j");
  EXPECT_THAT(point(bs, 0.5, 0.75), testing::IsNear(Vec3(0.5, 1.5, 0.5), 1e-15));
}

// The InputError's where() and a fragment of its message.
void expect_error(const char* text, const std::string& where, const std::string& fragment) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), where) << text << "\n  " << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
        << text << "\n  message: " << e.what() << "\n  expected to contain: " << fragment;
  }
}

TEST(SurfaceJson, ErrorsNameTheirPath) {
  expect_error(R"j({"sphre": {"center": [0,0,0], "radius": 1}})j", "surfaces.s", "unknown surface type 'sphre'");
  expect_error(R"j({"sphre": {}})j", "surfaces.s", "known types: plane, sphere, cylinder");
  expect_error(R"j({})j", "surfaces.s", "unknown surface type (empty object)");
  expect_error(R"j([1, 2])j", "surfaces.s", "must be an object");
  expect_error(R"j({"sphere": {"radius": 1}, "torus": {}})j", "surfaces.s", "exactly one type key");
  expect_error(R"j({"sphere": {"radius": 1}})j", "surfaces.s.sphere", "missing key 'center'");
  expect_error(R"j({"sphere": {"center": [0,0], "radius": 1}})j", "surfaces.s.sphere.center", "got 2 components");
  expect_error(R"j({"sphere": {"center": [0,0,"q"], "radius": 1}})j", "surfaces.s.sphere.center[2]", "q");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": -1}})j", "surfaces.s.sphere.radius", "must be > 0, got -1");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": "R-2"}})j", "surfaces.s.sphere.radius", "must be > 0, got 0");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": "0/0"}})j", "surfaces.s.sphere.radius", "");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": "log(-1)"}})j", "surfaces.s.sphere.radius", "");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": true}})j", "surfaces.s.sphere.radius",
               "expected a number or an expression string, got a boolean");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": 1, "radus": 2}})j", "surfaces.s.sphere.radus",
               "unknown key 'radus'");
  expect_error(R"j({"sphere": {"center": [0,0,0], "radius": 1}, "color": "red"})j", "surfaces.s.color", "unknown key");
  expect_error(R"j({"cylinder": {"point": [0,0,0], "axis": [0,0,0], "radius": 1}})j", "surfaces.s.cylinder.axis",
               "non-zero vector");
  expect_error(R"j({"cylinder": {"point": [0,0,0], "axis": [0,0,1], "radius": 1, "range": [2, 2]}})j",
               "surfaces.s.cylinder.range", "lo < hi");
  expect_error(R"j({"cylinder": {"point": [0,0,0], "axis": [0,0,1], "radius": 1, "range": [0, 1, 2]}})j",
               "surfaces.s.cylinder.range", "interval [lo, hi]");
  expect_error(R"j({"cylinder": {"point": [0,0,0], "axis": [0,0,1], "radius": 1, "reference": [0,0,5]}})j",
               "surfaces.s.cylinder.reference", "must not be parallel to the axis");
  expect_error(R"j({"cone": {"apex": [0,0,0], "axis": [0,0,1], "half_angle": "pi/2"}})j", "surfaces.s.cone.half_angle",
               "(0, pi/2)");
  expect_error(R"j({"torus": {"center": [0,0,0], "axis": [0,0,1], "major_radius": 2, "minor_radius": 0}})j",
               "surfaces.s.torus.minor_radius", "> 0");
  expect_error(R"j({"ellipsoid": {"center": [0,0,0], "radii": [1, 2]}})j", "surfaces.s.ellipsoid.radii", "3 radii");
  expect_error(R"j({"paraboloid": {"vertex": [0,0,0], "axis": [0,0,1], "focal_length": [1, -1]}})j",
               "surfaces.s.paraboloid.focal_length[1]", "> 0");
  expect_error(R"j({"capsule": {"center": [0,0,0], "axis": [0,0,1], "radius": 1, "length": -2}})j",
               "surfaces.s.capsule.length", ">= 0");
  expect_error(R"j({"spherocylinder": {"center": [0,0,0], "axis": [0,0,1], "radius": 1}})j",
               "surfaces.s.spherocylinder", "missing key 'length'");
}

TEST(SurfaceJson, ExpressionErrorsNameTheirPath) {
  expect_error(R"j({"parametric": ["cos(u)", "sin(u", "v"], "u": [0, 1], "v": [0, 1]})j", "surfaces.s.parametric[1]",
               "column");
  expect_error(R"j({"parametric": ["cos(u)", "w", "v"], "u": [0, 1], "v": [0, 1]})j", "surfaces.s.parametric[1]", "w");
  expect_error(R"j({"parametric": ["u", "v"], "u": [0, 1], "v": [0, 1]})j", "surfaces.s.parametric", "3 coordinate");
  expect_error(R"j({"parametric": ["u", "v", 0], "u": [0, 1]})j", "surfaces.s", "missing key 'v'");
  expect_error(R"j({"parametric": ["u", "v", 0], "u": [1, 0], "v": [0, 1]})j", "surfaces.s.u", "lo < hi");
  expect_error(R"j({"parametric": ["u", "v", 0], "u": [0, "2*pi"], "v": [0, 1], "periodic": ["w"]})j",
               "surfaces.s.periodic[0]", "\"u\" or \"v\"");
  expect_error(R"j({"parametric": ["u", "v", 0], "u": [0, 1], "v": [0, 1], "periodic": "u"})j", "surfaces.s.periodic",
               "array");
  expect_error(R"j({"implicit": "x^2+y^2-", "box": [[-1,1],[-1,1],[-1,1]]})j", "surfaces.s.implicit", "column");
  expect_error(R"j({"implicit": "u+x", "box": [[-1,1],[-1,1],[-1,1]]})j", "surfaces.s.implicit", "u");
  expect_error(R"j({"implicit": "x", "box": [[-1,1],[-1,1]]})j", "surfaces.s.box", "box");
  expect_error(R"j({"implicit": "x", "box": [[-1,1],[-1,1],[1,-1]]})j", "surfaces.s.box[2]", "lo < hi");
  expect_error(R"j({"implicit": "x"})j", "surfaces.s", "missing key 'box'");
  expect_error(R"j({"implicit": "x", "box": [[-1,1],[-1,1],[-1,1]], "u": [0, 1]})j", "surfaces.s.u", "unknown key");
}

TEST(SurfaceJson, PatchErrorsNameTheirPath) {
  expect_error(R"j({"bezier": {"control_points": [[[0,0,0],[0,1,0]],[[1,0,0]]]}})j", "surfaces.s.bezier.control_points[1]",
               "rectangular");
  expect_error(R"j({"bezier": {"control_points": [[[0,0,0],[0,1]],[[1,0,0],[1,1,0]]]}})j",
               "surfaces.s.bezier.control_points[0][1]", "a list of 3 numbers [x, y, z], got 2 components");
  expect_error(R"j({"bezier": {"control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]], "weights": [[1,1],[1,0]]}})j",
               "surfaces.s.bezier.weights[1][1]", "> 0");
  expect_error(R"j({"bezier": {"control_points": []}})j", "surfaces.s.bezier.control_points", "non-empty");
  expect_error(R"j({"bspline": {"degree": 1.5, "knots_u": [0,0,1,1], "knots_v": [0,0,1,1],
                               "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}})j",
               "surfaces.s.bspline.degree", "integer");
  expect_error(R"j({"bspline": {"degree": [1, 1], "knots_u": [0,0,1], "knots_v": [0,0,1,1],
                               "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}})j",
               "surfaces.s.bspline.knots_u", "4 knots");
  expect_error(R"j({"bspline": {"degree": [1, 1], "knots_u": [0,0,1,1], "knots_v": [0,1,0,1],
                               "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]}})j",
               "surfaces.s.bspline.knots_v[2]", "non-decreasing");
  expect_error(R"j({"bspline": {"degree": [1, 1], "knots_u": [0,0,1,1], "knots_v": [0,0,1,1]}})j", "surfaces.s.bspline",
               "missing key 'control_points'");
}

// Every JSON value (object member or array element) of j, as pointers into j.
void collect(json& j, std::vector<json*>& out) {
  out.push_back(&j);
  if (j.is_object() || j.is_array())
    for (auto& c : j) collect(c, out);
}

json random_value(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 11);
  switch (kind(rng)) {
    case 0: return nullptr;
    case 1: return true;
    case 2: return 0;
    case 3: return -1.5;
    case 4: return 1e300;
    case 5: return "";
    case 6: return "1/0";
    case 7: return "pi/3";
    case 8: return "((";
    case 9: return json::array({1, 2});
    case 10: return json::array({json::array({0, 1}), json::array({1, 0}), json::array({0, 1})});
    default: return json::object({{"x", 1}});
  }
}

// Seeded mutation fuzzing: any change to a valid description gives a surface or an InputError,
// never another exception or a crash.
TEST(SurfaceJson, MutatedDescriptionsFailCleanly) {
  const char* seeds[] = {
      R"j({"sphere": {"center": [0,0,0], "radius": "R", "axis": [0,1,1]}})j",
      R"j({"cone": {"apex": [0,0,1], "axis": [0,0,-1], "half_angle": "pi/4", "range": [0, 2]}})j",
      R"j({"torus": {"center": [0,0,0], "axis": [0,0,1], "major_radius": "R", "minor_radius": "h"}})j",
      R"j({"paraboloid": {"vertex": [0,0,0], "axis": [0,0,1], "focal_length": [0.25, 1], "v": [0, 3]}})j",
      R"j({"capsule": {"center": [0,0,0], "axis": [0,1,0], "radius": 1, "length": 2, "reference": [1,0,0]}})j",
      R"j({"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]})j",
      R"j({"implicit": "x^2+y^2-x", "box": [[-2,2],[-2,2],[-2,2]]})j",
      R"j({"bezier": {"control_points": [[[1,0,0],[1,0,1]],[[1,1,0],[1,1,1]],[[0,1,0],[0,1,1]]],
                      "weights": [[1,1],[0.7,0.7],[1,1]]}})j",
      R"j({"bspline": {"degree": [2, 1], "knots_u": [0,0,0,0.5,1,1,1], "knots_v": [0,0,1,1],
                       "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]],[[2,0,1],[2,1,1]],[[3,0,0],[3,1,0]]]}})j",
  };
  std::mt19937 rng(20240611);  // fixed seed: failures reproduce
  int accepted = 0, rejected = 0;
  for (const char* text : seeds) {
    for (int trial = 0; trial < 300; ++trial) {
      json j = json::parse(text);
      const int edits = 1 + trial % 3;
      for (int e = 0; e < edits; ++e) {
        std::vector<json*> nodes;  // re-collected: an edit may free the nodes below it
        collect(j, nodes);
        std::uniform_int_distribution<std::size_t> pick(0, nodes.size() - 1);
        *nodes[pick(rng)] = random_value(rng);
      }
      try {
        const Surface s = surface_from_json(j, kConstants, "surfaces.s");
        ++accepted;
        if (s.is_parametric()) {
          const ParamDomain& d = s.domain();
          (void)point(s, d.u.lo + 0.3 * d.u.width(), d.v.lo + 0.6 * d.v.width());
        }
        if (s.is_implicit()) (void)gradient(s, Vec3(0.1, 0.2, 0.3));
      } catch (const InputError& e) {
        ++rejected;
        EXPECT_FALSE(e.message().empty());
        EXPECT_EQ(e.where().rfind("surfaces.s", 0), 0u) << e.what();
      } catch (const std::exception& e) {
        ADD_FAILURE() << "unexpected exception " << e.what() << " for " << j.dump();
      }
    }
  }
  EXPECT_GT(rejected, 1000);
  EXPECT_GT(accepted, 50);
}

}  // namespace
}  // namespace ssimarch
