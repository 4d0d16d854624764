// How much an input reader reads before it stops with an InputError, so that a wrong path
// (/dev/zero, a disk image, a binary) ends in a message instead of exhausting memory. The limits
// are far above any real input; a user with a larger one raises them (`--max-input-mb`,
// docs/reliability.md).
#pragma once

#include <cstdint>
#include <string>

namespace ssimarch {

struct InputLimits {
  /// Largest scene or surface file (JSON), bytes. Scenes are kilobytes; a large B-spline net megabytes.
  std::uint64_t max_scene_bytes = std::uint64_t{64} << 20;
  /// Largest packing file (CSV or LAMMPS dump), bytes: about 25 million particles.
  std::uint64_t max_packing_bytes = std::uint64_t{2} << 30;
  /// Largest STEP file (ISO 10303-21), bytes: CAD assemblies reach hundreds of MiB.
  std::uint64_t max_step_bytes = std::uint64_t{1} << 30;
  /// Longest line of a packing file, bytes (a row of 8 numbers is under 200).
  std::uint64_t max_line_bytes = std::uint64_t{1} << 16;
};

/// "64 MiB", "2 GiB": a byte count as a message states it.
inline std::string byte_count_text(std::uint64_t n) {
  const char* unit[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int k = 0;
  while (k < 4 && n >= 1024 && n % 1024 == 0) n /= 1024, ++k;
  return std::to_string(n) + " " + unit[k];
}

}  // namespace ssimarch
