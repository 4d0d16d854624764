// Reading a STEP model converted to another length unit (docs/cad.md, "Length unit"): every
// length scaled once as it is read, so each face's surface, box, placement and trimming loops are
// the model's own times the factor, and traced curves scale with them; the units a user names;
// conversions that cannot be made are refused naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/step/reader.hpp"
#include "ssimarch/step/units.hpp"
#include "testing/matchers.hpp"

namespace ssimarch {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kData = std::filesystem::path(SSIMARCH_SOURCE_DIR) / "tests/step/data";

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The file with a millimetre declared when it declares no length unit (the reader's last
// resort, any LENGTH_UNIT instance, finds it).
StepFile in_millimetres(const std::filesystem::path& path) {
  std::string text = file_text(path);
  if (text.find("LENGTH_UNIT") == std::string::npos) {
    const std::size_t end = text.find("ENDSEC;", text.find("DATA;"));
    text.insert(end, "#999999=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n");
  }
  return parse_step(text, path.filename().string());
}

TEST(StepUnitConversion, UnitsAreNamedBySymbolOrName) {
  EXPECT_DOUBLE_EQ(named_length_unit("mm", "--unit").metres, 1e-3);
  EXPECT_EQ(named_length_unit("Millimeter", "--unit").name, "millimetre");
  EXPECT_DOUBLE_EQ(named_length_unit("IN", "--unit").metres, 0.0254);
  EXPECT_EQ(named_length_unit("inches", "--unit").name, "inch");
  EXPECT_DOUBLE_EQ(named_length_unit("micron", "--unit").metres, 1e-6);
  EXPECT_DOUBLE_EQ(named_length_unit("ft", "--unit").metres, 0.3048);
  EXPECT_DOUBLE_EQ(named_length_unit("metre", "--unit").metres, 1.0);
  try {
    named_length_unit("parsec", "--unit");
    FAIL() << "an unknown unit was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--unit"));
    EXPECT_THAT(e.what(), HasSubstr("\"parsec\""));
    EXPECT_THAT(e.what(), HasSubstr("mm, cm, m"));
  }
  EXPECT_THROW(named_length_unit("", "--unit"), InputError);
}

TEST(StepUnitConversion, AConversionNeedsOneDeclaredUnit) {
  const StepLengthUnit mm = named_length_unit("mm", "u"), inch = named_length_unit("in", "u");
  EXPECT_NEAR(length_conversion(inch, mm, "a.step"), 25.4, 1e-14);
  EXPECT_EQ(length_conversion(mm, mm, "a.step"), 1.0);
  try {
    StepModel(parse_step(file_text(kData / "rod_assembly.step"), "rod_assembly.step"), mm);
    FAIL() << "a file without a unit was converted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("rod_assembly.step"));
    EXPECT_THAT(e.what(), HasSubstr("declares no length unit"));
  }
  StepLengthUnit several = mm;
  several.several = true;
  EXPECT_THROW(length_conversion(several, inch, "a.step"), InputError);
  // Without a conversion a file without a unit reads as before.
  const StepModel plain(parse_step(file_text(kData / "rod_assembly.step"), "rod_assembly.step"));
  EXPECT_EQ(plain.length_scale(), 1.0);
  EXPECT_FALSE(plain.converted_to());
}

// A malformed unit stops a conversion, naming its instance, but not a reading in the file's numbers.
TEST(StepUnitConversion, AMalformedUnitStopsOnlyAConversion) {
  std::string text = file_text(kData / "rod_assembly.step");
  text.insert(text.find("ENDSEC;", text.find("DATA;")),
              "#999999=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.GRAM.));\n");
  const StepModel plain(parse_step(text, "gram.step"));
  EXPECT_EQ(plain.length_unit().metres, 0.0);
  EXPECT_EQ(plain.faces().size(), 4u);
  try {
    StepModel(parse_step(text, "gram.step"), named_length_unit("mm", "unit"));
    FAIL() << "a malformed unit was converted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("#999999"));
    EXPECT_THAT(e.what(), HasSubstr("METRE"));
  }
}

void expect_scaled(const Box& a, const Box& b, double s, const std::string& what) {
  const double tol = 1e-13 * s * std::max({1.0, a.x.width(), a.y.width(), a.z.width()});
  EXPECT_NEAR(b.x.lo, s * a.x.lo, tol) << what;
  EXPECT_NEAR(b.x.hi, s * a.x.hi, tol) << what;
  EXPECT_NEAR(b.y.lo, s * a.y.lo, tol) << what;
  EXPECT_NEAR(b.y.hi, s * a.y.hi, tol) << what;
  EXPECT_NEAR(b.z.lo, s * a.z.lo, tol) << what;
  EXPECT_NEAR(b.z.hi, s * a.z.hi, tol) << what;
}

