// The files a run has read (core/input_files.hpp; issue 29: an output must never replace an input):
// the same file under another spelling or through a link is found, another file or a file not yet
// there is not, and standard output never is.
#include "ssimarch/core/input_files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace ssimarch {
namespace {

namespace fs = std::filesystem;

TEST(InputFiles, AnInputIsFoundUnderEverySpellingOfItsPath) {
  const fs::path dir = fs::temp_directory_path() / ("ssimarch_input_files_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "scene.json") << "{}";
  std::ofstream(dir / "other.json") << "{}";
  note_input_file(dir / "scene.json");
  EXPECT_TRUE(input_file_at(dir / "scene.json"));
  EXPECT_TRUE(input_file_at(dir / "sub" / ".." / "scene.json"));
  fs::create_symlink(dir / "scene.json", dir / "link.json");
  EXPECT_TRUE(input_file_at(dir / "link.json"));
  fs::create_hard_link(dir / "scene.json", dir / "hard.json");
  EXPECT_TRUE(input_file_at(dir / "hard.json"));
  EXPECT_FALSE(input_file_at(dir / "other.json"));
  EXPECT_FALSE(input_file_at(dir / "not_yet.json"));
  EXPECT_FALSE(input_file_at("-"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ssimarch
