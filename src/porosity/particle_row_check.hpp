// The check of one particle row shared by the packing readers (packing_io.cpp: the stream readers;
// packing_share.cpp: the block reader of a rank's share), so both give the same messages.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <string_view>

#include "ssimarch/porosity/packing.hpp"

namespace ssimarch::internal {

/// Row errors listed in one message; the others are counted ("... and N more").
inline constexpr int kMaxReportedRows = 10;

/// Validates one particle read from a row (sc: a spherocylinder row, whose axis it normalises);
/// returns an empty string when fine, else the reason.
/// The error of a row with more (non-empty) fields than the header or ATOMS line names (issue 29: a
/// shifted id column was read as coordinates), the same in every reader.
inline std::string more_fields_than_columns(std::size_t columns, std::size_t found) {
  return "expected " + std::to_string(columns) + " fields (the header's columns), found " + std::to_string(found) +
         ": a row with more fields than the header has its columns shifted";
}

inline std::string validate_particle(Particle& p, bool sc) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(p.centre[k])) return "centre coordinate is not finite";
  if (!std::isfinite(p.diameter)) return "diameter is not finite";
  if (!(p.diameter > 0)) return "diameter must be > 0 (got " + std::to_string(p.diameter) + ")";
  if (sc) {
    if (!std::isfinite(p.length)) return "length is not finite";
    if (p.length < 0) return "length must be >= 0 (got " + std::to_string(p.length) + ")";
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(p.axis[k])) return "axis component is not finite";
    const double n = p.axis.norm();
    if (!(n > 0)) return "axis (ux, uy, uz) must not be zero";
    p.axis /= n;
  }
  return {};
}

/// The names of the clump column (Packing::clumps): a CSV header's (compared in lower case) and a
/// LAMMPS dump's ATOMS columns (LAMMPS writes a molecule's id as `mol`, LIGGGHTS a multisphere
/// body's as `id_multisphere`).
inline constexpr std::array<std::string_view, 2> kCsvClumpColumns = {"particle", "clump"};
inline constexpr std::array<std::string_view, 3> kDumpClumpColumns = {"mol", "clump", "id_multisphere"};

/// Empty when `v`, read from the clump column, is a particle id (an integer of at most 2^53 in
/// magnitude, exact in a double), else the reason.
inline std::string validate_clump(double v) {
  if (!(std::abs(v) <= 9007199254740992.0) || v != std::floor(v))
    return "the clump id must be an integer of at most 2^53 in magnitude (got " + std::to_string(v) + ")";
  return {};
}

}  // namespace ssimarch::internal