void expect_regions_scaled(const FaceRegion* a, const FaceRegion* b, double s, const std::string& what) {
  ASSERT_EQ(a == nullptr, b == nullptr) << what;
  if (!a) return;
  ASSERT_EQ(a->boundary_curves(), b->boundary_curves()) << what;
  for (int i = 0; i < a->boundary_curves(); ++i) {
    const auto ra = a->boundary_range(i), rb = b->boundary_range(i);
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
      const Vec3 pa = a->boundary_point(i, ra[0] + t * (ra[1] - ra[0]));
      const Vec3 pb = b->boundary_point(i, rb[0] + t * (rb[1] - rb[0]));
      EXPECT_THAT(pb, testing::IsNear(Vec3(s * pa), 1e-13 * s * std::max(1.0, pa.norm()))) << what << " edge " << i;
    }
  }
}

// Every test model (planes, cylinders, tori, B-splines, holes, an assembly): read in millimetres
// and converted to metres and inches, each face is the same face scaled.
TEST(StepUnitConversion, EveryFaceOfEveryTestModelIsScaled) {
  int faces = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kData)) {
    if (entry.path().extension() != ".step") continue;
    const StepModel mm(in_millimetres(entry.path()));
    for (const char* unit : {"m", "in"}) {
      const StepModel to(in_millimetres(entry.path()), named_length_unit(unit, "unit"));
      const double s = 1e-3 / named_length_unit(unit, "unit").metres;
      EXPECT_EQ(to.length_scale(), s);
      EXPECT_EQ(to.length_unit().name, named_length_unit(unit, "unit").name);
      EXPECT_EQ(to.file_length_unit().name, "millimetre");
      ASSERT_EQ(to.faces().size(), mm.faces().size());
      for (std::size_t k = 0; k < mm.faces().size(); ++k) {
        const StepFace &fa = mm.faces()[k], &fb = to.faces()[k];
        const std::string what = entry.path().filename().string() + " face " + std::to_string(k + 1) + " in " + unit;
        EXPECT_THAT(fb.placement.translation, testing::IsNear(Vec3(s * fa.placement.translation), 1e-13));
        EXPECT_TRUE(fb.placement.rotation.isApprox(fa.placement.rotation, 1e-15)) << what;
        const Surface sa = mm.surface(fa.entity, fa.placement), sb = to.surface(fb.entity, fb.placement);
        EXPECT_EQ(sa.type_name(), sb.type_name()) << what;
        expect_scaled(sa.box(), sb.box(), s, what);
        expect_regions_scaled(mm.face_region(fa.entity, fa.placement).get(),
                              to.face_region(fb.entity, fb.placement).get(), s, what);
        ++faces;
      }
    }
  }
  EXPECT_GE(faces, 20);
}

