// Packing readers: valid CSV/LAMMPS input, and bad rows reported with file:line.
#include "ssimarch/porosity/packing.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace ssimarch {
namespace {

Packing csv(const std::string& text) {
  std::istringstream in(text);
  return read_packing_csv(in, "bed.csv");
}

std::string csv_error(const std::string& text) {
  try {
    csv(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(porosity_PackingCsv, SpheresAndSpherocylinders) {
  const Packing s = csv("# comment\nx,y,z,d\n0,0,0.5,1\n1.5, -2, 3e-1 ,0.25\n\n");
  ASSERT_EQ(s.particles.size(), 2u);
  EXPECT_FALSE(s.spherocylinders);
  EXPECT_DOUBLE_EQ(s.particles[1].centre.z(), 0.3);
  EXPECT_DOUBLE_EQ(s.particles[1].diameter, 0.25);
  EXPECT_EQ(s.particles[1].length, 0.0);
  // Columns in any order, axis not unit length.
  const Packing r = csv("l,d,uz,uy,ux,z,y,x\n2,0.5,0,0,3,1,2,3\n");
  ASSERT_EQ(r.particles.size(), 1u);
  EXPECT_TRUE(r.spherocylinders);
  EXPECT_DOUBLE_EQ(r.particles[0].axis.x(), 1.0);
  EXPECT_DOUBLE_EQ(r.particles[0].centre.x(), 3.0);
  EXPECT_DOUBLE_EQ(r.particles[0].length, 2.0);
}

TEST(porosity_PackingCsv, BadRowsNameFileAndLine) {
  EXPECT_NE(csv_error("x,y,z,d\n0,0,0,1\n0,0,0\n").find("bed.csv:3: expected 4 fields"), std::string::npos);
  EXPECT_NE(csv_error("x,y,z,d\n0,0,nan,1\n").find("bed.csv:2: centre coordinate is not finite"), std::string::npos);
  EXPECT_NE(csv_error("x,y,z,d\n0,0,0,-1\n").find("bed.csv:2: diameter must be > 0"), std::string::npos);
  EXPECT_NE(csv_error("x,y,z,d\n0,0,0,abc\n").find("bed.csv:2:7: column 'd': not a number"), std::string::npos);
  EXPECT_NE(csv_error("x,y,z,ux,uy,uz,d,l\n0,0,0,0,0,0,1,1\n").find("bed.csv:2: axis (ux, uy, uz) must not be zero"),
            std::string::npos);
  EXPECT_NE(csv_error("x,y,z,ux,uy,uz,d,l\n0,0,0,0,0,1,1,-2\n").find("bed.csv:2: length must be >= 0"), std::string::npos);
  EXPECT_NE(csv_error("x,y,d\n").find("bed.csv:1: header lacks column 'z'"), std::string::npos);
  EXPECT_NE(csv_error("x,y,z,d,l\n").find("header lacks column 'ux'"), std::string::npos);
  EXPECT_NE(csv_error("").find("empty file"), std::string::npos);
  // Several bad rows are all listed (count first).
  const std::string many = csv_error("x,y,z,d\n0,0,0,-1\n0,0,0,1\n0,0,0,0\n");
  EXPECT_NE(many.find("2 bad rows"), std::string::npos);
  EXPECT_NE(many.find("bed.csv:4:"), std::string::npos);
}

TEST(porosity_PackingLammps, LastSnapshotWithRadiusColumn) {
  std::istringstream in(
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp pp\n-5 5\n-5 5\n0 10\n"
      "ITEM: ATOMS id type x y z radius\n1 1 0 0 9 0.5\n"
      "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n-5 5\n-5 5\n0 10\n"
      "ITEM: ATOMS id type x y z vx radius\n1 1 0 0 0.5 0 0.5\n2 1 1 1 0.5 0 0.25\n");
  const Packing p = read_lammps_dump(in, "dump.liggghts");
  ASSERT_EQ(p.particles.size(), 2u);
  EXPECT_DOUBLE_EQ(p.particles[1].diameter, 0.5);
  EXPECT_DOUBLE_EQ(p.particles[0].centre.z(), 0.5);
}

TEST(porosity_PackingLammps, ScaledCoordinatesAndErrors) {
  std::istringstream in(
      "ITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n0 2\n0 4\n0 8\nITEM: ATOMS id xs ys zs diameter\n1 0.5 0.5 0.5 1\n");
  const Packing p = read_lammps_dump(in, "d");
  ASSERT_EQ(p.particles.size(), 1u);
  EXPECT_DOUBLE_EQ(p.particles[0].centre.y(), 2.0);
  std::istringstream bad("ITEM: NUMBER OF ATOMS\n2\nITEM: ATOMS id x y z radius\n1 0 0 0 -1\n");
  try {
    read_lammps_dump(bad, "dump.txt");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dump.txt:4"), std::string::npos) << e.what();
  }
  std::istringstream norad("ITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z\n1 0 0 0\n");
  EXPECT_THROW(read_lammps_dump(norad, "d"), InputError);
}

TEST(porosity_PackingFiles, FieldThatIsNotANumberIsLocatedByLineAndColumn) {
  EXPECT_NE(csv_error("x,y,z,d\n0, 1e,0,1\n").find("bed.csv:2:4: column 'y': not a number: '1e'"), std::string::npos);
  std::istringstream dump("ITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id x y z radius\n1 0  q 0 0.5\n");
  try {
    read_lammps_dump(dump, "dump.txt");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "dump.txt");
    EXPECT_NE(std::string(e.what()).find("dump.txt:4:6: column 'y': not a number: 'q'"), std::string::npos) << e.what();
  }
}

TEST(porosity_PackingCsv, WriteReadRoundTrip) {
  std::vector<Particle> ps(2);
  ps[0].centre = {0.1, 0.2, 0.3};
  ps[0].diameter = 0.7;
  ps[0].length = 1.25;
  ps[1].centre = {-1.0 / 3, 2.0 / 7, 5.0};
  ps[1].axis = Vec3(1, 2, 3).normalized();
  ps[1].diameter = 0.5;
  ps[1].length = 0.0;
  std::ostringstream out;
  write_packing_csv(out, ps);
  const Packing back = csv(out.str());
  ASSERT_EQ(back.particles.size(), 2u);
  EXPECT_EQ(back.particles[1].centre, ps[1].centre);  // shortest round-trip formatting
  EXPECT_TRUE(back.particles[1].axis.isApprox(ps[1].axis, 1e-15));
  EXPECT_EQ(back.particles[0].length, 1.25);
}

TEST(porosity_PackingFile, MissingFileIsAnError) {
  EXPECT_THROW(read_packing("/nonexistent/bed.csv"), InputError);
}

TEST(porosity_PackingCsv, AByteOrderMarkIsSkipped) {
  // Spreadsheets write one; it used to hide the first column ("missing column x").
  const Packing p = csv("\xEF\xBB\xBFx,y,z,d\n0,0,0.5,1\n");
  ASSERT_EQ(p.particles.size(), 1u);
  EXPECT_DOUBLE_EQ(p.particles[0].diameter, 1.0);
}

TEST(porosity_PackingFile, SizeLimitsStopAWrongFile) {
  // /dev/zero has no newline and no end.
  try {
    read_packing("/dev/zero");
    FAIL() << "/dev/zero was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/zero:1: a line longer than 64 KiB"), std::string::npos) << e.what();
  }
  InputLimits small;
  small.max_packing_bytes = 64;
  std::istringstream in("x,y,z,d\n0,0,0.5,1\n0,0,1.5,1\n0,0,2.5,1\n0,0,3.5,1\n0,0,4.5,1\n0,0,5.5,1\n");  // 74 bytes
  try {
    read_packing_csv(in, "bed.csv", small);
    FAIL() << "the file limit was not applied";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than 64 bytes"), std::string::npos) << e.what();
  }
}

TEST(porosity_LammpsDump, AnAtomCountBeyondTheFileIsRejectedBeforeAnyConversion) {
  // 1e300 converted to long is undefined behaviour (UBSan's float-cast-overflow catches it).
  std::istringstream in("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1e300\nITEM: ATOMS id x y z radius\n");
  try {
    read_lammps_dump(in, "d.dump");
    FAIL() << "an atom count of 1e300 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("d.dump:4: atom count 1e300 is more than the file can hold"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ssimarch
