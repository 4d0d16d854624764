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

// Issue 13: a failed run leaves earlier outputs untouched, a full device is an error.
TEST_F(porosity_Cli, OutputsAreAllOrNothing) {
  std::ofstream(p("ok.csv")) << "x,y,z,d\n0,0,0.5,1\n";
  std::ofstream(p("out.csv")) << "earlier\n";
  std::ofstream(p("out_axial.csv")) << "earlier axial\n";
  // The summary cannot be written (its directory is missing) after both profiles were: neither
  // profile file changes and no temporary is left behind.
  CliRun r = run("porosity " + p("ok.csv") + " --container-radius 3 --radii 5 --axial 3 -o " + p("out.csv") +
                 " --summary " + p("missing/s.json"));
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("missing/s.json: cannot be opened for writing"), std::string::npos) << r.out;
  EXPECT_EQ(lines(p("out.csv")), std::vector<std::string>{"earlier"});
  EXPECT_EQ(lines(p("out_axial.csv")), std::vector<std::string>{"earlier axial"});
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);
  if (fs::exists("/dev/full")) {
    CliRun full = run("porosity " + p("ok.csv") + " --container-radius 3 --radii 5 -o /dev/full");
    EXPECT_EQ(full.status, 2) << full.out;
    EXPECT_NE(full.out.find("/dev/full: write failed"), std::string::npos) << full.out;
  }
}