// Every surface kind the reader maps, as surface instances (not faces): a plane, cylinder and
// cone in rectangles (their v and the plane's u are lengths), a sphere, a torus, a line and a
// circle turned about an axis, an ellipse extruded by a vector of length 1.5 in a rectangle (its
// v counts vectors, not lengths), offsets of a trimmed cylinder and a sphere, a bilinear patch.
TEST(StepUnitConversion, EverySurfaceKindIsScaled) {
  const std::string text =
      "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n"
      "#1=AXIS2_PLACEMENT_3D('',#2,#3,#4);\n#2=CARTESIAN_POINT('',(1.,2.,3.));\n#3=DIRECTION('',(0.,0.6,0.8));\n"
      "#4=DIRECTION('',(1.,0.,0.));\n"
      "#10=PLANE('',#1);\n#11=RECTANGULAR_TRIMMED_SURFACE('',#10,-1.,2.,0.5,4.,.T.,.T.);\n"
      "#20=CYLINDRICAL_SURFACE('',#1,1.5);\n#21=RECTANGULAR_TRIMMED_SURFACE('',#20,0.,6.3,-1.,2.,.T.,.T.);\n"
      "#30=CONICAL_SURFACE('',#1,2.,0.5);\n#31=RECTANGULAR_TRIMMED_SURFACE('',#30,0.,6.3,-1.,3.,.T.,.T.);\n"
      "#40=SPHERICAL_SURFACE('',#1,2.5);\n#50=TOROIDAL_SURFACE('',#1,3.,0.75);\n"
      "#60=LINE('',#61,#62);\n#61=CARTESIAN_POINT('',(2.,0.,0.));\n#62=VECTOR('',#63,1.);\n"
      "#63=DIRECTION('',(0.,0.,1.));\n"
      "#64=TRIMMED_CURVE('',#60,(PARAMETER_VALUE(-1.)),(PARAMETER_VALUE(3.)),.T.,.PARAMETER.);\n"
      "#65=AXIS1_PLACEMENT('',#66,#63);\n#66=CARTESIAN_POINT('',(0.,0.,0.));\n"
      "#67=SURFACE_OF_REVOLUTION('',#64,#65);\n"
      "#70=CIRCLE('',#71,1.);\n#71=AXIS2_PLACEMENT_3D('',#72,#73,#74);\n#72=CARTESIAN_POINT('',(3.,0.,0.));\n"
      "#73=DIRECTION('',(0.,-1.,0.));\n#74=DIRECTION('',(1.,0.,0.));\n#75=SURFACE_OF_REVOLUTION('',#70,#65);\n"
      "#80=ELLIPSE('',#81,2.,1.);\n#81=AXIS2_PLACEMENT_3D('',#66,#63,#74);\n#82=VECTOR('',#63,1.5);\n"
      "#83=SURFACE_OF_LINEAR_EXTRUSION('',#80,#82);\n"
      "#84=RECTANGULAR_TRIMMED_SURFACE('',#83,0.,1.,-0.5,2.,.T.,.T.);\n"
      "#90=OFFSET_SURFACE('',#21,0.25,.F.);\n#91=OFFSET_SURFACE('',#40,-0.5,.F.);\n"
      "#92=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#61,#66),(#72,#61)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),"
      "(0.,1.),(0.,1.),.UNSPECIFIED.);\n"
      "#99=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
      "ENDSEC;\nEND-ISO-10303-21;\n";
  const StepModel mm(parse_step(text, "kinds.step"));
  const StepModel in(parse_step(text, "kinds.step"), named_length_unit("in", "unit"));
  const double s = 1 / 25.4;
  for (std::int64_t id : {11, 21, 31, 40, 50, 67, 75, 84, 90, 91, 92}) {
    const Surface a = mm.surface(id), b = in.surface(id);
    std::string what = "#";
    what += std::to_string(id);  // appended, not "#" + ...: g++ 12 warns (-Wstringop-overflow) on the sum
    expect_scaled(a.box(), b.box(), s, what);
    // The same fractions of the parameter domain are the same points, scaled.
    const ParamDomain &da = a.domain(), &db = b.domain();
    for (double x : {0.0, 0.25, 0.9})
      for (double y : {0.1, 0.5, 1.0}) {
        const Vec3T<double> pa = a.point<double>(da.u.lo + x * da.u.width(), da.v.lo + y * da.v.width());
        const Vec3T<double> pb = b.point<double>(db.u.lo + x * db.u.width(), db.v.lo + y * db.v.width());
        EXPECT_THAT(Vec3(pb.x, pb.y, pb.z), testing::IsNear(Vec3(s * Vec3(pa.x, pa.y, pa.z)), 1e-14)) << what;
      }
  }
}

double total_length(const IntersectionRun& r) {
  double l = 0;
  for (const TracedCurve& c : r.result.curves) l += c.length;
  return l;
}

// A scene's STEP surfaces read converted ("unit"): the plate of the rod assembly against each rod
// in inches is the same circle, 2 pi mm = 2 pi / 25.4 in, and a plane given in inches meets it.
TEST(StepUnitConversion, ASceneReadsItsStepSurfacesInTheUnitItNames) {
  const auto dir = std::filesystem::temp_directory_path() / ("ssimarch_unit_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "rod_mm.step");
    std::string text = file_text(kData / "rod_assembly.step");
    text.insert(text.find("ENDSEC;", text.find("DATA;")),
                "#999999=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n");
    out << text;
  }
  for (const auto& [unit, scale] : {std::pair{"", 1.0}, std::pair{",\"unit\": \"in\"", 1 / 25.4}}) {
    const std::string face = R"({"step": "rod_mm.step", "face": )";
    const Scene s =
        parse_scene(R"({"surfaces": {"plate": )" + face + "4" + unit + "}, \"rod\": " + face + "1" + unit +
                        R"(}, "cut": {"plane": {"point": [0, 0, )" + std::to_string(-scale) +
                        R"(], "normal": [0, 0, 1]}}}, "intersections": [{"name": "a", "surfaces": ["plate", "rod"]},
            {"name": "b", "surfaces": ["rod", "cut"]}]})",
                    "unit.json", dir);
    const IntersectionRun plate = run_intersection(s, s.intersections[0]);
    ASSERT_EQ(plate.result.curves.size(), 1u) << unit;
    EXPECT_NEAR(total_length(plate), 2 * M_PI * scale, 1e-9 * scale) << unit;
    // The rod (radius 1 mm, z from -2 - 5 to -2 + 5 mm) cut 1 mm below the plate.
    const IntersectionRun cut = run_intersection(s, s.intersections[1]);
    EXPECT_NEAR(total_length(cut), 2 * M_PI * scale, 1e-9 * scale) << unit;
  }
  try {
    parse_scene(R"({"surfaces": {"a": {"step": "rod_mm.step", "face": 1, "unit": "furlong"}}, "intersections": []})",
                "unit.json", dir);
    FAIL() << "an unknown unit was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("surfaces.a.unit"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ssimarch
