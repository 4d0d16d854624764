// `ssimarch porosity` and `ssimarch packing` end to end: column names, summary JSON, errors and exit
// codes. Fails when the CLI is not built (tests/testing/cli_run.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "testing/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

// stdout and stderr together: the checks below look for messages on either.
struct CliRun {
  int status;
  std::string out;
};

CliRun run(const std::string& args) {
  const ssimarch::testing::CliRun r = ssimarch::testing::run_cli(args);
  return {r.status, r.all()};
}

std::vector<std::string> lines(const fs::path& f) {
  std::ifstream in(f);
  std::vector<std::string> v;
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

class porosity_Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ssimarch::testing::cli_scratch_dir() / "porosity";
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  std::string p(const char* name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(porosity_Cli, GenerateThenProfilesWithDocumentedColumns) {
  CliRun g = run("packing spheres --container-radius 3 --count 200 --seed 5 -o " + p("bed.csv"));
  ASSERT_EQ(g.status, 0) << g.out;
  EXPECT_NE(g.out.find("bulk porosity"), std::string::npos);
  CliRun r = run("porosity " + p("bed.csv") + " --container-radius 3 --z-range 1,3 --radii 20 -o " + p("radial.csv") +
              " --summary " + p("s.json") + " --plot " + p("r.svg"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("bulk porosity: "), std::string::npos) << r.out;
  const auto rl = lines(p("radial.csv"));
  ASSERT_EQ(rl.size(), 21u);
  EXPECT_EQ(rl[0], "r,porosity");
  EXPECT_EQ(rl[20].rfind("3,", 0), 0u);
  std::ifstream js(p("s.json"));
  const auto j = nlohmann::json::parse(js);
  EXPECT_GT(j["bulk_porosity"].get<double>(), 0.2);
  EXPECT_LT(j["bulk_porosity"].get<double>(), 0.8);
  EXPECT_EQ(j["outputs"]["radial"]["columns"], "r,porosity");
  std::ifstream svg(p("r.svg"));
  const std::string picture((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(picture.find("exact radial porosity"), std::string::npos);  // the profile's legend
  EXPECT_NE(picture.find("Porosity profile of bed.csv"), std::string::npos);
  EXPECT_NE(picture.find("<polyline"), std::string::npos);
  EXPECT_EQ(picture.substr(picture.size() - 7), "</svg>\n");

  CliRun b = run("porosity " + p("bed.csv") + " --container-radius 3 --bins 6 --axial 5 --map 4,3 -o " + p("b.csv"));
  ASSERT_EQ(b.status, 0) << b.out;
  EXPECT_EQ(lines(p("b.csv"))[0], "r_inner,r_outer,porosity");
  EXPECT_EQ(lines(p("b.csv")).size(), 7u);
  EXPECT_EQ(lines(p("b_axial.csv"))[0], "z,porosity");
  EXPECT_EQ(lines(p("b_axial.csv")).size(), 6u);
  EXPECT_EQ(lines(p("b_map.csv"))[0], "r,z,porosity");
  EXPECT_EQ(lines(p("b_map.csv")).size(), 13u);
}

TEST_F(porosity_Cli, SpherocylinderPackingAndStdout) {
  ASSERT_EQ(run("packing spherocylinders --container-radius 3 --count 100 --diameter 0.5 --length 1 -o " + p("rods.csv")).status, 0);
  CliRun r = run("porosity " + p("rods.csv") + " --container-radius 3 --axial 4");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("z,porosity\n"), std::string::npos);
}

TEST_F(porosity_Cli, BadInputGivesFileLineAndStatus2) {
  std::ofstream(p("bad.csv")) << "x,y,z,d\n0,0,0,1\n0,0,nan,1\n1,1,1,-2\n";
  CliRun r = run("porosity " + p("bad.csv") + " --container-radius 3");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("bad.csv:3: centre coordinate is not finite"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bad.csv:4: diameter must be > 0"), std::string::npos) << r.out;
  std::ofstream(p("axis.csv")) << "x,y,z,ux,uy,uz,d,l\n0,0,0,0,0,0,1,1\n";
  r = run("porosity " + p("axis.csv") + " --container-radius 3");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("axis.csv:2: axis (ux, uy, uz) must not be zero"), std::string::npos) << r.out;
  EXPECT_EQ(run("porosity " + p("missing.csv") + " --container-radius 3").status, 2);
  std::ofstream(p("ok.csv")) << "x,y,z,d\n0,0,0.5,1\n";
  EXPECT_EQ(run("porosity " + p("ok.csv") + " --container-radius 3 --radii 5 --bins 5").status, 2);
  const CliRun neg = run("porosity " + p("ok.csv") + " --container-radius -1");
  EXPECT_EQ(neg.status, 2);
  EXPECT_NE(neg.out.find("--container-radius: must be a finite number > 0 (got -1)"), std::string::npos) << neg.out;
  EXPECT_EQ(run("porosity " + p("ok.csv") + " --container-radius nan").status, 2);
  EXPECT_EQ(run("porosity " + p("ok.csv") + " --container-radius 3 --z-range 2,1").status, 2);
  EXPECT_EQ(run("porosity " + p("ok.csv") + " --container-radius 3 --plot out.pdf").status, 2);
  EXPECT_EQ(run("porosity " + p("ok.csv") + " --container-radius 3 --plot out.png").status, 2);  // SVG only
  EXPECT_EQ(run("porosity " + p("ok.csv") + " --container-radius 3 --map 0,3").status, 2);
  const CliRun big = run("packing spheres --container-radius 1 --diameter 5 --count 3");
  EXPECT_EQ(big.status, 2);
  EXPECT_NE(big.out.find("--diameter: the particle diameter 5 must be smaller than the container diameter 2"),
            std::string::npos)
      << big.out;
  EXPECT_EQ(run("packing spherocylinders --container-radius 3 --solid-fraction 1.5").status, 2);
}

}  // namespace
