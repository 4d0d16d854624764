// Packing files: CSV with a header (spheres: x,y,z,d; spherocylinders: x,y,z,ux,uy,uz,d,l; the
// axis need not be unit length; units are the file's; an optional clump column, Packing::clumps)
// and LAMMPS/LIGGGHTS text dumps of spheres (ITEM: ATOMS with x y z (or xu yu zu, or scaled xs ys
// zs) and radius or diameter columns; the last snapshot in the file is used). Invalid input throws
// ssimarch::InputError (core/error.hpp) whose location is "file:line" (or "file:line:column" for a
// field that is not a number); bad rows are collected (up to ten reported) and thrown together
// with the file as location.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/porosity/particle.hpp"
#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch {

struct Packing {
  std::vector<Particle> particles;
  bool spherocylinders = false;  ///< the file had axis and length columns
  /// The particle each row belongs to, from a clump column (CSV `particle` or `clump`; LAMMPS dumps
  /// `mol`, `clump` or `id_multisphere`): rows with the same id are the spheres of one clumped
  /// particle (a LIGGGHTS multisphere body, a rigid molecule). Integers, one per row of
  /// `particles`; empty when the file has no such column (each row is a particle of its own).
  std::vector<long> clumps;
};

/// How many particles the packing holds: the distinct clump ids, or its rows when it has none.
long particle_count(const Packing& packing);
/// The number of distinct values among `ids`.
long distinct_count(std::span<const long> ids);
/// The number of distinct values among the ids that the processes of `comm` hold together (each
/// its own `ids`): each id is sent to one process chosen by its value, which counts the distinct
/// ones it receives. Collective.
long distinct_count(std::span<const long> ids, const ProfileCommunicator& comm);

/// Reads a CSV or a LAMMPS dump (recognised by a first line starting with "ITEM:"). A UTF-8 byte
/// order mark before the first line is skipped. A file larger than limits.max_packing_bytes or a
/// line longer than limits.max_line_bytes is an InputError (core/input_limits.hpp).
Packing read_packing(const std::filesystem::path& path, const InputLimits& limits = {}, unsigned threads = 0);
/// Streaming reader of a regular file (CSV or LAMMPS dump, the formats above): the file is read in
/// 4 MiB blocks, never held. With a communicator, this process reads only its share: the lines
/// whose first byte lies in the rank-th of size() equal byte ranges (of a LAMMPS dump, the rows of
/// the last snapshot there), and every process gets the same InputError (the first share's) for a
/// bad file; row errors name the file's line. Without one it reads the whole file. The shares'
/// particles, concatenated in rank order, are the file's in order. A share is read and parsed by
/// `threads` workers (0: the library's thread count) in pieces of at least 4 MiB.
Packing read_packing_share(const std::filesystem::path& path, const InputLimits& limits = {},
                           const ProfileCommunicator* comm = nullptr, unsigned threads = 0);
Packing read_packing_csv(std::istream& in, const std::string& name, const InputLimits& limits = {});
Packing read_lammps_dump(std::istream& in, const std::string& name, const InputLimits& limits = {});

/// Writes the CSV format (sphere columns when every particle has length 0).
void write_packing_csv(std::ostream& out, std::span<const Particle> particles);

}  // namespace ssimarch
