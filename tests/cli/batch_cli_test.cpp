// `ssimarch batch` run as a user runs it: one process with 1 and several threads, and (in a build
// with SSIMARCH_MPI=ON) under mpirun with 1, 2 and 3 ranks: the same merged output every time,
// a rank without work, an empty job list, a bad job in the middle reported while the rest go on.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "testing/batch_outputs.hpp"
#include "testing/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using nlohmann::json;
using ssimarch::testing::CliRun;

fs::path scratch() { return ssimarch::testing::cli_scratch_dir(); }

using ssimarch::testing::read_json;
using ssimarch::testing::without_times;

std::string write_file(const std::string& name, const std::string& text) {
  return ssimarch::testing::write_scratch_file(name, text);
}

const std::string& kExamples = ssimarch::testing::examples_dir();

// Eight surfaces (28 pairs: closed-form quadric pairs, traced tori, empty pairs), two example
// scenes, and a malformed job in the middle.
std::string jobs_file() {
  const std::string model = R"({"surfaces": {
    "a": {"sphere": {"center": [0,0,0], "radius": 1}}, "b": {"sphere": {"center": [1.2,0,0], "radius": 0.8}},
    "c": {"torus": {"center": [0,0,0.5], "axis": [0,1,0], "major_radius": 1, "minor_radius": 0.3}},
    "d": {"cylinder": {"point": [0,0,0], "axis": [0,0,1], "radius": 0.5, "range": [-2, 2]}},
    "e": {"torus": {"center": [0.5,0,0], "axis": [0,0,1], "major_radius": 1.1, "minor_radius": 0.35}},
    "f": {"ellipsoid": {"center": [0,0.3,0], "radii": [1.3, 0.6, 0.9]}},
    "g": {"sphere": {"center": [20,0,0], "radius": 1}},
    "h": {"cone": {"apex": [0,0,-1.5], "axis": [0,0,1], "half_angle": 0.5, "range": [0.1, 2.5]}}}})";
  write_file("model.json", model);
  return write_file("jobs.json", R"({"jobs": [
    {"scene": "model.json", "pairs": "all"},
    ")" + kExamples + R"(viviani.json",
    {"scene": {"surfaces": {"s": {"sphre": {}}}}},
    ")" + kExamples + R"(occt_tori_crossed.json"]})");
}

TEST(BatchCli, TheOutputDoesNotDependOnTheThreadCount) {
  const std::string jobs = jobs_file();
  const fs::path one = scratch() / "batch1.json", three = scratch() / "batch3.json";
  const CliRun r1 = ssimarch::testing::run_cli("batch " + jobs + " --threads 1 -o " + one.string());
  const CliRun r3 = ssimarch::testing::run_cli("batch " + jobs + " --threads 3 -o " + three.string());
  // The malformed job makes the batch incomplete (status 1); the others are traced.
  EXPECT_EQ(r1.status, 1) << r1.err;
  EXPECT_EQ(r3.status, 1) << r3.err;
  const json a = read_json(one), b = read_json(three);
  EXPECT_EQ(without_times(a), without_times(b));
  ASSERT_EQ(a["jobs"].size(), 4u);
  EXPECT_EQ(a["jobs"][0]["intersections"].size(), 28u);
  EXPECT_THAT(a["jobs"][2]["error"].get<std::string>(), HasSubstr("sphre"));
  EXPECT_FALSE(a["jobs"][3]["intersections"][0]["curves"].empty());
  EXPECT_EQ(a["summary"]["failed_jobs"], 1);
  EXPECT_THAT(r1.err, HasSubstr("load balance"));
}

// --progress json: one line per update on stderr, stage "batch", in units of the batch, ending at
// every unit; -q shows none.
TEST(BatchCli, ProgressReportsTheUnitsAsJsonLines) {
  const std::string jobs = jobs_file();
  const fs::path out = scratch() / "batch_progress.json";
  const CliRun r = ssimarch::testing::run_cli("batch " + jobs + " --threads 2 --progress json -o " + out.string());
  EXPECT_EQ(r.status, 1) << r.err;
  const std::size_t units = read_json(out).at("summary").at("intersections").get<std::size_t>();
  std::istringstream lines(r.err);
  double last_done = -1, total = 0;
  int reports = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("{\"progress\"", 0) != 0) continue;
    const json p = json::parse(line).at("progress");
    EXPECT_EQ(p.at("stage"), "batch");
    EXPECT_GE(p.at("done").get<double>(), last_done);  // the highest unit reached never goes back
    last_done = p.at("done").get<double>();
    total = p.at("total").get<double>();
    ++reports;
  }
  EXPECT_GE(reports, 2);
  EXPECT_EQ(total, static_cast<double>(units));
  EXPECT_EQ(last_done, total);
  const CliRun quiet = ssimarch::testing::run_cli("batch " + jobs + " --progress json -q -o " + out.string());
  EXPECT_THAT(quiet.err, ::testing::Not(HasSubstr("\"progress\"")));
}

