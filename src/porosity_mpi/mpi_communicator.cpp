// MPI_COMM_WORLD as a ProfileCommunicator (include/ssimarch/porosity_mpi/mpi_communicator.hpp).
#include "ssimarch/porosity_mpi/mpi_communicator.hpp"

#include <mpi.h>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace ssimarch {

namespace {

// Adds arrays of 128-bit two's complement integers stored as (low, high) word pairs; commutative
// and associative, so MPI may combine the ranks in any order without changing a bit.
void add_pairs(void* in, void* inout, int* len, MPI_Datatype*) {
  const auto* a = static_cast<const std::uint64_t*>(in);
  auto* b = static_cast<std::uint64_t*>(inout);
  for (int k = 0; k < *len; ++k) add_fixed_point_words(a + 2 * k, b + 2 * k);
}

}  // namespace

MpiCommunicator::MpiCommunicator(int* argc, char*** argv) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    // Worker threads compute, only the calling thread communicates.
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    finalize_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiCommunicator::~MpiCommunicator() {
  if (finalize_) MPI_Finalize();
}

void MpiCommunicator::sum(std::span<long> values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  bytes_sent_ += static_cast<long>(values.size_bytes());
}

void MpiCommunicator::sum(ProfileSums& s) const {
  // Solid and error totals as word pairs, then the four counts as pairs too (sign-extended).
  std::vector<std::uint64_t> words;
  words.reserve(4 * s.solid.size() + 8);
  for (const auto* vec : {&s.solid, &s.error})
    for (const FixedPointSum& f : *vec) {
      std::uint64_t w[2];
      f.words(w);
      words.insert(words.end(), w, w + 2);
    }
  for (long c : {s.evaluations, s.unconverged, s.particles_used, s.particles_clipped}) {
    words.push_back(static_cast<std::uint64_t>(c));
    words.push_back(c < 0 ? ~std::uint64_t{0} : 0);
  }
  MPI_Datatype pair;
  MPI_Type_contiguous(2, MPI_UINT64_T, &pair);
  MPI_Type_commit(&pair);
  MPI_Op op;
  MPI_Op_create(&add_pairs, 1, &op);
  MPI_Allreduce(MPI_IN_PLACE, words.data(), static_cast<int>(words.size() / 2), pair, op, MPI_COMM_WORLD);
  MPI_Op_free(&op);
  MPI_Type_free(&pair);
  bytes_sent_ += static_cast<long>(words.size() * sizeof(std::uint64_t));
  std::size_t k = 0;
  for (auto* vec : {&s.solid, &s.error})
    for (FixedPointSum& f : *vec) {
      f.set_words(&words[k]);
      k += 2;
    }
  for (long* c : {&s.evaluations, &s.unconverged, &s.particles_used, &s.particles_clipped}) {
    *c = static_cast<long>(words[k]);
    k += 2;
  }
}

void MpiCommunicator::min_max(double& lo, double& hi) const {
  double v[2] = {-lo, hi};  // max of -lo is -min of lo: one reduction
  MPI_Allreduce(MPI_IN_PLACE, v, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  lo = -v[0];
  hi = v[1];
  bytes_sent_ += sizeof v;
}

bool MpiCommunicator::any(bool flag) const {
  int v = flag ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
  bytes_sent_ += sizeof v;
  return v != 0;
}

long MpiCommunicator::exclusive_prefix_sum(long value) const {
  long out = 0;
  MPI_Exscan(&value, &out, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  bytes_sent_ += sizeof value;
  return rank_ == 0 ? 0 : out;  // MPI leaves rank 0's result undefined
}

long MpiCommunicator::max(long value) const {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD);
  bytes_sent_ += sizeof value;
  return value;
}

std::string MpiCommunicator::first_error(const std::string& message) const {
  int first = message.empty() ? size_ : rank_;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  bytes_sent_ += sizeof first;
  if (first == size_) return {};
  long n = static_cast<long>(message.size());
  MPI_Bcast(&n, 1, MPI_LONG, first, MPI_COMM_WORLD);
  std::string out = rank_ == first ? message : std::string(static_cast<std::size_t>(n), ' ');
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, first, MPI_COMM_WORLD);
  if (rank_ == first) bytes_sent_ += n;
  return out;
}

std::string MpiCommunicator::exchange(std::string bytes, const std::vector<std::size_t>& counts) const {
  // Counts first (MPI_Alltoall), then the bytes (MPI_Alltoallv: int counts and displacements, so
  // at most 2 GiB sent or received by one rank; more ranks split a larger bed).
  const auto n = static_cast<std::size_t>(size_);
  std::vector<int> send_counts(n), recv_counts(n), send_at(n), recv_at(n);
  constexpr std::size_t kMax = static_cast<std::size_t>(std::numeric_limits<int>::max());
  if (bytes.size() > kMax) throw std::length_error("MPI exchange of more than 2 GiB from one rank: run on more ranks");
  for (std::size_t k = 0, at = 0; k < n; at += counts[k], ++k) {
    send_counts[k] = static_cast<int>(counts[k]);
    send_at[k] = static_cast<int>(at);
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::size_t received = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (received > kMax) break;
    recv_at[k] = static_cast<int>(received);
    received += static_cast<std::size_t>(recv_counts[k]);
  }
  if (received > kMax) throw std::length_error("MPI exchange of more than 2 GiB to one rank: run on more ranks");
  std::string recv(received, '\0');
  MPI_Alltoallv(bytes.data(), send_counts.data(), send_at.data(), MPI_BYTE, recv.data(), recv_counts.data(),
                recv_at.data(), MPI_BYTE, MPI_COMM_WORLD);
  bytes_sent_ += static_cast<long>(bytes.size() + sizeof(int) * n);
  return recv;
}

bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace ssimarch
