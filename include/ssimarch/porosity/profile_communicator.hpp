// How the partial sums of a profile computed by several processes are combined (MPI porosity,
// docs/scaling.md). The porosity module holds no MPI code: a process computes the profiles of its
// share of the particles with ProfileOptions::communicator set, and the profile functions call it
// to add the particle counts (accuracy budget) and the partial sums over all processes. Sums are
// FixedPointSum totals, so the result has the same bits for any number of processes. The overlap
// search (overlaps.hpp) also exchanges particles between processes.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "ssimarch/porosity/fixed_point_sum.hpp"

namespace ssimarch {

/// Partial sums of one profile over a block of particles.
struct ProfileSums {
  std::vector<FixedPointSum> solid;  ///< per value: solid length^2 (radial, axial) or length^3 (bins)
  std::vector<FixedPointSum> error;  ///< per value: estimated quadrature error, same units
  long evaluations = 0, unconverged = 0, particles_used = 0, particles_clipped = 0;

  ProfileSums& operator+=(const ProfileSums& o) {
    for (std::size_t j = 0; j < solid.size(); ++j) {
      solid[j] += o.solid[j];
      error[j] += o.error[j];
    }
    evaluations += o.evaluations;
    unconverged += o.unconverged;
    particles_used += o.particles_used;
    particles_clipped += o.particles_clipped;
    return *this;
  }
};

class ProfileCommunicator {
 public:
  virtual ~ProfileCommunicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Element-wise sums over all processes; every process gets the totals.
  virtual void sum(std::span<long> values) const = 0;
  virtual void sum(ProfileSums& sums) const = 0;
  /// Smallest `lo` and largest `hi` over all processes, on every process.
  virtual void min_max(double& lo, double& hi) const = 0;
  /// True on every process when `flag` is true on one.
  virtual bool any(bool flag) const = 0;
  /// Sum of `value` over the processes below this one (0 on the first).
  virtual long exclusive_prefix_sum(long value) const = 0;
  /// Largest `value` over all processes, on every process.
  virtual long max(long value) const = 0;
  /// The non-empty `message` of the lowest process that has one ("" when none has), on every
  /// process: an input error found by one process's share is reported by all of them.
  virtual std::string first_error(const std::string& message) const = 0;
  /// All-to-all exchange of bytes: `bytes` holds the messages to processes 0, 1, ... one after the
  /// other, `counts[k]` bytes for process k (counts.size() == size()); returns what the processes
  /// sent to this one, concatenated in process order (taken by value: the caller's buffer is moved
  /// in, not copied). The overlap search moves particles with it.
  virtual std::string exchange(std::string bytes, const std::vector<std::size_t>& counts) const = 0;
};

}  // namespace ssimarch
