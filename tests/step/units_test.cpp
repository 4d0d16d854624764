// The length unit of a STEP file (io/step_units.hpp): SI units with their prefixes, units converted
// from an SI unit (the inch of AP214 files), none, several, and malformed ones refused naming the
// instance.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/step/units.hpp"

namespace ssimarch {
namespace {

using ::testing::HasSubstr;

StepLengthUnit unit_of(const std::string& data) {
  const std::string text = "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n" + data + "ENDSEC;\nEND-ISO-10303-21;\n";
  return step_length_unit(parse_step(text, "u.step"));
}

// The inch, 0.0254 m, alone among the geometry's units.
void expect_only_the_inch(const StepLengthUnit& unit) {
  EXPECT_EQ(unit.name, "inch");
  EXPECT_NEAR(unit.metres, 0.0254, 1e-17);
  EXPECT_FALSE(unit.several);
}

TEST(StepUnits, SiUnitsWithTheirPrefixes) {
  const StepLengthUnit mm = unit_of(
      "#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
      "#2=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n");
  EXPECT_EQ(mm.name, "millimetre");
  EXPECT_DOUBLE_EQ(mm.metres, 1e-3);
  EXPECT_FALSE(mm.several);
  const StepLengthUnit m = unit_of("#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.METRE.));\n");
  EXPECT_EQ(m.name, "metre");
  EXPECT_DOUBLE_EQ(m.metres, 1.0);
  EXPECT_DOUBLE_EQ(unit_of("#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MICRO.,.METRE.));\n").metres, 1e-6);
}

TEST(StepUnits, AnInchIsConvertedFromItsSiUnit) {
  // The inch (#4) as 25.4 of a millimetre (#1) that is itself a length unit.
  const std::string inch_over_mm =
      "#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
      "#2=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#1);\n"
      "#3=DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n"
      "#4=(CONVERSION_BASED_UNIT('INCH',#2)LENGTH_UNIT()NAMED_UNIT(#3));\n";
  const StepLengthUnit in = unit_of(inch_over_mm);
  // Without a context both length units count: the first, and "several".
  EXPECT_EQ(in.name, "millimetre");
  EXPECT_TRUE(in.several);
  // As CAD systems write it: the context assigns the inch; the millimetre only defines it.
  const StepLengthUnit assigned =
      unit_of(inch_over_mm +
              "#5=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n"
              "#6=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#4,'distance_accuracy_value','');\n"
              "#7=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#6))"
              "GLOBAL_UNIT_ASSIGNED_CONTEXT((#4,#5))REPRESENTATION_CONTEXT('',''));\n");
  expect_only_the_inch(assigned);
  const StepLengthUnit only = unit_of(
      "#1=(NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
      "#2=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#1);\n"
      "#4=(CONVERSION_BASED_UNIT('INCH',#2)LENGTH_UNIT()NAMED_UNIT(*));\n");
  expect_only_the_inch(only);
}

// An assembly as Inventor writes one (pythonocc-demos' 11752.stp): the product's placement context
// in inches, another in millimetres, the B-rep in the inch context; a relationship entity whose
// name also ends in SHAPE_REPRESENTATION is no representation.
TEST(StepUnits, TheUnitOfTheContextHoldingTheBrep) {
  const StepLengthUnit u = unit_of(
      "#1=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.CENTI.,.METRE.));\n"
      "#2=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(2.54),#1);\n"
      "#3=(CONVERSION_BASED_UNIT('INCH',#2)LENGTH_UNIT()NAMED_UNIT(*));\n"
      "#4=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNIT_ASSIGNED_CONTEXT((#3))REPRESENTATION_CONTEXT('',''));\n"
      "#5=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
      "#6=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNIT_ASSIGNED_CONTEXT((#5))REPRESENTATION_CONTEXT('',''));\n"
      "#7=SHAPE_REPRESENTATION('',(),#6);\n"
      "#8=ADVANCED_BREP_SHAPE_REPRESENTATION('',(),#4);\n"
      "#9=CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#7,#8);\n");
  expect_only_the_inch(u);
}

TEST(StepUnits, NoneDeclaredIsSaid) {
  const StepLengthUnit none = unit_of("#1=CARTESIAN_POINT('',(0.,0.,0.));\n");
  EXPECT_EQ(none.name, "unspecified");
  EXPECT_EQ(none.metres, 0.0);
}

TEST(StepUnits, MalformedUnitsNameTheInstance) {
  auto error = [](const std::string& data) {
    try {
      unit_of(data);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_THAT(error("#7=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MEGALO.,.METRE.));\n"), HasSubstr("u.step:5: #7"));
  EXPECT_THAT(error("#7=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MEGALO.,.METRE.));\n"),
              HasSubstr("unknown SI prefix .MEGALO."));
  EXPECT_THAT(error("#7=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT($,.SECOND.));\n"), HasSubstr("must be the METRE"));
  EXPECT_THAT(
      error("#1=(NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n#2=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(-1.),#1);\n"
            "#3=(CONVERSION_BASED_UNIT('INCH',#2)LENGTH_UNIT()NAMED_UNIT(*));\n"),
      HasSubstr("conversion factor must be > 0"));
  EXPECT_THAT(error("#3=(CONVERSION_BASED_UNIT('LOOP',#4)LENGTH_UNIT()NAMED_UNIT(*));\n"
                    "#4=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(2.),#3);\n"),
              HasSubstr("cycle"));
}

}  // namespace
}  // namespace ssimarch
