// STEP import: the Part 21 syntax (every parameter kind, complex instances, errors with their
// line, bounded nesting), each surface type against ISO 10303-42's closed form of its
// parameterisation, a NURBS face of an AP214-like file against the cylinder it represents, and
// the round trip through our own writer (surfaces and p-curves read back land on the 3D curve).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include "testing/matchers.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/step/reader.hpp"
#include "ssimarch/step/writer.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;

std::string step_text(const std::string& data) {
  return "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('t','',(''),(''),'','','');\n"
         "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n" +
         data + "ENDSEC;\nEND-ISO-10303-21;\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_step(text, "t.step");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StepPart21, ReadsEveryParameterKindAndComplexInstances) {
  const StepFile f =
      parse_step(step_text("/* comment */ #1=A('it''s',$,*,.T.,-1.5E-3,42,#2,\"0F\",(1,(2.,3.)),LENGTH_MEASURE(2.5));\n"
                           "#2=(B()C(1,'x')D((#1)));\n"),
                 "t.step");
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f.schemas, std::vector<std::string>{"AUTOMOTIVE_DESIGN"});
  const StepInstance& a = *f.find(1);
  EXPECT_EQ(a.line, 8);
  const auto& p = a.records[0].params;
  ASSERT_EQ(p.size(), 10u);
  EXPECT_EQ(p[0].text, "it's");
  EXPECT_EQ(p[1].kind, StepValue::Kind::kUnset);
  EXPECT_EQ(p[2].kind, StepValue::Kind::kDerived);
  EXPECT_EQ(p[3].kind, StepValue::Kind::kEnum);
  EXPECT_EQ(p[3].text, "T");
  EXPECT_EQ(p[4].kind, StepValue::Kind::kReal);
  EXPECT_EQ(p[4].number, -1.5e-3);
  EXPECT_EQ(p[5].kind, StepValue::Kind::kInteger);
  EXPECT_EQ(p[6].ref, 2);
  EXPECT_EQ(p[7].kind, StepValue::Kind::kBinary);
  ASSERT_EQ(p[8].items.size(), 2u);
  EXPECT_EQ(p[8].items[1].items[1].number, 3.0);
  EXPECT_EQ(p[9].kind, StepValue::Kind::kTyped);
  EXPECT_EQ(p[9].text, "LENGTH_MEASURE");
  EXPECT_EQ(p[9].items[0].number, 2.5);
  const StepInstance& b = *f.find(2);
  ASSERT_EQ(b.records.size(), 3u);
  EXPECT_EQ(b.type_text(), "(B C D)");
  ASSERT_NE(b.record("C"), nullptr);
  EXPECT_EQ(b.record("C")->params[1].text, "x");
}

TEST(StepPart21, ErrorsNameTheLine) {
  // The parser stops on line 10 (at #3) and names the instance left open on line 9.
  const std::string open = error_of(step_text("#1=A(1);\n#2=B(2)\n#3=C(3);\n"));
  EXPECT_NE(open.find("t.step:10: instance #2 (line 9) does not end with ';', found '#'"), std::string::npos) << open;
  EXPECT_NE(error_of(step_text("#1=A('open);\n")).find("not closed"), std::string::npos);
  EXPECT_NE(error_of(step_text("#1=A(1);\n#1=B(2);\n")).find("defined twice (first on line 8)"), std::string::npos);
  EXPECT_NE(error_of(step_text("#1=A(1.2.3);\n")).find("not a finite number"), std::string::npos);
  EXPECT_NE(error_of(step_text("#1=A(1E999);\n")).find("not a finite number"), std::string::npos);
  EXPECT_NE(error_of("ISO-10303-21;\nHEADER;\n").find("t.step:3: expected an entity name, found the end of the file"),
            std::string::npos);
  EXPECT_NE(error_of(step_text("#99999999999999999=A();\n")).find("too large"), std::string::npos);
}

