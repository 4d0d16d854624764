// The files a run has read, so that no output of the run replaces one of them (issue 29: `ssimarch
// trace s.json -o s.json` replaced the scene by its result). The readers note each file they open
// (io's read_text_file, the packing readers); io/output_files.hpp refuses a destination that is
// the same file as a noted one (the same inode: a hard link, a symbolic link or another spelling
// of the path counts too). Thread-safe.
#pragma once

#include <filesystem>
#include <mutex>
#include <optional>
#include <system_error>
#include <vector>

namespace ssimarch {

namespace internal {
struct InputFileRegistry {
  std::mutex mutex;
  std::vector<std::filesystem::path> paths;
};
inline InputFileRegistry& input_file_registry() {
  static InputFileRegistry r;
  return r;
}
}  // namespace internal

/// Records that this run reads `path`.
inline void note_input_file(const std::filesystem::path& path) {
  auto& r = internal::input_file_registry();
  std::lock_guard lock(r.mutex);
  r.paths.push_back(path);
}

/// The noted input that `destination` is the same file as, if any. A destination that does not
/// exist yet is no input; standard output ("-") never is.
inline std::optional<std::filesystem::path> input_file_at(const std::filesystem::path& destination) {
  std::error_code ec;
  if (destination == "-" || !std::filesystem::exists(destination, ec)) return std::nullopt;
  auto& r = internal::input_file_registry();
  std::lock_guard lock(r.mutex);
  for (const std::filesystem::path& p : r.paths)
    if (std::filesystem::equivalent(p, destination, ec) && !ec) return p;
  return std::nullopt;
}

}  // namespace ssimarch
