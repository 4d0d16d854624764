// All-or-nothing output (io/output_files.hpp): files appear only on commit, a failed run leaves
// the earlier files untouched and no temporaries behind, and a full device is an error.
#include "ssimarch/io/output_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace ssimarch {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path fresh_dir(const char* name) {
  const fs::path d = fs::temp_directory_path() / ("ssimarch_output_files_" + std::string(name));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(OutputFiles, FilesAppearOnlyOnCommit) {
  const fs::path d = fresh_dir("commit");
  OutputFiles files;
  files.open(d / "a.csv") << "new a\n";
  files.open(d / "b.csv") << "new b\n";
  EXPECT_FALSE(fs::exists(d / "a.csv"));
  files.commit();
  EXPECT_EQ(slurp(d / "a.csv"), "new a\n");
  EXPECT_EQ(slurp(d / "b.csv"), "new b\n");
  EXPECT_EQ(entries(d), 2u);  // no temporaries left
}

TEST(OutputFiles, AFailedRunLeavesTheEarlierFilesUntouched) {
  const fs::path d = fresh_dir("abort");
  std::ofstream(d / "a.csv") << "old a\n";
  try {
    OutputFiles files;
    files.open(d / "a.csv") << "new a\n";
    files.open(d / "missing_dir" / "b.csv");  // cannot be created: the run fails here
    FAIL() << "opening a file in a missing directory did not throw";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.csv"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(d / "a.csv"), "old a\n");
  EXPECT_EQ(entries(d), 1u);  // the temporary of a.csv is gone
}

TEST(OutputFiles, AFullDeviceIsAnError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  OutputFiles files;
  std::ostream& out = files.open("/dev/full");
  for (int i = 0; i < 100000; ++i) out << "0123456789";
  EXPECT_THROW(files.commit(), OutputError);
}

TEST(OutputFiles, PendingTemporariesCanBeRemovedByAWatchdog) {
  const fs::path d = fresh_dir("watchdog");
  OutputFiles files;
  files.open(d / "a.csv") << "partial";
  EXPECT_EQ(entries(d), 1u);
  remove_pending_outputs();
  EXPECT_EQ(entries(d), 0u);
}

}  // namespace
}  // namespace ssimarch
