// MPI for the porosity profiles (built with SSIMARCH_MPI=ON; docs/scaling.md): a
// ProfileCommunicator over MPI_COMM_WORLD. Sums of counts are MPI_Allreduce of longs; sums of
// profiles are MPI_Allreduce of FixedPointSum totals (128-bit integers as word pairs, added by a
// commutative user operation), so every rank gets the same bits for any number of ranks. This
// header does not include mpi.h.
#pragma once

#include <memory>

#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch {

class MpiCommunicator final : public ProfileCommunicator {
 public:
  /// Initialises MPI (unless it already is) and finalises it in the destructor when it did.
  MpiCommunicator(int* argc, char*** argv);
  ~MpiCommunicator() override;
  MpiCommunicator(const MpiCommunicator&) = delete;
  MpiCommunicator& operator=(const MpiCommunicator&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void sum(std::span<long> values) const override;
  void sum(ProfileSums& sums) const override;
  void min_max(double& lo, double& hi) const override;
  bool any(bool flag) const override;
  long exclusive_prefix_sum(long value) const override;
  long max(long value) const override;
  std::string first_error(const std::string& message) const override;
  std::string exchange(std::string bytes, const std::vector<std::size_t>& counts) const override;
  /// Bytes this rank has sent in reductions so far (the model of docs/scaling.md).
  long bytes_sent() const { return bytes_sent_; }

 private:
  int rank_ = 0, size_ = 1;
  bool finalize_ = false;
  mutable long bytes_sent_ = 0;
};

/// True when this process was started by mpirun/mpiexec (OpenMPI or PMIx environment variables):
/// the CLI initialises MPI only then, so that a plain run needs no MPI runtime.
bool launched_by_mpirun();

}  // namespace ssimarch
