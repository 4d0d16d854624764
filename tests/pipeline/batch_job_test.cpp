// Batches (pipeline/batch_job.hpp, io/batch_file.hpp) and the parallel trace of a scene: the
// same output for 1 and several threads, bad jobs reported while the rest go on, all pairs.
#include "ssimarch/pipeline/batch_job.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/thread_pool.hpp"
#include "ssimarch/io/batch_file.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/trace_writers.hpp"
#include "testing/batch_outputs.hpp"

namespace ssimarch {
namespace {

using ::testing::HasSubstr;
using nlohmann::json;

using testing::without_times;

const std::string& kExamples = testing::examples_dir();

TEST(ParallelTrace, AScenesIntersectionsGiveTheSerialOutputOnAnyThreadCount) {
  // Four intersections of which the certified search and the tracer do real work.
  const Scene scene = load_scene(kExamples + "occt_tori_crossed.json");
  const Scene petals = load_scene(kExamples + "thesis_ex12_three_petals.json");
  auto output = [&](unsigned threads) {
    set_thread_count(threads);
    json all = json::array();
    for (const Scene* s : {&scene, &petals})
      for (const IntersectionRun& r : trace_scene(*s).runs) all.push_back(without_times(to_json(r)));
    return all;
  };
  const json serial = output(1);
  ASSERT_EQ(serial.size(), scene.intersections.size() + petals.intersections.size());
  EXPECT_FALSE(serial[0]["curves"].empty());
  EXPECT_EQ(output(2), serial);
  EXPECT_EQ(output(4), serial);
  set_thread_count(0);
}

TEST(Batch, AllPairsOfAModelAreEveryUnorderedPairOnce) {
  const Scene model = parse_scene(R"({"surfaces": {
      "a": {"sphere": {"center": [0,0,0], "radius": 1}}, "b": {"sphere": {"center": [1,0,0], "radius": 1}},
      "c": {"torus": {"center": [0,0,0], "axis": [0,0,1], "major_radius": 1, "minor_radius": 0.3}},
      "d": {"parametric": ["u", "v", "0.1*u*v"], "u": [-1, 1], "v": [-1, 1]}}})",
                                  "m.json");
  const std::vector<IntersectionSpec> pairs = all_surface_pairs(model, TraceJobOptions{});
  ASSERT_EQ(pairs.size(), 6u);  // 4 * 3 / 2
  EXPECT_EQ(pairs[0].name, "a/b");
  EXPECT_EQ(pairs[5].name, "c/d");
  EXPECT_EQ(pairs[2].kind, PairKind::kParametricImplicit);  // a/d: the patch has no implicit form
  EXPECT_TRUE(pairs[2].swapped);
  EXPECT_EQ(pairs[0].kind, PairKind::kImplicitImplicit);
}

// Runs every unit of a batch in one process with `threads` threads; the merged output.
json run_locally(const Batch& batch, unsigned threads) {
  std::atomic<std::size_t> next{0};
  std::vector<json> units(batch.units.size());
  std::mutex m;
  std::vector<int> runs(batch.units.size(), 0);
  run_batch_units(batch, threads, [&] { return next.fetch_add(1); }, [&](std::size_t u, BatchOutcome&& o) {
    json j = batch_unit_json(batch, u, o);
    std::lock_guard<std::mutex> lock(m);
    units[u] = std::move(j);
    ++runs[u];
  });
  for (int r : runs) EXPECT_EQ(r, 1);
  return without_times(batch_result_json(batch, units));
}

const char* kJobs = R"({"jobs": [
  "viviani.json",
  {"scene": {"surfaces": {"s": {"sphere": {"center": [0,0,0], "radius": 1}}, "p": {"plane": {"point": [0,0,0.5], "normal": [0,0,1], "u": [-2,2], "v": [-2,2]}},
                          "far": {"sphere": {"center": [9,9,9], "radius": 1}}}},
   "pairs": "all"},
  {"scene": "no_such_scene.json"},
  {"scene": "occt_tori_crossed.json", "intersections": ["tori_crossed"], "options": {"step_length": 0.05}},
  {"scene": {"surfaces": {"s": {"sphere": {"center": [0,0,0], "radius": 1}}}}, "pairs": "everything"},
  {"scene": {"surfaces": {"s": {"sphere": {"center": [0,0,0], "radius": 1e7}}, "t": {"sphere": {"center": [1e7,0,0], "radius": 1e7}}},
             "intersections": [{"surfaces": ["s", "t"], "options": {"tolerance": 1e-12}}]}}
]})";

