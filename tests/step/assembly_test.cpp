// STEP assemblies (docs/cad.md, "Assemblies"): a part placed several times is listed once per
// placement, in the root's coordinates, through placements nested in a sub-assembly, written with
// rep_1 and rep_2 swapped, and by a MAPPED_ITEM; traced curves lie where the parts are placed.
// Model: tests/step/data/rod_assembly.step (make_trim_models.py), whose placements OpenCASCADE
// 7.6's STEPControl_Reader reads the same (cylinder axes through (5, 0, -2) along z, (0, -5, 0.5)
// along y, (-5, 0, -2) along z; the plate z = 0).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "ssimarch/step/reader.hpp"
#include "testing/matchers.hpp"

namespace ssimarch {
namespace {

const std::string kModel = std::string(SSIMARCH_SOURCE_DIR) + "/tests/step/data/rod_assembly.step";

TEST(StepAssembly, EveryPlacementOfAPartIsAFace) {
  const StepModel m = StepModel::read(kModel);
  ASSERT_EQ(m.faces().size(), 4u);
  const char* names[] = {"rod_1", "sub_1/rod_2", "rod_3", "plate_1"};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(m.faces()[static_cast<std::size_t>(k)].instance, names[k]) << k;
  // The three rods are one face definition of one part.
  EXPECT_EQ(m.faces()[0].entity, m.faces()[1].entity);
  EXPECT_EQ(m.faces()[0].entity, m.faces()[2].entity);
  EXPECT_THAT(m.faces()[0].placement.translation, testing::IsNear(Vec3(5, 0, -2), 1e-15));
  EXPECT_TRUE(m.faces()[0].placement.rotation.isIdentity(1e-15));
  // sub_1 turns 90 degrees about z and moves to (0, -5, 0.5); in it the rod runs along x.
  const PartPlacement& p2 = m.faces()[1].placement;
  EXPECT_THAT(p2.translation, testing::IsNear(Vec3(0, -5, 0.5), 1e-15));
  EXPECT_THAT(p2.rotate(Vec3::UnitZ()), testing::IsNear(Vec3(0, 1, 0), 1e-15));
  EXPECT_NEAR(p2.rotation.determinant(), 1.0, 1e-15);
  EXPECT_THAT(m.faces()[2].placement.translation, testing::IsNear(Vec3(-5, 0, -2), 1e-15));
  EXPECT_TRUE(m.faces()[3].placement.is_identity());
}

Vec3 point_of(const Surface& s, double u, double v) {
  const Vec3T<double> q = s.point<double>(u, v);
  return {q.x, q.y, q.z};
}

TEST(StepAssembly, APlacedSurfaceIsThePartsSurfaceMoved) {
  const StepModel m = StepModel::read(kModel);
  const StepFace& f = m.faces()[1];
  const Surface placed = m.surface(f.entity, f.placement), own = m.surface(f.entity);
  const ParamDomain& d = own.domain();
  ASSERT_EQ(placed.domain().u.lo, d.u.lo);
  ASSERT_EQ(placed.domain().v.hi, d.v.hi);
  for (double u : {d.u.lo, 0.3, 2.0, d.u.hi})
    for (double v : {d.v.lo, 0.5 * (d.v.lo + d.v.hi), d.v.hi}) {
      const Vec3 p = point_of(placed, u, v);
      EXPECT_THAT(p, testing::IsNear(f.placement.apply(point_of(own, u, v)), 1e-14));
      // On the cylinder of radius 1 about the line x = 0, z = 0.5, for -5 <= y <= 5.
      EXPECT_NEAR(std::hypot(p.x(), p.z() - 0.5), 1.0, 1e-14);
      EXPECT_GE(p.y(), -5 - 1e-14);
      EXPECT_LE(p.y(), 5 + 1e-14);
    }
}

IntersectionRun trace_faces(int a, int b) {
  const Scene s = parse_scene(R"({"surfaces": {"a": {"step": "rod_assembly.step", "face": )" + std::to_string(a) +
                                  R"(}, "b": {"step": "rod_assembly.step", "face": )" + std::to_string(b) +
                                  R"(}}, "intersections": [{"name": "ab", "surfaces": ["a", "b"]}]})",
                              "assembly.json", std::string(SSIMARCH_SOURCE_DIR) + "/tests/step/data");
  return run_intersection(s, s.intersections[0]);
}

TEST(StepAssembly, CurvesLieWhereThePartsArePlaced) {
  // The plate z = 0 cuts rod_1 (axis z through (5, 0)) and rod_3 (through (-5, 0)) in unit circles.
  for (const auto& [face, centre] : {std::pair{1, Vec3(5, 0, 0)}, std::pair{3, Vec3(-5, 0, 0)}}) {
    const IntersectionRun r = trace_faces(4, face);
    ASSERT_EQ(r.result.curves.size(), 1u) << face;
    EXPECT_TRUE(r.result.curves[0].closed);
    EXPECT_THAT(r.result.curves[0], testing::HasLength(2 * M_PI, 1e-9));
    EXPECT_THAT(r.result.curves[0],
                testing::HasEveryPointWithin(
                    [c = centre](const Vec3& p) { return std::hypot((p - c).norm() - 1, p.z()); }, 1e-10));
  }
  // sub_1/rod_2 lies along y at height 0.5: the plate cuts it in the lines x = +-sqrt(3)/2,
  // -5 <= y <= 5, each of length 10.
  const IntersectionRun r = trace_faces(4, 2);
  ASSERT_EQ(r.result.curves.size(), 2u);
  for (const TracedCurve& c : r.result.curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_THAT(c, testing::HasLength(10, 1e-9));
    EXPECT_THAT(c, testing::HasEveryPointWithin(
                       [](const Vec3& p) { return std::hypot(std::fabs(p.x()) - std::sqrt(0.75), p.z()); }, 1e-10));
  }
}

// A part that contains itself through its components.
TEST(StepAssembly, ACycleOfPlacementsIsAnErrorNamingTheRepresentation) {
  const std::string text = R"(ISO-10303-21;
HEADER;
FILE_DESCRIPTION((''),'2;1');
FILE_NAME('cycle','',(''),(''),'','','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));
ENDSEC;
DATA;
#1=REPRESENTATION_CONTEXT('3D','3D');
#2=CARTESIAN_POINT('',(0.,0.,0.));
#3=AXIS2_PLACEMENT_3D('',#2,$,$);
#4=CARTESIAN_POINT('',(1.,0.,0.));
#5=AXIS2_PLACEMENT_3D('',#4,$,$);
#10=PLANE('',#3);
#11=ADVANCED_FACE('',(),#10,.T.);
#12=OPEN_SHELL('',(#11));
#13=SHELL_BASED_SURFACE_MODEL('',(#12));
#20=SHAPE_REPRESENTATION('root',(#3),#1);
#21=MANIFOLD_SURFACE_SHAPE_REPRESENTATION('b',(#3,#13),#1);
#22=SHAPE_REPRESENTATION('c',(#3),#1);
#30=ITEM_DEFINED_TRANSFORMATION('','',#3,#5);
#31=(REPRESENTATION_RELATIONSHIP('','',#21,#20)REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#30)SHAPE_REPRESENTATION_RELATIONSHIP());
#32=(REPRESENTATION_RELATIONSHIP('','',#22,#21)REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#30)SHAPE_REPRESENTATION_RELATIONSHIP());
#33=(REPRESENTATION_RELATIONSHIP('','',#21,#22)REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#30)SHAPE_REPRESENTATION_RELATIONSHIP());
ENDSEC;
END-ISO-10303-21;
)";
  try {
    StepModel m(parse_step(text, "cycle.step"));
    FAIL() << "a cycle of placements was accepted with " << m.faces().size() << " faces";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cycle.step:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cycle"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ssimarch
