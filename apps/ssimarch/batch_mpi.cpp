// The MPI side of `ssimarch batch` (built with SSIMARCH_MPI=ON; batch_ranks.hpp). Units are
// handed out by a shared counter on rank 0 advanced with MPI_Fetch_and_op under a passive-target
// epoch (MPI-3 one-sided atomics, MPI standard 3.1 §11.3.4): no rank waits on a master loop, and
// on one node the window is shared memory (OpenMPI's osc/sm), so taking a unit costs an atomic
// add. The threads of a rank serialize their MPI calls (MPI_THREAD_SERIALIZED). At the end every
// rank's (unit, JSON text) pairs are gathered on rank 0 (MPI_Gatherv), which merges them in unit
// order: the output is the same for any rank and thread count.
#include <mpi.h>

#include <cstdint>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <limits>
#include <mutex>

#include "batch_ranks.hpp"
#include "commands.hpp"
#include "ssimarch/core/thread_pool.hpp"

namespace ssimarch::cli {

namespace {

// A rank's results as bytes: per unit its number, rank, wall and CPU seconds, text length, text.
template <class T>
void put(std::string* out, T v) {
  out->append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
T get(const std::string& in, std::size_t* at) {
  T v;
  std::memcpy(&v, in.data() + *at, sizeof v);
  *at += sizeof v;
  return v;
}

std::string serialize(const std::vector<UnitResult>& local) {
  std::string bytes;
  for (const UnitResult& r : local) {
    put<std::uint64_t>(&bytes, r.unit);
    put<std::int32_t>(&bytes, r.rank);
    put<double>(&bytes, r.wall_s);
    put<double>(&bytes, r.cpu_s);
    put<std::uint64_t>(&bytes, r.text.size());
    bytes += r.text;
  }
  return bytes;
}

std::vector<UnitResult> deserialize(const std::string& bytes, std::size_t units) {
  std::vector<UnitResult> all(units);
  for (std::size_t at = 0; at < bytes.size();) {
    UnitResult r;
    r.unit = get<std::uint64_t>(bytes, &at);
    r.rank = get<std::int32_t>(bytes, &at);
    r.wall_s = get<double>(bytes, &at);
    r.cpu_s = get<double>(bytes, &at);
    const auto n = get<std::uint64_t>(bytes, &at);
    r.text.assign(bytes, at, n);
    at += n;
    all.at(r.unit) = std::move(r);
  }
  return all;
}

class MpiRanks final : public BatchRanks {
 public:
  MpiRanks() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    if (provided < MPI_THREAD_SERIALIZED) {
      MPI_Finalize();
      throw CliError("batch: the MPI library does not provide MPI_THREAD_SERIALIZED");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    MPI_Comm_size(node, &node_ranks_);
    MPI_Comm_free(&node);
    const MPI_Aint bytes = rank_ == 0 ? static_cast<MPI_Aint>(sizeof(std::uint64_t)) : 0;
    MPI_Win_allocate(bytes, sizeof(std::uint64_t), MPI_INFO_NULL, MPI_COMM_WORLD, &counter_memory_, &window_);
    if (rank_ == 0) {  // local stores to window memory inside an exclusive epoch (MPI 3.1 §11.7)
      MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window_);
      *counter_memory_ = 0;
      MPI_Win_unlock(0, window_);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Win_lock_all(0, window_);
  }
  ~MpiRanks() override {
    close_window();
    MPI_Finalize();
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  unsigned default_threads() const override {
    return std::max(1u, hardware_threads() / static_cast<unsigned>(std::max(1, node_ranks_)));
  }

  std::size_t next() override {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::uint64_t one = 1;
    std::uint64_t got = 0;
    MPI_Fetch_and_op(&one, &got, MPI_UINT64_T, 0, 0, MPI_SUM, window_);
    MPI_Win_flush(0, window_);
    return static_cast<std::size_t>(got);
  }

  std::pair<std::vector<UnitResult>, std::vector<RankLoad>> gather(std::vector<UnitResult> local, std::size_t units,
                                                                   const RankLoad& load) override {
    close_window();
    const std::string bytes = serialize(local);
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw CliError("batch: rank " + std::to_string(rank_) + "'s results exceed 2 GiB (MPI_Gatherv counts are int)");
    const int count = static_cast<int>(bytes.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank_ == 0) {
      long long total = 0;
      for (int r = 0; r < size_; ++r) {
        offsets[static_cast<std::size_t>(r)] = static_cast<int>(total);
        total += counts[static_cast<std::size_t>(r)];
        if (total > std::numeric_limits<int>::max()) throw CliError("batch: the gathered results exceed 2 GiB");
      }
      all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(bytes.data(), count, MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
    const double mine[4] = {load.units, load.busy_s, load.cpu_s, load.finish_s};
    std::vector<double> loads(4 * static_cast<std::size_t>(size_));
    MPI_Gather(mine, 4, MPI_DOUBLE, loads.data(), 4, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (rank_ != 0) return {};
    std::vector<RankLoad> per_rank;
    for (std::size_t r = 0; r < static_cast<std::size_t>(size_); ++r)
      per_rank.push_back({loads[4 * r], loads[4 * r + 1], loads[4 * r + 2], loads[4 * r + 3]});
    return {deserialize(all, units), std::move(per_rank)};
  }

  int share_status(int status) override {
    MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return status;
  }
  [[noreturn]] void abort(int status) override {
    MPI_Abort(MPI_COMM_WORLD, status);
    std::exit(status);
  }

 private:
  void close_window() {
    if (window_ == MPI_WIN_NULL) return;
    MPI_Win_unlock_all(window_);
    MPI_Win_free(&window_);  // collective: every rank has taken its last unit
  }

  int rank_ = 0, size_ = 1, node_ranks_ = 1;
  std::uint64_t* counter_memory_ = nullptr;
  MPI_Win window_ = MPI_WIN_NULL;
  std::mutex mutex_;
};

}  // namespace

std::unique_ptr<BatchRanks> mpi_batch_ranks() {
  return std::make_unique<MpiRanks>();
}

}  // namespace ssimarch::cli