TEST(Batch, BadJobsAndFailedPairsAreReportedAndTheRestIsTraced) {
  const Batch batch = parse_batch(kJobs, "jobs.json", kExamples);
  ASSERT_EQ(batch.jobs.size(), 6u);
  EXPECT_THAT(batch.jobs[2].error, HasSubstr("no_such_scene.json"));
  EXPECT_THAT(batch.jobs[4].error, HasSubstr("jobs[4].pairs"));
  const json out = run_locally(batch, 2);
  const json& jobs = out["jobs"];
  ASSERT_EQ(jobs.size(), 6u);
  EXPECT_EQ(jobs[0]["source"], "viviani.json");
  ASSERT_EQ(jobs[1]["intersections"].size(), 3u);  // far/p, far/s, p/s (names sorted)
  EXPECT_EQ(jobs[1]["intersections"][2]["name"], "p/s");
  // The plane z = 1/2 cuts the unit sphere in a circle of radius sqrt(3)/2.
  ASSERT_EQ(jobs[1]["intersections"][2]["curves"].size(), 1u);
  EXPECT_NEAR(jobs[1]["intersections"][2]["curves"][0]["length"].get<double>(), 2 * M_PI * std::sqrt(0.75), 1e-6);
  EXPECT_TRUE(jobs[1]["intersections"][0]["curves"].empty());  // far from both
  EXPECT_TRUE(jobs[2].contains("error"));
  EXPECT_FALSE(jobs[2].contains("intersections"));
  EXPECT_EQ(jobs[3]["intersections"].size(), 1u);
  EXPECT_EQ(jobs[3]["intersections"][0]["name"], "tori_crossed");
  EXPECT_FALSE(jobs[3]["intersections"][0]["curves"].empty());
  // A tolerance (stated; the default follows the model) below the rounding of a model this large:
  // refused before tracing, that pair's error.
  const json& bad = jobs[5]["intersections"][0];
  EXPECT_FALSE(bad["complete"].get<bool>());
  EXPECT_THAT(bad["error"].get<std::string>(), HasSubstr("usable range for the model size"));
  EXPECT_EQ(out["summary"]["failed_jobs"], 2);
  EXPECT_EQ(out["summary"]["failed_intersections"], 1);
  EXPECT_EQ(out["summary"]["intersections"], batch.units.size());
  EXPECT_FALSE(batch_result_complete(out));
  EXPECT_EQ(run_locally(batch, 1), out);
  EXPECT_EQ(run_locally(batch, 3), out);
}

TEST(Batch, AnEmptyJobListIsAnEmptyCompleteResult) {
  const Batch batch = parse_batch(R"({"jobs": []})", "jobs.json", ".");
  EXPECT_TRUE(batch.units.empty());
  const json out = run_locally(batch, 2);
  EXPECT_TRUE(out["jobs"].empty());
  EXPECT_EQ(out["summary"]["intersections"], 0);
  EXPECT_TRUE(batch_result_complete(out));
}

TEST(Batch, AnUnusableBatchFileIsAnInputError) {
  EXPECT_THROW(parse_batch("{\"jobs\": [", "jobs.json", "."), InputError);
  EXPECT_THROW(parse_batch(R"({"jobs": {}})", "jobs.json", "."), InputError);
  EXPECT_THROW(parse_batch(R"({"job": []})", "jobs.json", "."), InputError);
  try {
    parse_batch(R"({"jobs": [], "threads": 2})", "jobs.json", ".");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("threads"));
  }
}

}  // namespace
}  // namespace ssimarch
