// The porosity and packing jobs: the same numbers as the porosity functions called one by one
// (bit for bit), every invalid job rejected with its field named, and the packing's own errors
// passed through with their file location.
#include "ssimarch/pipeline/porosity_job.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/pipeline/packing_job.hpp"
#include "testing/packed_beds.hpp"

namespace ssimarch {
namespace {

PorosityJob small_job() {
  PorosityJob job;
  job.packing = testing::drop_and_roll_bed(2.5, 120, 11).particles;
  job.container_radius = 2.5;
  return job;
}

std::string where_of(const PorosityJob& job) {
  try {
    run_porosity_job(job);
  } catch (const InputError& e) {
    return e.where();
  }
  return "no error";
}

TEST(pipeline_PorosityJob, EqualsTheProfilesComputedOneByOne) {
  PorosityJob job = small_job();
  job.radial_points = 12;
  job.bins = 5;
  job.axial_slices = 7;
  job.map_radii = 3;
  job.map_heights = 4;
  const PorosityJobResult r = run_porosity_job(job);
  const Container c{2.5, vertical_extent(job.packing)};
  EXPECT_EQ(r.container.slab.z_min, c.slab.z_min);
  EXPECT_EQ(r.container.slab.z_max, c.slab.z_max);
  EXPECT_EQ(r.particles, 120);
  EXPECT_FALSE(r.spherocylinders);
  EXPECT_EQ(r.bulk.porosity, bulk_porosity(job.packing, c).porosity);
  ASSERT_TRUE(r.radial && r.bins && r.axial && r.map);
  EXPECT_EQ(r.radial->porosity, radial_profile(job.packing, c, even_radii(2.5, 12)).porosity);
  EXPECT_EQ(r.bins->porosity, bin_profile(job.packing, c, even_edges(2.5, 5)).porosity);
  EXPECT_EQ(r.axial->porosity,
            axial_profile(job.packing, c, slice_centres(c.slab.z_min, c.slab.z_max, 7)).porosity);
  const std::vector<double> rs{2.5 * 0.5 / 3, 2.5 * 1.5 / 3, 2.5 * 2.5 / 3};
  EXPECT_EQ(cell_centres(2.5, 3), rs);
  EXPECT_EQ(r.map->porosity, porosity_map(job.packing, c, rs, slice_centres(c.slab.z_min, c.slab.z_max, 4)).porosity);
  EXPECT_EQ(r.unconverged, r.bulk.stats.unconverged + r.radial->stats.unconverged + r.bins->stats.unconverged +
                               r.axial->stats.unconverged + r.map->stats.unconverged);
  EXPECT_TRUE(r.timings.bulk && r.timings.radial && r.timings.axial && r.timings.map);
}

TEST(pipeline_PorosityJob, RunsOnlyTheStagesAskedFor) {
  PorosityJob job = small_job();
  job.height_range = BedSlab{0.5, 1.5};
  job.axial_slices = 3;
  const PorosityJobResult r = run_porosity_job(job);
  EXPECT_EQ(r.container.slab.z_min, 0.5);
  EXPECT_FALSE(r.radial || r.bins || r.map);
  ASSERT_TRUE(r.axial);
  EXPECT_EQ(r.axial->x, slice_centres(0.5, 1.5, 3));
  EXPECT_FALSE(r.timings.radial || r.timings.map);
}

TEST(pipeline_PorosityJob, ReportsProgressPerStage) {
  PorosityJob job = small_job();
  job.radial_points = 4;
  job.options.threads = 1;
  std::vector<std::string> stages;
  job.progress = [&](std::string_view s, double) {
    if (stages.empty() || stages.back() != s) stages.emplace_back(s);
  };
  run_porosity_job(job);
  EXPECT_EQ(stages, (std::vector<std::string>{"bulk", "radial"}));
}

TEST(pipeline_PorosityJob, InvalidJobsNameTheirField) {
  PorosityJob job = small_job();
  job.container_radius = -1;
  EXPECT_EQ(where_of(job), "container_radius");
  job = small_job();
  job.options.tolerance = 0;
  EXPECT_EQ(where_of(job), "options.tolerance");
  job = small_job();
  job.axial_slices = -2;
  EXPECT_EQ(where_of(job), "axial_slices");
  job = small_job();
  job.map_radii = 3;
  EXPECT_EQ(where_of(job), "map_radii");
  job = small_job();
  job.height_range = BedSlab{2.0, 2.0};
  EXPECT_EQ(where_of(job), "height_range");
  job = PorosityJob{};
  job.container_radius = 1;
  EXPECT_EQ(where_of(job), "packing");
}

TEST(pipeline_PorosityJob, PackingFileErrorsKeepTheirLocation) {
  const auto dir = std::filesystem::temp_directory_path() / ("ssimarch_job_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.csv") << "x,y,z,d\n0,0,0,1\n0,0,x,1\n";
  std::ofstream(dir / "empty.csv") << "x,y,z,d\n";
  PorosityJob job;
  job.container_radius = 1;
  job.packing_file = dir / "bad.csv";
  try {
    run_porosity_job(job);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:3:5: column 'z': not a number"), std::string::npos) << e.what();
  }
  job.packing_file = dir / "empty.csv";
  EXPECT_EQ(where_of(job), (dir / "empty.csv").string());
  std::filesystem::remove_all(dir);
}

TEST(pipeline_PackingJob, GeneratesTheGeneratorsBedAndItsBulkPorosity) {
  SpherocylinderRsaOptions o;
  o.container_radius = 2;
  o.diameter = 0.5;
  o.length = 1;
  o.count = 40;
  o.seed = 9;
  const PackingJobResult r = run_packing_job(o);
  GeneratorReport rep;
  const auto direct = rsa_spherocylinders(o, &rep);
  ASSERT_EQ(r.particles.size(), direct.size());
  EXPECT_EQ(r.particles.back().centre, direct.back().centre);
  EXPECT_EQ(r.bed.slab.z_max, rep.height);
  EXPECT_EQ(r.bulk.porosity, bulk_porosity(direct, Container{2.0, {0.0, rep.height}}).porosity);
  SphereBedOptions s;
  s.container_radius = 1;
  s.diameter = 3;
  try {
    run_packing_job(s);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "diameter");
  }
}

}  // namespace
}  // namespace ssimarch
