#include "batch_ranks.hpp"

#include <atomic>
#include <cstdlib>
#include <string>

#include "commands.hpp"
#include "ssimarch/core/thread_pool.hpp"

namespace ssimarch::cli {

#ifdef SSIMARCH_WITH_MPI
std::unique_ptr<BatchRanks> mpi_batch_ranks();  // batch_mpi.cpp
#endif

namespace {

class OneProcess final : public BatchRanks {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  unsigned default_threads() const override { return hardware_threads(); }
  std::size_t next() override { return next_.fetch_add(1); }
  std::pair<std::vector<UnitResult>, std::vector<RankLoad>> gather(std::vector<UnitResult> local, std::size_t units,
                                                                   const RankLoad& load) override {
    std::vector<UnitResult> all(units);
    for (UnitResult& r : local) all.at(r.unit) = std::move(r);
    return {std::move(all), {load}};
  }
  int share_status(int status) override { return status; }
  [[noreturn]] void abort(int status) override { std::exit(status); }

 private:
  std::atomic<std::size_t> next_{0};
};

// The rank count mpirun (OpenMPI, or a PMI launcher such as MPICH's hydra) gave this process.
int launcher_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::atoi(v);
  return 0;
}

}  // namespace

std::unique_ptr<BatchRanks> start_batch_ranks() {
  const int ranks = launcher_ranks();
#ifdef SSIMARCH_WITH_MPI
  if (ranks > 0) return mpi_batch_ranks();
#else
  if (ranks > 1)
    throw CliError("batch: started by mpirun with " + std::to_string(ranks) +
                   " ranks, but this ssimarch was built without MPI (cmake -DSSIMARCH_MPI=ON; docs/scaling.md)");
#endif
  return std::make_unique<OneProcess>();
}

}  // namespace ssimarch::cli
