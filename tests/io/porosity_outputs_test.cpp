// The files of a porosity run (io/porosity_outputs.hpp): the format by name or by extension, the
// derived file names, and what the CSV and summary hold for one sphere's radial profile.
#include "ssimarch/io/porosity_outputs.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ssimarch/core/error.hpp"

namespace ssimarch {
namespace {

TEST(PorosityOutputs, TheFormatComesFromTheNameOrElseTheExtension) {
  EXPECT_EQ(porosity_file_format("", "bed.vtm", "--format"), PorosityFileFormat::kVtk);
  EXPECT_EQ(porosity_file_format("", "bed.vti", "--format"), PorosityFileFormat::kVtk);
  EXPECT_EQ(porosity_file_format("", "bed.csv", "--format"), PorosityFileFormat::kCsv);
  EXPECT_EQ(porosity_file_format("", "", "--format"), PorosityFileFormat::kCsv);
  EXPECT_EQ(porosity_file_format("vtk-ascii", "bed.csv", "--format"), PorosityFileFormat::kVtkAscii);
  EXPECT_EQ(porosity_file_format("csv", "bed.vtm", "--format"), PorosityFileFormat::kCsv);
  try {
    porosity_file_format("xml", "bed.vtm", "--format");
    FAIL() << "an unknown format was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--format");
    EXPECT_NE(e.message().find("csv, vtk or vtk-ascii, got 'xml'"), std::string::npos) << e.message();
  }
}

TEST(PorosityOutputs, FurtherProfilesAreNamedAfterTheFirst) {
  EXPECT_EQ(derived_path("out/run.csv", "axial"), std::filesystem::path("out/run_axial.csv"));
  EXPECT_EQ(derived_path("run", "map"), std::filesystem::path("run_map"));
}

TEST(PorosityOutputs, OneSpheresRadialProfileAndSummary) {
  PorosityJob job;
  Particle p;
  p.centre = Vec3(0, 0, 0);
  p.diameter = 1;
  job.packing = {p};
  job.container_radius = 2;
  job.radial_points = 4;
  const PorosityJobResult r = run_porosity_job(job);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ssimarch_porosity_outputs_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path csv = dir / "one.csv";
  OutputFiles files;
  const nlohmann::json outputs = write_porosity_profiles(files, csv.string(), PorosityFileFormat::kCsv, r);
  files.commit();
  EXPECT_EQ(outputs.at("radial").at("columns"), "r,porosity");
  EXPECT_EQ(outputs.at("radial").at("n"), 4);
  std::ifstream in(csv);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "r,porosity");
  // r = R/4 = 0.5 touches the sphere of radius 0.5 only at z = 0: porosity 1 - sqrt(A^2 - r^2)/A = 1.
  std::istringstream row(first);
  double x = 0, eps = 0;
  char comma = 0;
  row >> x >> comma >> eps;
  EXPECT_DOUBLE_EQ(x, 0.5);
  EXPECT_NEAR(eps, 1.0, 1e-8);
  const nlohmann::json summary = porosity_summary_json(job, r, "one sphere");
  EXPECT_EQ(summary.at("packing"), "one sphere");
  EXPECT_EQ(summary.at("tolerance"), PorosityDefaults::kTolerance);
  EXPECT_EQ(summary.at("overlaps").at("rule"), "union");
  // One sphere of radius 1/2 in a cylinder of radius 2 and height 1: 1 - (pi/6) / (4 pi).
  EXPECT_NEAR(summary.at("bulk_porosity").get<double>(), 1.0 - 1.0 / 24.0, 1e-9);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ssimarch
