// Running the ssimarch binary as a user does, for the CLI tests (ssimarch::testing). The binary's
// path comes from SSIMARCH_CLI, set by ssimarch_test_needs_cli() in tests/testing/CMakeLists.txt;
// a missing binary is a test failure, never a skip.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#ifndef SSIMARCH_CLI
#error "SSIMARCH_CLI (the ssimarch binary) is not defined: call ssimarch_test_needs_cli(<test>) in CMake"
#endif

namespace ssimarch::testing {

struct CliRun {
  int status = -1;  ///< exit status, -1 if the process did not exit normally
  std::string out, err;
  std::string all() const { return out + err; }
};

/// A scratch directory private to this test process, created on first use.
inline std::filesystem::path cli_scratch_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("ssimarch_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// Writes `text` to the file `name` in the scratch directory; returns its path.
inline std::string write_scratch_file(const std::string& name, const std::string& text) {
  const std::filesystem::path p = cli_scratch_dir() / name;
  std::ofstream(p) << text;
  return p.string();
}

/// Runs `ssimarch <args>` through the shell; stdout and stderr are captured separately.
inline CliRun run_cli(const std::string& args) {
  const std::filesystem::path bin(SSIMARCH_CLI);
  CliRun r;
  if (!std::filesystem::exists(bin)) {
    ADD_FAILURE() << "the ssimarch CLI is not built: " << bin << " (build the ssimarch_cli target)";
    return r;
  }
  const std::filesystem::path err = cli_scratch_dir() / "stderr.txt";
  const std::string cmd = bin.string() + " " + args + " 2>" + err.string();
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    ADD_FAILURE() << "cannot run " << cmd;
    return r;
  }
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  r.err = ss.str();
  return r;
}

}  // namespace ssimarch::testing