TEST(StepPart21, NestingIsBounded) {
  const std::string deep = std::string(100000, '(') + std::string(100000, ')');
  EXPECT_NE(error_of(step_text("#1=A(" + deep + ");\n")).find("nested deeper than 64"), std::string::npos);
  EXPECT_NE(error_of(step_text("#1=(" + std::string(1000, '(') + ");\n")).find("t.step:8"), std::string::npos);
}

// Placement at (1, 2, 3), axis z' = (0, 0.6, 0.8), reference x' = (1, 0, 0), so y' = z' x x' =
// (0, 0.8, -0.6) (ISO 10303-42 §4.4.10); #1 is the placement.
const char* kPlacement =
    "#1=AXIS2_PLACEMENT_3D('',#2,#3,#4);\n#2=CARTESIAN_POINT('',(1.,2.,3.));\n#3=DIRECTION('',(0.,0.6,0.8));\n"
    "#4=DIRECTION('',(1.,0.,0.));\n";
const Vec3 kO(1, 2, 3), kX(1, 0, 0), kY(0, 0.8, -0.6), kZ(0, 0.6, 0.8);

Vec3 at(const Surface& s, double u, double v) {
  const Vec3T<double> p = s.point(u, v);
  return {p.x, p.y, p.z};
}

void expect_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_THAT(a, testing::IsNear(b, tol)) << a.transpose() << " vs " << b.transpose();
}

TEST(StepReader, AnalyticSurfacesFollowIso10303_42) {
  // A trimmed plane and cylinder carry their rectangle; the sphere and torus are whole.
  const StepModel m(parse_step(
      step_text(std::string(kPlacement) +
                "#10=PLANE('',#1);\n#11=RECTANGULAR_TRIMMED_SURFACE('',#10,-1.,2.,0.5,4.,.T.,.T.);\n"
                "#20=CYLINDRICAL_SURFACE('',#1,1.5);\n#21=RECTANGULAR_TRIMMED_SURFACE('',#20,0.,6.3,-1.,2.,.T.,.T.);\n"
                "#30=CONICAL_SURFACE('',#1,2.,0.5);\n#31=RECTANGULAR_TRIMMED_SURFACE('',#30,0.,6.3,-1.,3.,.T.,.T.);\n"
                "#40=SPHERICAL_SURFACE('',#1,2.5);\n#50=TOROIDAL_SURFACE('',#1,3.,0.75);\n"),
      "t.step"));
  const Surface plane = m.surface(11), cyl = m.surface(21), cone = m.surface(31), sphere = m.surface(40),
                torus = m.surface(50);
  EXPECT_EQ(plane.domain().u.lo, -1.0);
  EXPECT_EQ(plane.domain().v.hi, 4.0);
  EXPECT_EQ(cyl.domain().v.lo, -1.0);
  for (double u : {0.3, 2.0, 4.5})
    for (double v : {-0.7, 0.4, 1.1}) {
      const Vec3 radial = std::cos(u) * kX + std::sin(u) * kY;
      expect_near(at(plane, u, v), kO + u * kX + v * kY, 1e-14);
      expect_near(at(cyl, u, v), kO + 1.5 * radial + v * kZ, 1e-14);
      // ssimarch's cone parameter starts at the apex: v_ours = v_step + R / tan(alpha).
      expect_near(at(cone, u, v + 2.0 / std::tan(0.5)), kO + (2.0 + v * std::tan(0.5)) * radial + v * kZ, 1e-13);
      const double lat = v;  // SPHERICAL_SURFACE: v is the latitude
      expect_near(at(sphere, u, lat), kO + 2.5 * std::cos(lat) * radial + 2.5 * std::sin(lat) * kZ, 1e-14);
      expect_near(at(torus, u, v), kO + (3.0 + 0.75 * std::cos(v)) * radial + 0.75 * std::sin(v) * kZ, 1e-14);
    }
  EXPECT_NEAR(cone.domain().v.lo, -1.0 + 2.0 / std::tan(0.5), 1e-14);
}