TEST_F(porosity_Cli, OverlappingParticlesAreReportedAndFailUnderStrict) {
  // Three coincident spheres: their union is one ball (issue 30); the run names the worst pair.
  std::ofstream(p("three.csv")) << "x,y,z,d\n0,0,1,1\n0,0,1,1\n0,0,1,1\n";
  std::ofstream(p("one.csv")) << "x,y,z,d\n0,0,1,1\n";
  const std::string args = " --container-radius 2 --z-range 0.9,1.1 --radii 8 -o ";
  CliRun r = run("porosity " + p("three.csv") + args + p("r.csv"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("note: 3 pairs of particles overlap (worst: particles 1 and 2 by 1)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("is counted once: the porosities are those of the union"), std::string::npos) << r.out;
  ASSERT_EQ(run("porosity " + p("one.csv") + args + p("one_r.csv")).status, 0);
  const auto three = lines(p("r.csv")), one = lines(p("one_r.csv"));
  ASSERT_EQ(three.size(), one.size());
  for (std::size_t k = 1; k < one.size(); ++k)  // r,porosity after the header
    EXPECT_NEAR(std::stod(three[k].substr(three[k].find(',') + 1)), std::stod(one[k].substr(one[k].find(',') + 1)),
                1e-9)
        << three[k] << " vs " << one[k];
  // Counted once per particle (the old rule, on request): the porosity at their centre is 1 - 3.
  CliRun sum = run("porosity " + p("three.csv") + args + p("sum.csv") + " --overlaps sum");
  EXPECT_EQ(sum.status, 0) << sum.out;
  EXPECT_NE(sum.out.find("warning: 3 pairs of particles overlap"), std::string::npos) << sum.out;
  EXPECT_NE(sum.out.find("outside [0, 1] for this reason"), std::string::npos) << sum.out;
  CliRun bad = run("porosity " + p("three.csv") + args + p("bad.csv") + " --overlaps both");
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("--overlaps must be 'union'"), std::string::npos) << bad.out;
  CliRun strict = run("porosity " + p("three.csv") + " --container-radius 2 --radii 4 --strict -o " + p("s.csv"));
  EXPECT_EQ(strict.status, 1) << strict.out;
  EXPECT_NE(strict.out.find("--strict: 3 pairs of particles overlap"), std::string::npos) << strict.out;
  EXPECT_FALSE(fs::exists(p("s.csv")));
}

TEST_F(porosity_Cli, ClumpedParticlesAreTheirUnionAndStrictRejectsOnlyOverlapsBetweenThem) {
  // Two particles of two overlapping spheres each (a clump column), apart from each other; the same
  // spheres without the column.
  const std::string rows = "0,0,1,1,7\n0.4,0,1,1,7\n1.5,0,1,1,9\n1.9,0,1,1,9\n";
  std::ofstream(p("clumps.csv")) << "x,y,z,d,particle\n" << rows;
  std::ofstream(p("spheres.csv")) << "x,y,z,d\n0,0,1,1\n0.4,0,1,1\n1.5,0,1,1\n1.9,0,1,1\n";
  const std::string args = " --container-radius 3 --z-range 0.6,1.4 --radii 12 --strict -o ";
  CliRun c = run("porosity " + p("clumps.csv") + args + p("c.csv") + " --summary " + p("c.json"));
  ASSERT_EQ(c.status, 0) << c.out;
  EXPECT_NE(c.out.find("4 spheres of 2 clumped particles"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("note: 2 pairs of spheres overlap inside their clumped particles (2 particles of 4 spheres)"),
            std::string::npos)
      << c.out;
  std::ifstream js(p("c.json"));
  const nlohmann::json j = nlohmann::json::parse(js);
  EXPECT_EQ(j["particles"], 4);
  EXPECT_EQ(j["clumped_particles"], 2);
  EXPECT_EQ(j["overlaps"]["pairs"], 0);
  EXPECT_EQ(j["overlaps"]["within_clumps"]["pairs"], 2);
  // A clumped bed's profile is its union's: the same file without the column, value for value.
  CliRun s =
      run("porosity " + p("spheres.csv") + " --container-radius 3 --z-range 0.6,1.4 --radii 12 -o " + p("s.csv"));
  ASSERT_EQ(s.status, 0) << s.out;
  EXPECT_EQ(lines(p("c.csv")), lines(p("s.csv")));
  // Particles 7 and 9 moved together: one pair between particles, which --strict rejects.
  std::ofstream(p("touching.csv")) << "x,y,z,d,particle\n0,0,1,1,7\n0.4,0,1,1,7\n1.3,0,1,1,9\n1.7,0,1,1,9\n";
  CliRun t = run("porosity " + p("touching.csv") + args + p("t.csv"));
  EXPECT_EQ(t.status, 1) << t.out;
  EXPECT_NE(t.out.find("--strict: 1 pair of clumped particles overlap (worst: rows 2 and 3 by 0.1"), std::string::npos)
      << t.out;
  EXPECT_FALSE(fs::exists(p("t.csv")));
}

TEST_F(porosity_Cli, RangesAreValidatedWithTheReason) {
  std::ofstream(p("ok.csv")) << "x,y,z,d\n0,0,0.5,1\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--container-radius 3 --radii 2000000000", "--radii: must be at most 1000000"},
      {"--container-radius 3 --radii 10000000", "--radii: must be at most 1000000"},
      {"--container-radius 1e-300", "--container-radius: the radius 1e-300 is below 1e-100"},
      {"--container-radius 3 --map 10000,10000", "--map: a map of at most 1000000 cells"},
      {"--container-radius 3 --tolerance nan", "--tolerance: must be a finite number > 0"},
  };
  for (const auto& [args, message] : cases) {
    CliRun r = run("porosity " + p("ok.csv") + " " + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << args << "\n" << r.out;
  }
  std::ofstream(p("huge.csv")) << "x,y,z,d\n0,0,0,1e308\n";
  CliRun huge = run("porosity " + p("huge.csv") + " --container-radius 3");
  EXPECT_EQ(huge.status, 2) << huge.out;
  EXPECT_NE(huge.out.find("particle 1: diameter 1e+308 is beyond +-1e100"), std::string::npos) << huge.out;
  CliRun zero = run("porosity /dev/zero --container-radius 3");
  EXPECT_EQ(zero.status, 2) << zero.out;
  EXPECT_NE(zero.out.find("/dev/zero:1: a line longer than 64 KiB"), std::string::npos) << zero.out;
  std::ofstream(p("bom.csv")) << "\xEF\xBB\xBFx,y,z,d\n0,0,0.5,1\n";
  EXPECT_EQ(run("porosity " + p("bom.csv") + " --container-radius 3 --radii 3").status, 0);
}

TEST_F(porosity_Cli, GeneratorOptionsAreBoundedAndItsPromiseHolds) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--container-radius 5 --diameter-max inf", "--diameter-max: must be 0 or a finite number >= diameter"},
      {"--container-radius 5 --diameter-max 100", "--diameter-max: the largest diameter 100 must be smaller than the container diameter 10"},
      {"--container-radius 5 --count 100000000000", "--count: must be at most 1e7"},
  };
  for (const auto& [args, message] : cases) {
    CliRun r = run("packing spheres " + args + " -o " + p("bed.csv"));
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(p("bed.csv")));
  }
  // Polydisperse beds keep the no-overlap promise (checked on every run; a break fails the command).
  CliRun ok = run("packing spheres --container-radius 4 --diameter 0.5 --diameter-max 3 --count 150 -o " + p("poly.csv"));
  EXPECT_EQ(ok.status, 0) << ok.out;
  EXPECT_EQ(ok.out.find("max overlap"), std::string::npos) << ok.out;
}

