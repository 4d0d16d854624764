// A whole input file as text, within the run's size limit (core/input_limits.hpp), noted as an
// input of the run (core/input_files.hpp). The one reader of scene, batch, STEP and result files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/input_files.hpp"
#include "ssimarch/core/input_limits.hpp"

namespace ssimarch {

/// The whole file as text. Throws InputError(path, ...) when it is missing, a directory
/// ("is a directory, not a <what>"), a device or socket, unreadable, empty (white space only) or
/// longer than max_bytes (read in pieces, so that a pipe stops there too).
inline std::string read_text_file(const std::filesystem::path& path, std::string_view what,
                                  std::uint64_t max_bytes = InputLimits{}.max_scene_bytes) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), "no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path.string(), "is a directory, not a " + std::string(what));
  // A device (/dev/zero, /dev/urandom, a terminal) is refused before a byte is read (issue 29: a
  // STEP surface pointing at /dev/zero read 1 GiB first); a pipe is read, up to the size limit.
  if (std::filesystem::is_character_file(path, ec) || std::filesystem::is_block_file(path, ec) ||
      std::filesystem::is_socket(path, ec))
    throw InputError(path.string(),
                     "is a device or socket, not a " + std::string(what) + ": give a regular file (or a pipe)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot be opened for reading");
  note_input_file(path);
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      throw InputError(path.string(), "larger than " + byte_count_text(max_bytes) + ", the limit for a " +
                                          std::string(what) +
                                          " (is it the right file? --max-input-mb raises the limit)");
  }
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(path.string(), "the file is empty");
  return text;
}

}  // namespace ssimarch
