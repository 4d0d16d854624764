// The library's one pool of worker threads (issue 17 item 1): a trace of several intersections,
// the certified start-point search of one, a batch of pairs and the porosity profiles all share
// it, so nested parallel loops never multiply threads beyond the count the user set
// (`--threads`, set_thread_count). parallel_for(n, body) runs body(0..n-1); the calling thread
// works too, so a parallel_for inside a parallel_for cannot deadlock: every index a thread waits
// for is being run by a thread that is not waiting on it. Results go to slots indexed by i, so
// the output of a loop is the serial loop's, whatever the scheduling.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace ssimarch {

/// The cores of this machine (std::thread::hardware_concurrency, at least 1).
inline unsigned hardware_threads() {
  const unsigned h = std::thread::hardware_concurrency();
  return h == 0 ? 1 : h;
}

/// A fixed set of threads that run the indices of parallel loops. size() threads take part in
/// a loop: size() - 1 workers and the caller.
class ThreadPool {
 public:
  /// `threads` = 0: hardware_threads().
  explicit ThreadPool(unsigned threads) {
    const unsigned n = threads == 0 ? hardware_threads() : threads;
    for (unsigned i = 1; i < n; ++i) workers_.emplace_back([this] { work(); });
  }
  ~ThreadPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
  }
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// body(i) for i = 0..n-1, in any order and on any of the pool's threads; returns when all
  /// are done. When bodies throw, the exception of the lowest such index is rethrown (the one
  /// a serial loop would have met first); the other indices still run.
  template <class Body>
  void parallel_for(std::size_t n, Body&& body) {
    if (n == 0) return;
    if (workers_.empty() || n == 1) {
      for (std::size_t i = 0; i < n; ++i) body(i);
      return;
    }
    auto loop = std::make_shared<Loop>();
    loop->n = n;
    // Helpers that start after the loop ended claim no index, so they never touch `body`.
    auto run = [loop, &body] {
      for (std::size_t i; (i = loop->next.fetch_add(1)) < loop->n;) {
        try {
          body(i);
        } catch (...) {
          std::lock_guard<std::mutex> lock(loop->mutex);
          if (i < loop->error_index) {
            loop->error_index = i;
            loop->error = std::current_exception();
          }
        }
        if (loop->done.fetch_add(1) + 1 == loop->n) {
          std::lock_guard<std::mutex> lock(loop->mutex);
          loop->finished.notify_all();
        }
      }
    };
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const std::size_t helpers = std::min<std::size_t>(workers_.size(), n - 1);
      for (std::size_t k = 0; k < helpers; ++k) queue_.emplace_back(run);
    }
    wake_.notify_all();
    run();
    std::unique_lock<std::mutex> lock(loop->mutex);
    loop->finished.wait(lock, [&] { return loop->done.load() == loop->n; });
    if (loop->error) std::rethrow_exception(loop->error);
  }

 private:
  struct Loop {
    std::size_t n = 0;
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};
    std::mutex mutex;
    std::condition_variable finished;
    std::exception_ptr error;
    std::size_t error_index = std::numeric_limits<std::size_t>::max();
  };

  void work() {
    for (;;) {
      std::function<void()> task;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, nothing left
        task = std::move(queue_.front());
        queue_.pop_front();
      }
      task();
    }
  }

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> queue_;
  bool stopping_ = false;
};

namespace internal {

struct SharedPool {
  std::mutex mutex;
  unsigned threads = 0;  // 0: hardware_threads()
  std::unique_ptr<ThreadPool> pool;
};

inline SharedPool& shared_pool_state() {
  static SharedPool state;
  return state;
}

}  // namespace internal

/// Sets how many threads the library's loops use (0: every core, the default). Call it before
/// the work starts (the CLI does for `--threads`), not while a loop runs.
inline void set_thread_count(unsigned threads) {
  internal::SharedPool& s = internal::shared_pool_state();
  std::lock_guard<std::mutex> lock(s.mutex);
  const unsigned n = threads == 0 ? hardware_threads() : threads;
  if (s.pool && s.pool->size() != n) s.pool.reset();
  s.threads = threads;
}

/// The count set_thread_count asked for, resolved (at least 1).
inline unsigned thread_count() {
  internal::SharedPool& s = internal::shared_pool_state();
  std::lock_guard<std::mutex> lock(s.mutex);
  return s.threads == 0 ? hardware_threads() : s.threads;
}

/// The pool of the whole library, started on first use with thread_count() threads.
inline ThreadPool& shared_thread_pool() {
  internal::SharedPool& s = internal::shared_pool_state();
  std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.pool) s.pool = std::make_unique<ThreadPool>(s.threads);
  return *s.pool;
}

/// body(i) for i = 0..n-1 on the shared pool (ThreadPool::parallel_for).
template <class Body>
void parallel_for(std::size_t n, Body&& body) {
  shared_thread_pool().parallel_for(n, std::forward<Body>(body));
}

}  // namespace ssimarch