// Issue 29: inputs that were read wrongly or silently, each a clean error naming file, line or flag.
TEST_F(porosity_Cli, StrictInputsAreRefusedWithTheRule) {
  auto write = [&](const char* name, const std::string& text) {
    std::ofstream(p(name)) << text;
    return p(name);
  };
  const std::string ok = write("ok.csv", "x,y,z,d\n0,0,1,1\n");
  // A row with a field past the header's: a shifted id column must not be read as coordinates.
  CliRun extra = run("porosity " + write("extra.csv", "x,y,z,d\n0,0,1,1\n7,0,0,1,1\n") + " --container-radius 3");
  EXPECT_EQ(extra.status, 2) << extra.out;
  EXPECT_NE(extra.out.find("extra.csv:3"), std::string::npos) << extra.out;
  EXPECT_NE(extra.out.find("more fields than the header"), std::string::npos) << extra.out;
  // A trailing separator is no field.
  EXPECT_EQ(
      run("porosity " + write("trailing.csv", "x,y,z,d\n0,0,1,1,\n") + " --container-radius 3 -o " + p("t.csv")).status,
      0);
  CliRun twice = run("porosity " + write("twice.csv", "x,y,z,d,x\n0,0,1,1,0\n") + " --container-radius 3");
  EXPECT_EQ(twice.status, 2);
  EXPECT_NE(twice.out.find("names column 'x' twice (fields 1 and 5)"), std::string::npos) << twice.out;
  CliRun scaled =
      run("porosity " +
          write("scaled.dump",
                "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: ATOMS id xs ys zs radius\n1 0.5 0.5 0.5 0.5\n") +
          " --container-radius 3");
  EXPECT_EQ(scaled.status, 2);
  EXPECT_NE(scaled.out.find("no 'ITEM: BOX BOUNDS'"), std::string::npos) << scaled.out;
  CliRun gz = run("porosity " + write("bed.dump.gz", std::string("\x1f\x8b\x08\x00rest", 8)) + " --container-radius 3");
  EXPECT_EQ(gz.status, 2);
  EXPECT_NE(gz.out.find("is gzip-compressed"), std::string::npos) << gz.out;
  for (const char* flag : {"--radii", "--bins", "--axial"}) {
    CliRun zero = run("porosity " + ok + " --container-radius 3 " + flag + " 0");
    EXPECT_EQ(zero.status, 2) << flag;
    EXPECT_NE(zero.out.find(std::string(flag) + ": must be a positive number, got 0"), std::string::npos) << zero.out;
  }
}

// Issue 29: an output that names an input is refused before anything is written; the input stays.
TEST_F(porosity_Cli, AnOutputNeverReplacesTheInput) {
  std::ofstream(p("bed.csv")) << "x,y,z,d\n0,0,1,1\n";
  CliRun r = run("porosity " + p("bed.csv") + " --container-radius 3 -o " + p("bed.csv"));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("is an input of this run"), std::string::npos) << r.out;
  EXPECT_EQ(lines(p("bed.csv")), (std::vector<std::string>{"x,y,z,d", "0,0,1,1"}));
  // Another spelling of the same file, and a plot onto it, too.
  CliRun plot = run("porosity " + p("bed.csv") + " --container-radius 3 -o " + p("out.csv") + " --plot " +
                    dir_.string() + "/./bed.csv");
  EXPECT_EQ(plot.status, 2) << plot.out;
  EXPECT_FALSE(fs::exists(p("out.csv")));
  EXPECT_EQ(lines(p("bed.csv")).size(), 2u);
}

}  // namespace
