// The streaming reader of packing files (read_packing_share): the same particles as the line
// readers, whole or split into 1..5 shares (in-process ranks), lines across its 4 MiB blocks,
// shares without rows, an empty file, and a bad row in the middle of a large file reported by
// every share with the file's line number.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "ssimarch/porosity/packing.hpp"
#include "thread_group.hpp"

namespace ssimarch {
namespace {

namespace fs = std::filesystem;

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("ssimarch_share_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// Reads `path` split into n shares; returns the concatenated particles (or the errors, one per share).
struct SplitRead {
  std::vector<Particle> particles;
  std::vector<std::string> errors;
  std::vector<std::size_t> share_sizes;
};

SplitRead read_split(const fs::path& path, int n) {
  testing::ThreadGroup group(n);
  std::vector<Packing> shares(static_cast<std::size_t>(n));
  std::vector<std::string> errors(static_cast<std::size_t>(n));
  std::vector<std::thread> ranks;
  for (int k = 0; k < n; ++k)
    ranks.emplace_back([&, k] {
      testing::ThreadGroup::Member me(group, k);
      try {
        shares[static_cast<std::size_t>(k)] = read_packing_share(path, {}, &me);
      } catch (const InputError& e) {
        errors[static_cast<std::size_t>(k)] = e.what();
      }
    });
  for (auto& t : ranks) t.join();
  SplitRead out;
  for (int k = 0; k < n; ++k) {
    const auto& s = shares[static_cast<std::size_t>(k)].particles;
    out.particles.insert(out.particles.end(), s.begin(), s.end());
    out.share_sizes.push_back(s.size());
  }
  out.errors = errors;
  return out;
}

void expect_same(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].centre, b[i].centre) << i;
    EXPECT_EQ(a[i].diameter, b[i].diameter) << i;
    EXPECT_EQ(a[i].axis, b[i].axis) << i;
    EXPECT_EQ(a[i].length, b[i].length) << i;
  }
}

std::string random_csv(int rows, bool rods, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-3, 3);
  std::ostringstream o;
  o.precision(17);
  o << "# generated\n" << (rods ? "x,y,z,ux,uy,uz,d,length,id\n" : "z, x ,y,diameter\n");
  for (int i = 0; i < rows; ++i) {
    if (i % 97 == 5) o << "\n# a comment\n";
    if (rods)
      o << U(rng) << "," << U(rng) << "," << U(rng) << "," << U(rng) << "," << U(rng) << ",1," << 0.5 + U(rng) / 10
        << "," << 1 + U(rng) / 6 << "," << i << "\r\n";
    else
      o << U(rng) << "," << U(rng) << ", " << U(rng) << "," << 0.5 + U(rng) / 10 << "\n";
  }
  return o.str();
}

TEST(porosity_PackingShare, CsvWholeAndSplitEqualTheLineReader) {
  for (const bool rods : {false, true}) {
    const std::string text = random_csv(rods ? 3000 : 120000, rods, 5);  // spheres: 5 MB, beyond one block
    const fs::path p = write_file(rods ? "rods.csv" : "spheres.csv", text);
    std::istringstream in(text);
    const Packing ref = read_packing_csv(in, p.string());
    const Packing whole = read_packing_share(p);
    EXPECT_EQ(whole.spherocylinders, rods);
    expect_same(whole.particles, ref.particles);
    for (int n : {2, 3, 5}) {
      const SplitRead s = read_split(p, n);
      for (const auto& e : s.errors) EXPECT_EQ(e, "");
      expect_same(s.particles, ref.particles);
    }
    fs::remove(p);
  }
}

TEST(porosity_PackingShare, LammpsLastSnapshotSplit) {
  std::ostringstream o;
  o.precision(17);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0, 1);
  for (int snap = 0; snap < 3; ++snap) {
    const int n = 500 + 300 * snap;
    o << "ITEM: TIMESTEP\n" << snap * 1000 << "\nITEM: NUMBER OF ATOMS\n" << n
      << "\nITEM: BOX BOUNDS pp pp pp\n-5 5\n-5 5\n0 " << 10 + snap << "\nITEM: ATOMS id type xs ys zs radius\n";
    for (int i = 0; i < n; ++i) o << i + 1 << " 1 " << U(rng) << " " << U(rng) << " " << U(rng) << " 0.25\n";
  }
  const fs::path p = write_file("dump.lammps", o.str());
  std::istringstream in(o.str());
  const Packing ref = read_lammps_dump(in, p.string());
  ASSERT_EQ(ref.particles.size(), 1100u);
  expect_same(read_packing_share(p).particles, ref.particles);
  for (int n : {2, 3, 4}) {
    const SplitRead s = read_split(p, n);
    for (const auto& e : s.errors) EXPECT_EQ(e, "");
    expect_same(s.particles, ref.particles);
    EXPECT_EQ(s.share_sizes[0], 0u) << "the first share holds only earlier snapshots";
  }
  fs::remove(p);
}

TEST(porosity_PackingShare, SharesWithoutRowsAndEmptyFile) {
  const fs::path tiny = write_file("tiny.csv", "x,y,z,d\n0,0,0,1\n");
  const SplitRead s = read_split(tiny, 5);
  ASSERT_EQ(s.particles.size(), 1u);
  for (const auto& e : s.errors) EXPECT_EQ(e, "");
  fs::remove(tiny);
  const fs::path empty = write_file("empty.csv", "");
  for (int n : {1, 3}) {
    const SplitRead e = read_split(empty, n);
    for (const auto& m : e.errors) EXPECT_NE(m.find("empty file"), std::string::npos) << m;
  }
  fs::remove(empty);
}

TEST(porosity_PackingShare, BadRowInTheMiddleNamesItsLineInEveryShare) {
  std::string text = random_csv(50000, false, 7);
  // Line numbers: 1 comment, 2 header, then rows with a blank and a comment line every 97 rows.
  std::istringstream probe(text);
  std::string line;
  long ln = 0, target = 0;
  std::size_t offset = 0, at = 0;
  while (std::getline(probe, line)) {
    ++ln;
    if (ln > 30000 && line.find(',') != std::string::npos && !target) {
      target = ln;
      at = offset;
    }
    offset += line.size() + 1;
  }
  const std::size_t eol = text.find('\n', at);
  text.replace(at, eol - at, "1.0,2.0,oops,0.5");
  const fs::path p = write_file("bad.csv", text);
  const std::string expected = p.string() + ":" + std::to_string(target) + ":";
  for (int n : {1, 2, 3}) {
    const SplitRead s = read_split(p, n);
    for (const auto& e : s.errors) {
      EXPECT_NE(e.find("1 bad row"), std::string::npos) << e;
      EXPECT_NE(e.find(expected), std::string::npos) << expected << " in " << e;
      EXPECT_NE(e.find("not a number: 'oops'"), std::string::npos) << e;
    }
    EXPECT_TRUE(s.particles.empty());
  }
  fs::remove(p);
}

}  // namespace
}  // namespace ssimarch
