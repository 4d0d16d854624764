// Fixed-chunk parallel loop with progress polling on the calling thread (internal to porosity).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/core/thread_pool.hpp"

namespace ssimarch::internal {

// 0: the library's thread count (core/thread_pool.hpp: `--threads`, every core by default).
inline unsigned worker_count(unsigned requested) { return requested > 0 ? requested : thread_count(); }

/// Runs body(chunk) for chunk = 0..chunks-1 on `threads` workers; `progress(fraction)` is called on the
/// calling thread while waiting. Exceptions from workers are rethrown; one from `progress` stops the
/// loop after the running chunks and is rethrown. After Ctrl-C (core/interrupt.hpp) the chunks not
/// yet begun are skipped and Interrupted is thrown once every worker has stopped.
inline void parallel_chunks(int chunks, unsigned threads, const std::function<void(int)>& body,
                            const std::function<void(double)>& progress) {
  std::atomic<int> next{0}, done{0};
  std::exception_ptr error;
  std::mutex error_mutex, done_mutex;
  std::condition_variable all_done;  // wakes the progress loop at the end, not at its next tick
  auto finish_one = [&] {
    if (done.fetch_add(1) + 1 == chunks) {
      std::lock_guard<std::mutex> lock(done_mutex);
      all_done.notify_all();
    }
  };
  auto worker = [&] {
    for (int k; (k = next.fetch_add(1)) < chunks;) {
      if (interrupt_requested()) {
        finish_one();
        continue;
      }
      try {
        body(k);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
      finish_one();
    }
  };
  const unsigned n = std::max(1u, std::min<unsigned>(worker_count(threads), static_cast<unsigned>(std::max(chunks, 1))));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < n; ++t) pool.emplace_back(worker);
  if (progress) {
    try {
      while (done.load() < chunks) {
        progress(static_cast<double>(done.load()) / std::max(chunks, 1));
        std::unique_lock<std::mutex> lock(done_mutex);
        all_done.wait_for(lock, std::chrono::milliseconds(100), [&] { return done.load() >= chunks; });
      }
      progress(1.0);
    } catch (...) {
      // A progress callback that throws cancels the loop (e.g. Ctrl-C in the Python module): no
      // new chunks start, the running ones finish, the exception goes to the caller.
      next.store(chunks);
      for (auto& t : pool) t.join();
      throw;
    }
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  throw_if_interrupted();
}

}  // namespace ssimarch::internal
