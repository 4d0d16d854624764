// Clumped particles (issue 30 item 2): the clump column of CSV files and LAMMPS dumps read by every
// reader, the overlaps inside a particle told apart from those between particles (against a scan of
// all pairs, on threads and in-process ranks), and the particles counted across ranks.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/overlaps.hpp"
#include "ssimarch/porosity/packing.hpp"
#include "thread_group.hpp"

namespace ssimarch {
namespace {

namespace fs = std::filesystem;

// A file under the test's own scratch directory, removed with it.
class porosity_Clumps : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ssimarch_clumps_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  fs::path dir_;
};

// The error text of reading `path` with the file reader, "no error" when it reads.
std::string file_error(const fs::path& path) {
  try {
    read_packing(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(porosity_Clumps, CsvAndDumpsCarryTheClumpColumnInEveryReader) {
  const std::string csv = "x,y,z,d,particle\n0,0,1,1,7\n0.4,0,1,1,7\n3,0,1,1,-2\n";
  for (const Packing& p : {read_packing(write("bed.csv", csv)), [&] {
                             std::istringstream in(csv);
                             return read_packing_csv(in, "bed.csv");
                           }()}) {
    ASSERT_EQ(p.particles.size(), 3u);
    EXPECT_EQ(p.clumps, (std::vector<long>{7, 7, -2}));
    EXPECT_EQ(particle_count(p), 2);
  }
  // LAMMPS: `mol` (a molecule, LAMMPS) or `id_multisphere` (a LIGGGHTS multisphere body).
  const std::string dump =
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
      "ITEM: ATOMS id type x y z radius id_multisphere\n1 1 0 0 1 0.5 4\n2 1 0.4 0 1 0.5 4\n3 1 2 0 1 0.5 5\n";
  for (const Packing& p : {read_packing(write("bed.dump", dump)), [&] {
                             std::istringstream in(dump);
                             return read_lammps_dump(in, "bed.dump");
                           }()}) {
    EXPECT_EQ(p.clumps, (std::vector<long>{4, 4, 5}));
    EXPECT_EQ(particle_count(p), 2);
  }
  const Packing mol = read_packing(
      write("mol.dump", "ITEM: NUMBER OF ATOMS\n2\nITEM: ATOMS x y z diameter mol\n0 0 0 1 3\n1 0 0 1 3\n"));
  EXPECT_EQ(mol.clumps, (std::vector<long>{3, 3}));
  // Without the column: no ids, every row a particle.
  const Packing plain = read_packing(write("plain.csv", "x,y,z,d\n0,0,1,1\n0.4,0,1,1\n"));
  EXPECT_TRUE(plain.clumps.empty());
  EXPECT_EQ(particle_count(plain), 2);
}

TEST_F(porosity_Clumps, BadClumpIdsAndTwoClumpColumnsAreNamed) {
  EXPECT_NE(file_error(write("a.csv", "x,y,z,d,clump\n0,0,1,1,2.5\n"))
                .find("a.csv:2:9: column 'clump': the clump id must be an integer"),
            std::string::npos)
      << file_error(write("a.csv", "x,y,z,d,clump\n0,0,1,1,2.5\n"));
  EXPECT_NE(
      file_error(write("b.csv", "x,y,z,d,particle\n0,0,1,1,x\n")).find("b.csv:2:9: column 'particle': not a number"),
      std::string::npos);
  EXPECT_NE(file_error(write("c.csv", "x,y,z,d,particle\n0,0,1,1,1e300\n")).find("at most 2^53"), std::string::npos);
  EXPECT_NE(file_error(write("d.csv", "particle,x,y,z,d,clump\n1,0,0,1,1,1\n"))
                .find("d.csv:1: the header names two clump columns ('particle' and 'clump')"),
            std::string::npos)
      << file_error(write("d.csv", "particle,x,y,z,d,clump\n1,0,0,1,1,1\n"));
  std::istringstream in("x,y,z,d,clump\n0,0,1,1,2.5\n");
  try {
    read_packing_csv(in, "s.csv");
    ADD_FAILURE() << "a fractional clump id was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.csv:2:9: column 'clump': the clump id must be an integer"),
              std::string::npos)
        << e.what();
  }
}

Particle sphere(double x, double y, double z, double d) {
  Particle p;
  p.centre = Vec3(x, y, z);
  p.diameter = d;
  return p;
}

// Clumps of 1 to 4 overlapping spheres (a random centre, spheres within half a diameter of it),
// the clumps themselves dense enough in a 6 x 6 x 12 column that many overlap each other.
void clumped_column(int clumps, std::uint64_t seed, std::vector<Particle>& ps, std::vector<long>& ids) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  for (int c = 0; c < clumps; ++c) {
    const Vec3 centre(6 * U(rng), 6 * U(rng), 12 * U(rng));
    const int n = 1 + static_cast<int>(4 * U(rng));
    for (int k = 0; k < n; ++k) {
      const double d = 0.3 + 0.4 * U(rng);
      ps.push_back(
          sphere(centre.x() + d * (U(rng) - 0.5), centre.y() + d * (U(rng) - 0.5), centre.z() + d * (U(rng) - 0.5), d));
      ids.push_back(1000 + 3 * c);  // ids neither 0-based nor consecutive
    }
  }
}

// find_overlaps of the packing split into n blocks over in-process ranks, with the blocks' clump ids.
std::vector<ParticleOverlaps> split_search(const std::vector<Particle>& ps, const std::vector<long>& ids, int n) {
  std::vector<ParticleOverlaps> out(static_cast<std::size_t>(n));
  testing::run_on_ranks(n, [&](const testing::ThreadGroup::Member& me, int k) {
    const std::size_t b = ps.size() * static_cast<std::size_t>(k) / static_cast<std::size_t>(n);
    const std::size_t e = ps.size() * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(n);
    out[static_cast<std::size_t>(k)] =
        find_overlaps(std::span<const Particle>(ps.data() + b, e - b), static_cast<long>(b), me, 1e-9, 2,
                      std::span<const long>(ids.data() + b, e - b));
  });
  return out;
}

TEST_F(porosity_Clumps, OverlapsInsideAParticleAreToldApartFromThoseBetweenParticles) {
  std::vector<Particle> ps;
  std::vector<long> ids;
  clumped_column(900, 5, ps, ids);
  // The reference: every pair, split by whether the two spheres share a clump.
  long between = 0, within = 0;
  long double v_between = 0, v_within = 0;
  double worst = 0;
  for (std::size_t i = 0; i < ps.size(); ++i)
    for (std::size_t j = i + 1; j < ps.size(); ++j) {
      const double d = (ps[i].centre - ps[j].centre).norm();
      const double depth = ps[i].radius() + ps[j].radius() - d;
      if (!(depth > 1e-9 * std::min(ps[i].diameter, ps[j].diameter))) continue;
      const long double v = sphere_lens_volume(ps[i].radius(), ps[j].radius(), d);
      if (ids[i] == ids[j]) {
        ++within, v_within += v;
      } else {
        ++between, v_between += v;
        worst = std::max(worst, depth);
      }
    }
  ASSERT_GT(within, 300);
  ASSERT_GT(between, 100);
  const ParticleOverlaps one = find_overlaps(ps, 1e-9, 1, ids);
  EXPECT_EQ(one.pairs, between);
  EXPECT_EQ(one.clump_pairs, within);
  EXPECT_NEAR(one.max_depth, worst, 1e-15 * worst);
  EXPECT_NEAR(one.doubled_volume, static_cast<double>(v_between), 1e-13 * static_cast<double>(v_between));
  EXPECT_NEAR(one.clump_doubled_volume, static_cast<double>(v_within), 1e-13 * static_cast<double>(v_within));
  // Without the ids every overlapping pair is between particles.
  const ParticleOverlaps plain = find_overlaps(ps, 1e-9, 1);
  EXPECT_EQ(plain.pairs, between + within);
  EXPECT_EQ(plain.clump_pairs, 0);
  // Threads and ranks: the same counts and the same bits.
  for (unsigned threads : {2u, 3u}) {
    const ParticleOverlaps t = find_overlaps(ps, 1e-9, threads, ids);
    EXPECT_EQ(t.pairs, one.pairs);
    EXPECT_EQ(t.clump_pairs, one.clump_pairs);
    EXPECT_EQ(t.clump_doubled_volume, one.clump_doubled_volume);
  }
  for (int ranks : {2, 3})
    for (const ParticleOverlaps& r : split_search(ps, ids, ranks)) {
      EXPECT_EQ(r.pairs, one.pairs) << ranks;
      EXPECT_EQ(r.worst_first, one.worst_first) << ranks;
      EXPECT_EQ(r.worst_second, one.worst_second) << ranks;
      EXPECT_EQ(r.doubled_volume, one.doubled_volume) << ranks;
      EXPECT_EQ(r.clump_pairs, one.clump_pairs) << ranks;
      EXPECT_EQ(r.clump_doubled_volume, one.clump_doubled_volume) << ranks;
    }
  EXPECT_THROW(find_overlaps(ps, 1e-9, 1, std::span<const long>(ids.data(), 3)), std::invalid_argument);
}

TEST_F(porosity_Clumps, ParticlesAreCountedOnceAcrossRanks) {
  // Ids shared between the ranks' blocks, repeated and negative: 5 distinct values.
  const std::vector<long> ids = {4, -1, 4, 9, 9, 2, -1, 4, 0, 2, 9};
  EXPECT_EQ(distinct_count(ids), 5);
  for (int n : {1, 2, 3, 4}) {
    std::vector<long> out(static_cast<std::size_t>(n));
    testing::run_on_ranks(n, [&](const testing::ThreadGroup::Member& me, int k) {
      const std::size_t b = ids.size() * static_cast<std::size_t>(k) / static_cast<std::size_t>(n);
      const std::size_t e = ids.size() * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(n);
      out[static_cast<std::size_t>(k)] = distinct_count(std::span<const long>(ids.data() + b, e - b), me);
    });
    for (long c : out) EXPECT_EQ(c, 5) << n << " ranks";
  }
}

}  // namespace
}  // namespace ssimarch
