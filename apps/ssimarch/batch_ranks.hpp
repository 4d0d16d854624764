// How `ssimarch batch` shares its units between processes. One process: an atomic counter. Under
// mpirun, in a build with SSIMARCH_MPI=ON (batch_mpi.cpp): a counter in a window on rank 0 that
// every thread of every rank advances with MPI_Fetch_and_op (self-scheduling, one unit at a time:
// pair costs differ by orders of magnitude, so only dynamic assignment balances them), then the
// units' JSON texts gathered on rank 0, which writes the one merged output (docs/scaling.md).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ssimarch::cli {

/// One unit's result: its JSON text, which rank ran it, and its cost (wall and thread CPU time).
struct UnitResult {
  std::size_t unit = 0;
  int rank = 0;
  double wall_s = 0;
  double cpu_s = 0;
  std::string text;
};

/// What one rank did: units run, the sums of their wall and CPU times, and when its threads ran
/// out of units (seconds from the start of the distribution).
struct RankLoad {
  double units = 0;
  double busy_s = 0;
  double cpu_s = 0;
  double finish_s = 0;
};

class BatchRanks {
 public:
  virtual ~BatchRanks() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Threads per rank when --threads is not given: the cores of the node shared by its ranks.
  virtual unsigned default_threads() const = 0;
  /// The next unit number (>= the unit count when none is left); thread-safe.
  virtual std::size_t next() = 0;
  /// Every unit's result in unit order and every rank's load, on rank 0; empty vectors
  /// elsewhere. `local` holds the units this rank ran.
  virtual std::pair<std::vector<UnitResult>, std::vector<RankLoad>> gather(std::vector<UnitResult> local, std::size_t units,
                                                                           const RankLoad& load) = 0;
  /// Rank 0's exit status, on every rank.
  virtual int share_status(int status) = 0;
  /// Ends every rank with `status` (rank 0 could not write the output).
  [[noreturn]] virtual void abort(int status) = 0;
};

/// MPI ranks when this build has MPI and the process was started by mpirun, else one process.
/// Throws CliError when started by mpirun with several ranks in a build without MPI.
std::unique_ptr<BatchRanks> start_batch_ranks();

}  // namespace ssimarch::cli
