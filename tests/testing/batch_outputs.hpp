// Fixtures of the trace and batch output tests (ssimarch::testing): the example scenes' folder,
// outputs without their wall times, JSON files read back. Shared by tests/pipeline/batch_job_test.cpp
// and the CLI tests (tests/cli/batch_cli_test.cpp, cli_test.cpp). SSIMARCH_SOURCE_DIR is the
// project's root, set for every test target by ssimarch_add_test.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace ssimarch::testing {

/// The folder of the example scenes, with a trailing '/'.
inline const std::string& examples_dir() {
  static const std::string dir = std::string(SSIMARCH_SOURCE_DIR) + "/examples/";
  return dir;
}

/// A trace or batch output without its "time_ms" fields, the only part that differs between runs.
inline nlohmann::json without_times(nlohmann::json j) {
  if (j.is_object()) {
    j.erase("time_ms");
    for (auto& [k, v] : j.items()) v = without_times(v);
  } else if (j.is_array()) {
    for (auto& v : j) v = without_times(v);
  }
  return j;
}

/// The JSON document in file `p`.
inline nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return nlohmann::json::parse(s.str());
}

}  // namespace ssimarch::testing