// Swept and offset surfaces (ISO 10303-42 §4.4.30-4.4.33) as exact rational B-splines: a line
// turned about z is the cylinder r = 2, a circle the torus (R, r) = (3, 1), an ellipse extruded
// the elliptic cylinder (x/2)^2 + y^2 = 1; offsets of a trimmed cylinder and a sphere; an offset
// of a B-spline is refused naming the instance and the type.
TEST(StepReader, SweptAndOffsetSurfacesAreExact) {
  const StepModel m(parse_step(
      step_text(
          std::string(kPlacement) +
          "#20=CYLINDRICAL_SURFACE('',#1,1.5);\n#21=RECTANGULAR_TRIMMED_SURFACE('',#20,0.,6.3,-1.,2.,.T.,.T.);\n"
          "#40=SPHERICAL_SURFACE('',#1,2.5);\n"
          "#60=LINE('',#61,#62);\n#61=CARTESIAN_POINT('',(2.,0.,0.));\n#62=VECTOR('',#63,1.);\n#63=DIRECTION('',(0.,0.,"
          "1.));\n"
          "#64=TRIMMED_CURVE('',#60,(PARAMETER_VALUE(-1.)),(PARAMETER_VALUE(3.)),.T.,.PARAMETER.);\n"
          "#65=AXIS1_PLACEMENT('',#66,#63);\n#66=CARTESIAN_POINT('',(0.,0.,0.));\n"
          "#67=SURFACE_OF_REVOLUTION('',#64,#65);\n"
          "#70=CIRCLE('',#71,1.);\n#71=AXIS2_PLACEMENT_3D('',#72,#73,#74);\n#72=CARTESIAN_POINT('',(3.,0.,0.));\n"
          "#73=DIRECTION('',(0.,-1.,0.));\n#74=DIRECTION('',(1.,0.,0.));\n#75=SURFACE_OF_REVOLUTION('',#70,#65);\n"
          "#80=ELLIPSE('',#81,2.,1.);\n#81=AXIS2_PLACEMENT_3D('',#66,#63,#74);\n#82=VECTOR('',#63,1.5);\n"
          "#83=SURFACE_OF_LINEAR_EXTRUSION('',#80,#82);\n#84=RECTANGULAR_TRIMMED_SURFACE('',#83,0.,1.,-0.5,2.,.T.,.T.);"
          "\n"
          "#90=OFFSET_SURFACE('',#21,0.25,.F.);\n#91=OFFSET_SURFACE('',#40,-0.5,.F.);\n"
          "#92=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#61,#66),(#72,#61)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.,1.),("
          "0.,1.),"
          ".UNSPECIFIED.);\n#93=OFFSET_SURFACE('',#92,0.1,.F.);\n"),
      "t.step"));
  const Surface cylinder = m.surface(67), torus = m.surface(75), elliptic = m.surface(84);
  const Surface offset_cylinder = m.surface(90), offset_sphere = m.surface(91);
  EXPECT_EQ(cylinder.domain().v.lo, -1.0);
  EXPECT_EQ(cylinder.domain().v.hi, 3.0);
  EXPECT_EQ(elliptic.domain().v.lo, -0.5);
  EXPECT_EQ(elliptic.domain().v.hi, 2.0);
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double a = i / 16.0, b = j / 8.0;
      const ParamDomain& d = cylinder.domain();
      const Vec3 c = at(cylinder, d.u.lo + a * d.u.width(), d.v.lo + b * d.v.width());
      EXPECT_NEAR(std::hypot(c.x(), c.y()), 2.0, 1e-14);
      EXPECT_NEAR(c.z(), d.v.lo + b * d.v.width(), 1e-14);  // the line's own parameter
      const ParamDomain& e = torus.domain();
      const Vec3 t = at(torus, e.u.lo + a * e.u.width(), e.v.lo + b * e.v.width());
      EXPECT_NEAR(std::pow(std::hypot(t.x(), t.y()) - 3.0, 2) + t.z() * t.z(), 1.0, 1e-14);
      const ParamDomain& f = elliptic.domain();
      const double v = f.v.lo + b * f.v.width();
      const Vec3 q = at(elliptic, f.u.lo + a * f.u.width(), v);
      EXPECT_NEAR(q.x() * q.x() / 4 + q.y() * q.y(), 1.0, 1e-14);
      EXPECT_NEAR(q.z(), 1.5 * v, 1e-14);
    }
  // The profile's point at u = 0 and, half way round, opposite it.
  expect_near(at(cylinder, 0.0, 0.5), Vec3(2, 0, 0.5), 1e-15);
  expect_near(at(cylinder, 0.5, 0.5), Vec3(-2, 0, 0.5), 1e-15);
  for (double u : {0.3, 2.0, 4.5})
    for (double v : {-0.7, 0.4, 1.1}) {
      const Vec3 radial = std::cos(u) * kX + std::sin(u) * kY;
      expect_near(at(offset_cylinder, u, v), kO + 1.75 * radial + v * kZ, 1e-14);
      expect_near(at(offset_sphere, u, v), kO + 2.0 * std::cos(v) * radial + 2.0 * std::sin(v) * kZ, 1e-14);
    }
  EXPECT_EQ(offset_cylinder.domain().v.hi, 2.0);
  try {
    m.surface(93);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("#93"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("OFFSET_SURFACE"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bspline"), std::string::npos) << e.what();
  }
  // A revolved line without a trim or a face bounding it: the message says so.
  const StepModel bare(
      parse_step(step_text("#60=LINE('',#61,#62);\n#61=CARTESIAN_POINT('',(2.,0.,0.));\n#62=VECTOR('',#63,1.);\n"
                           "#63=DIRECTION('',(0.,0.,1.));\n#65=AXIS1_PLACEMENT('',#61,#63);\n"
                           "#66=CARTESIAN_POINT('',(0.,0.,0.));\n#64=AXIS1_PLACEMENT('',#66,#63);\n"
                           "#67=SURFACE_OF_REVOLUTION('',#60,#64);\n"),
                 "t.step"));
  try {
    bare.surface(67);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unbounded line"), std::string::npos) << e.what();
  }
}

TEST(StepReader, DegreesAreConverted) {
  const StepModel m(parse_step(
      step_text(std::string(kPlacement) +
                "#30=CONICAL_SURFACE('',#1,0.,30.);\n#31=RECTANGULAR_TRIMMED_SURFACE('',#30,0.,360.,0.,2.,.T.,.T.);\n"
                "#60=(CONVERSION_BASED_UNIT('DEGREE',#61)NAMED_UNIT(#62)PLANE_ANGLE_UNIT());\n"
                "#61=PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(0.0174532925199433),#63);\n"
                "#62=DIMENSIONAL_EXPONENTS(0.,0.,0.,0.,0.,0.,0.);\n#63=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,."
                "RADIAN.));\n"),
      "t.step"));
  EXPECT_NEAR(m.angle_unit(), kPi / 180, 1e-15);
  const Surface cone = m.surface(31);
  ASSERT_NE(cone.get_if<Cone>(), nullptr);
  EXPECT_NEAR(cone.get_if<Cone>()->half_angle(), kPi / 6, 1e-14);
}

TEST(StepReader, FacesAreBoundedByTheirEdges) {
  // An inclined cylinder face between two circles 2.5 apart along the axis (ISO 10303-42 edges).
  const StepModel m(parse_step(
      step_text(std::string(kPlacement) +
                "#5=CYLINDRICAL_SURFACE('',#1,1.5);\n#6=ADVANCED_FACE('',(#7,#8),#5,.F.);\n"
                "#7=FACE_OUTER_BOUND('',#9,.T.);\n#8=FACE_BOUND('',#10,.T.);\n#9=EDGE_LOOP('',(#11));\n#10=EDGE_LOOP(''"
                ",(#12));\n"
                "#11=ORIENTED_EDGE('',*,*,#13,.T.);\n#12=ORIENTED_EDGE('',*,*,#14,.F.);\n"
                "#13=EDGE_CURVE('',#15,#15,#17,.T.);\n#14=EDGE_CURVE('',#16,#16,#18,.T.);\n"
                "#15=VERTEX_POINT('',#19);\n#16=VERTEX_POINT('',#20);\n#19=CARTESIAN_POINT('',(2.5,2.,3.));\n"
                "#20=CARTESIAN_POINT('',(2.5,3.5,5.));\n#17=CIRCLE('',#1,1.5);\n#18=CIRCLE('',#21,1.5);\n"
                "#21=AXIS2_PLACEMENT_3D('',#22,#3,#4);\n#22=CARTESIAN_POINT('',(1.,3.5,5.));\n"),
      "t.step"));
  ASSERT_EQ(m.faces().size(), 1u);
  const StepFace& f = m.faces()[0];
  EXPECT_EQ(f.index, 1);
  EXPECT_EQ(f.entity, 6);
  EXPECT_EQ(f.surface_entity, 5);
  EXPECT_EQ(f.surface_type, "CYLINDRICAL_SURFACE");
  EXPECT_FALSE(f.same_sense);
  const Surface s = m.surface(6);
  EXPECT_NEAR(s.domain().v.lo, 0.0, 1e-14);
  EXPECT_NEAR(s.domain().v.hi, 2.5, 1e-14);
  EXPECT_TRUE(s.domain().periodic_u);
  // The bare surface has no bound: the message names it.
  try {
    m.surface(5);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.step:12: #5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(m.face(2, "scene"), InputError);
}

TEST(StepReader, ErrorsNameTheInstance) {
  auto message = [](const std::string& data, std::int64_t id) {
    try {
      StepModel(parse_step(step_text(data), "t.step")).surface(id);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("#1=PLANE('',#9);\n", 1).find("t.step:8: #1"), std::string::npos);
  EXPECT_NE(message("#1=PLANE('',#9);\n", 1).find("refers to #9"), std::string::npos);
  EXPECT_NE(
      message(std::string(kPlacement) + "#5=CYLINDRICAL_SURFACE('',#1,'r');\n", 5).find("radius must be a number"),
      std::string::npos);
  EXPECT_NE(message(std::string(kPlacement) + "#5=CYLINDRICAL_SURFACE('',#1,-1.);\n", 5).find("t.step:12: #5"),
            std::string::npos);
  EXPECT_NE(
      message(std::string(kPlacement) + "#5=CURVE_BOUNDED_SURFACE('',#1,(),.F.);\n", 5).find("not a surface type"),
      std::string::npos);
  EXPECT_NE(message(std::string(kPlacement) + "#5=SURFACE_OF_REVOLUTION('',#1,#6);\n#6=AXIS1_PLACEMENT('',#2,#3);\n", 5)
                .find("#1: AXIS2_PLACEMENT_3D: is not a swept curve"),
            std::string::npos);
  EXPECT_NE(message("#1=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#2,#2),(#2,#2)),.UNSPECIFIED.,.F.,.F.,.F.,(2,9),(2,2),"
                    "(0.,1.),(0.,1.),.UNSPECIFIED.);\n#2=CARTESIAN_POINT('',(0.,0.,0.));\n",
                    1)
                .find("adding up to 4"),
            std::string::npos);
}

const std::string kNurbsFile = std::string(SSIMARCH_SOURCE_DIR) + "/tests/step/data/half_cylinder_nurbs.step";

TEST(StepReader, NurbsFaceIsTheExactCylinder) {
  const StepModel m = StepModel::read(kNurbsFile);
  ASSERT_EQ(m.faces().size(), 2u);
  EXPECT_EQ(m.faces()[0].entity, 20);
  EXPECT_EQ(m.faces()[0].surface_type, "RATIONAL_B_SPLINE_SURFACE");
  EXPECT_EQ(m.faces()[1].surface_type, "PLANE");
  const Surface side = m.surface(20);
  const auto* b = side.get_if<BSplineSurface>();
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(b->is_rational());
  EXPECT_EQ(side.domain().u.hi, 2.0);
  EXPECT_EQ(side.domain().v.hi, 3.0);
  // Every point lies on x^2 + y^2 = 4, z = v; u = 1/2 is the 45 degree line (quadratic rational arc).
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 6; ++j) {
      const Vec3 p = at(side, 0.1 * i, 0.5 * j);
      EXPECT_NEAR(std::hypot(p.x(), p.y()), 2.0, 1e-14);
      EXPECT_NEAR(p.z(), 0.5 * j, 1e-14);
    }
  // The symmetric rational quadratic arc has its middle at the middle of its span.
  expect_near(at(side, 1.0, 1.0), Vec3(0, 2, 1), 1e-15);
  const Vec3 q = at(side, 0.5, 0.0);
  EXPECT_NEAR(std::atan2(q.y(), q.x()), kPi / 4, 1e-14);
  // The planar bottom is bounded by the half disc: u in [-2, 2], v = -y in [-2, 0].
  const Surface bottom = m.surface(m.faces()[1].entity);
  EXPECT_NEAR(bottom.domain().u.lo, -2.0, 1e-12);
  EXPECT_NEAR(bottom.domain().u.hi, 2.0, 1e-12);
  EXPECT_NEAR(bottom.domain().v.lo, -2.0, 1e-12);
  EXPECT_NEAR(bottom.domain().v.hi, 0.0, 1e-12);
}

TEST(StepReader, SceneNamesFacesOfAStepFile) {
  const std::string text = R"json({
    "surfaces": {"side": {"step": "half_cylinder_nurbs.step", "face": 1},
                 "cut": {"plane": {"point": [0, 0, 1], "normal": [0, 0.3, 1], "u": [-4, 4], "v": [-4, 4]}}},
    "intersections": [{"surfaces": ["side", "cut"], "as": ["parametric", "implicit"], "options": {"step_length": 0.05}}]})json";
  const Scene s = parse_scene(text, "scene.json", std::string(SSIMARCH_SOURCE_DIR) + "/tests/step/data");
  ASSERT_NE(s.surfaces.at("side").get_if<BSplineSurface>(), nullptr);
  const IntersectionRun r = run_intersection(s, s.intersections[0]);
  ASSERT_EQ(r.result.curves.size(), 1u);
  // Half of the ellipse z = 1 - 0.3 y on the cylinder of radius 2 (y >= 0): every point on both.
  for (const auto& p : r.result.curves[0].points) {
    EXPECT_NEAR(std::hypot(p.p.x(), p.p.y()), 2.0, 1e-9);
    EXPECT_NEAR(p.p.z(), 1 - 0.3 * p.p.y(), 1e-9);
  }
  auto error = [](const std::string& t) {
    try {
      parse_scene(t, "scene.json", std::string(SSIMARCH_SOURCE_DIR) + "/tests/step/data");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error(R"({"surfaces": {"a": {"step": "half_cylinder_nurbs.step", "face": 3}}})").find("surfaces.a.face"),
            std::string::npos);
  EXPECT_NE(error(R"({"surfaces": {"a": {"step": "half_cylinder_nurbs.step", "entity": 13}}})")
                .find("half_cylinder_nurbs.step:24: #13"),
            std::string::npos);
  EXPECT_NE(error(R"({"surfaces": {"a": {"step": "half_cylinder_nurbs.step"}}})").find("exactly one of"),
            std::string::npos);
  EXPECT_NE(error(R"({"surfaces": {"a": {"step": "missing.step", "face": 1}}})").find("missing.step"),
            std::string::npos);
}

// Our writer's file read back: each SURFACE_CURVE / INTERSECTION_CURVE's PCURVEs mapped through
// the surfaces read from the file land on its 3D B-spline, and the surfaces are the scene's.
TEST(StepReader, RoundTripThroughTheWriter) {
  const Scene s = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/tests/step/data/step_round_trip.json");
  std::vector<IntersectionRun> runs;
  for (const auto& spec : s.intersections) runs.push_back(run_intersection(s, spec));
  std::ostringstream os;
  write_step(os, runs, &s);
  const StepModel m(parse_step(os.str(), "out.step"));
  // The surfaces read back are the scene's, point for point.
  std::map<std::string, std::int64_t> surface_ids;
  for (std::int64_t id : m.file().order) {
    const StepInstance& inst = *m.file().find(id);
    for (const StepRecord& r : inst.records)
      if ((r.type == "REPRESENTATION_ITEM" || inst.records.size() == 1) && !r.params.empty() &&
          r.params[0].kind == StepValue::Kind::kString && s.surfaces.count(r.params[0].text) &&
          inst.records.front().type != "PLANE" && inst.records.front().type != "CYLINDRICAL_SURFACE" &&
          inst.records.front().type != "CONICAL_SURFACE")
        surface_ids[r.params[0].text] = id;
  }
  // Every surface of the scene: the trimmed plane, cylinder and cone, the torus, the ball, the
  // rational B-spline and Bezier patches and the polynomial B-spline.
  ASSERT_EQ(surface_ids.size(), 8u);
  for (const auto& [name, id] : surface_ids) {
    const Surface& original = s.surfaces.at(name);
    const Surface read = m.surface(id);
    const ParamDomain& d = original.domain();
    EXPECT_EQ(read.domain().u.lo, d.u.lo) << name;
    EXPECT_EQ(read.domain().v.hi, d.v.hi) << name;
    for (double a : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0})
      for (double b : {0.0, 0.2, 0.61, 0.7, 1.0}) {
        const double u = d.u.lo + a * d.u.width(), v = d.v.lo + b * d.v.width();
        expect_near(at(read, u, v), at(original, u, v), 1e-14);
      }
  }
  // Each curve with surfaces: its p-curves through the read surfaces are on its 3D curve.
  int intersection_curves = 0, surface_curves = 0, pcurves = 0;
  for (std::int64_t id : m.file().order) {
    const StepInstance& inst = *m.file().find(id);
    const std::string& type = inst.records.front().type;
    if (type != "INTERSECTION_CURVE" && type != "SURFACE_CURVE") continue;
    (type == "INTERSECTION_CURVE" ? intersection_curves : surface_curves)++;
    const auto& p = inst.records.front().params;
    const BSplineCurve c3 = m.bspline_curve(p[1].ref);
    for (const StepValue& g : p[2].items) {
      const StepInstance& pc = *m.file().find(g.ref);
      if (pc.records.front().type != "PCURVE") continue;
      ++pcurves;
      const Surface surf = m.surface(pc.records.front().params[1].ref);
      const StepInstance& rep = *m.file().find(pc.records.front().params[2].ref);
      const BSplineCurve c2 = m.bspline_curve(rep.records.front().params[1].items[0].ref);
      // Same parameter (arc length); a periodic 3D curve's p-curve that winds is clamped instead.
      EXPECT_NEAR(c2.start(), c3.start(), 1e-12);
      EXPECT_NEAR(c2.end(), c3.end(), 1e-12);
      for (int k = 0; k <= 50; ++k) {
        const double t = c3.start() + (c3.end() - c3.start()) * k / 50;
        const VecX uv = c2.at(t);
        expect_near(at(surf, uv[0], uv[1]), Vec3(c3.at(t)), 1e-7);
      }
    }
  }
  EXPECT_GE(intersection_curves, 6);  // every surface of the scene has a STEP form
  EXPECT_EQ(surface_curves, 0);
  EXPECT_GE(pcurves, 11);
}

}  // namespace
}  // namespace ssimarch
