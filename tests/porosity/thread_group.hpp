// In-process stand-in for MPI ranks in tests: one thread per rank, every collective an all-gather
// of byte strings between barriers, then combined in rank order (the MPI build's tests run the
// real thing under mpirun, tests/porosity/mpi_porosity_test.cmake).
#pragma once

#include <barrier>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch::testing {

class ThreadGroup {
 public:
  explicit ThreadGroup(int n) : n_(n), slots_(static_cast<std::size_t>(n)), sync_(n) {}

  class Member final : public ProfileCommunicator {
   public:
    Member(ThreadGroup& g, int rank) : g_(g), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return g_.n_; }
    void sum(std::span<long> v) const override {
      const auto all = gather_values<long>(std::vector<long>(v.begin(), v.end()));
      for (std::size_t k = 0; k < v.size(); ++k) {
        v[k] = 0;
        for (const auto& r : all) v[k] += r[k];
      }
    }
    void sum(ProfileSums& s) const override {
      std::vector<std::uint64_t> words;
      for (auto* vec : {&s.solid, &s.error})
        for (const auto& f : *vec) {
          std::uint64_t w[2];
          f.words(w);
          words.insert(words.end(), w, w + 2);
        }
      const auto all = gather_values<std::uint64_t>(words);
      std::vector<std::uint64_t> total(words.size(), 0);
      for (const auto& r : all)
        for (std::size_t k = 0; k < total.size(); k += 2) add_fixed_point_words(&r[k], &total[k]);
      std::size_t k = 0;
      for (auto* vec : {&s.solid, &s.error})
        for (auto& f : *vec) {
          f.set_words(&total[k]);
          k += 2;
        }
      std::vector<long> counts{s.evaluations, s.unconverged, s.particles_used, s.particles_clipped};
      sum(counts);
      s.evaluations = counts[0];
      s.unconverged = counts[1];
      s.particles_used = counts[2];
      s.particles_clipped = counts[3];
    }
    void min_max(double& lo, double& hi) const override {
      const auto all = gather_values<double>({lo, hi});
      for (const auto& r : all) {
        lo = std::min(lo, r[0]);
        hi = std::max(hi, r[1]);
      }
    }
    bool any(bool flag) const override {
      bool out = false;
      for (const auto& r : gather_values<long>({flag ? 1L : 0L})) out = out || r[0] != 0;
      return out;
    }
    long exclusive_prefix_sum(long value) const override {
      const auto all = gather_values<long>({value});
      long out = 0;
      for (int k = 0; k < rank_; ++k) out += all[static_cast<std::size_t>(k)][0];
      return out;
    }
    long max(long value) const override {
      for (const auto& r : gather_values<long>({value})) value = std::max(value, r[0]);
      return value;
    }
    std::string first_error(const std::string& message) const override {
      for (const std::string& m : g_.gather(rank_, message))
        if (!m.empty()) return m;
      return {};
    }

    std::string exchange(std::string bytes, const std::vector<std::size_t>& counts) const override {
      // Every member posts all its messages with their counts; member k keeps the k-th of each.
      std::string packed;
      for (std::size_t c : counts) {
        const std::uint64_t n = c;
        packed.append(reinterpret_cast<const char*>(&n), sizeof n);
      }
      packed += bytes;
      std::string out;
      for (const std::string& all : g_.gather(rank_, packed)) {
        std::size_t at = sizeof(std::uint64_t) * static_cast<std::size_t>(g_.n_), from = at, mine = 0;
        for (int k = 0; k < g_.n_; ++k) {
          std::uint64_t n = 0;
          std::memcpy(&n, all.data() + sizeof n * static_cast<std::size_t>(k), sizeof n);
          if (k == rank_) from = at, mine = n;
          at += n;
        }
        out.append(all, from, mine);
      }
      return out;
    }

   private:
    template <class T>
    std::vector<std::vector<T>> gather_values(const std::vector<T>& mine) const {
      std::string bytes(mine.size() * sizeof(T), '\0');
      if (!mine.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
      std::vector<std::vector<T>> out;
      for (const std::string& b : g_.gather(rank_, bytes)) {
        std::vector<T> v(b.size() / sizeof(T));
        if (!v.empty()) std::memcpy(v.data(), b.data(), b.size());
        out.push_back(std::move(v));
      }
      return out;
    }
    ThreadGroup& g_;
    int rank_;
  };

 private:
  std::vector<std::string> gather(int rank, const std::string& mine) {
    slots_[static_cast<std::size_t>(rank)] = mine;
    sync_.arrive_and_wait();
    std::vector<std::string> all = slots_;
    sync_.arrive_and_wait();
    return all;
  }
  int n_;
  std::vector<std::string> slots_;
  std::barrier<> sync_;
};

/// Runs f(communicator, rank) on n in-process ranks, a thread each, and waits for all of them.
template <class F>
void run_on_ranks(int n, F&& f) {
  ThreadGroup group(n);
  std::vector<std::thread> ranks;
  for (int k = 0; k < n; ++k)
    ranks.emplace_back([&, k] {
      ThreadGroup::Member me(group, k);
      f(me, k);
    });
  for (auto& t : ranks) t.join();
}

}  // namespace ssimarch::testing