TEST(BatchCli, StatusZeroWhenEverythingIsTracedAndTwoForAnUnusableFile) {
  const std::string ok = write_file("ok.json", R"({"jobs": [")" + kExamples + R"(viviani.json"]})");
  const CliRun r = ssimarch::testing::run_cli("batch " + ok + " -q");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["summary"]["intersections"], 2);  // viviani.json has two
  const CliRun bad = ssimarch::testing::run_cli("batch " + write_file("bad.json", R"({"jobs": 3})"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_THAT(bad.err, HasSubstr("jobs"));
}

#ifdef SSIMARCH_MPIEXEC
// mpirun as the tests run it (root in containers; more ranks than cores).
CliRun run_mpi(int ranks, const std::string& args) {
  const fs::path err = scratch() / "mpi_stderr.txt";
  const std::string cmd = std::string(SSIMARCH_MPIEXEC) + " --oversubscribe --allow-run-as-root -n " + std::to_string(ranks) + " " +
                          SSIMARCH_CLI + " " + args + " 2>" + err.string();
  CliRun r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    ADD_FAILURE() << "cannot run " << cmd;
    return r;
  }
  char buf[4096];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int s = pclose(p);
  r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  std::ifstream in(err);
  std::stringstream e;
  e << in.rdbuf();
  r.err = e.str();
  return r;
}

TEST(BatchMpi, OneTwoAndThreeRanksGiveTheSameOutput) {
  const std::string jobs = jobs_file();
  const fs::path serial = scratch() / "serial.json";
  ASSERT_EQ(ssimarch::testing::run_cli("batch " + jobs + " --threads 1 -o " + serial.string()).status, 1);
  const json expected = without_times(read_json(serial));
  for (int ranks : {1, 2, 3}) {
    const fs::path out = scratch() / ("mpi" + std::to_string(ranks) + ".json");
    const CliRun r = run_mpi(ranks, "batch " + jobs + " --threads 2 -o " + out.string());
    EXPECT_EQ(r.status, 1) << ranks << " ranks: " << r.err;
    EXPECT_EQ(without_times(read_json(out)), expected) << ranks << " ranks";
    EXPECT_THAT(r.err, HasSubstr("rank " + std::to_string(ranks - 1) + ":"));
    EXPECT_THAT(r.err, HasSubstr(std::to_string(ranks) + " rank(s)"));
  }
}

TEST(BatchMpi, ARankWithoutWorkAndAnEmptyJobList) {
  // Two intersections, three ranks: one rank at least finds nothing to do.
  const std::string one = write_file("one.json", R"({"jobs": [")" + kExamples + R"(viviani.json"]})");
  const CliRun r = run_mpi(3, "batch " + one + " --threads 1");
  EXPECT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out["summary"]["intersections"], 2);
  // Each entry is what `ssimarch trace` writes for the intersection, plus "complete".
  const CliRun t = ssimarch::testing::run_cli("trace " + kExamples + "viviani.json -q");
  ASSERT_EQ(t.status, 0) << t.err;
  json traced = without_times(json::parse(t.out))["intersections"];
  for (json& i : traced) i["complete"] = true;
  EXPECT_EQ(without_times(out["jobs"][0]["intersections"]), traced);
  EXPECT_THAT(r.err, HasSubstr("0 units"));
  const std::string empty = write_file("empty.json", R"({"jobs": []})");
  const CliRun e = run_mpi(2, "batch " + empty);
  EXPECT_EQ(e.status, 0) << e.err;
  EXPECT_TRUE(json::parse(e.out)["jobs"].empty());
}
#endif

}  // namespace
