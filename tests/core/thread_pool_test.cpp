// The library's thread pool (core/thread_pool.hpp): every index once, the serial result whatever
// the thread count, nested loops, the exception of the lowest index.
#include "ssimarch/core/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace ssimarch {
namespace {

TEST(ThreadPool, RunsEveryIndexExactlyOnce) {
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.size(), threads);
    for (std::size_t n : {0u, 1u, 2u, 7u, 1000u}) {
      std::vector<std::atomic<int>> hits(n);
      pool.parallel_for(n, [&](std::size_t i) { hits[i].fetch_add(1); });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1) << "threads " << threads << ", n " << n << ", i " << i;
    }
  }
}

TEST(ThreadPool, SlotsGiveTheSerialResult) {
  // A loop whose bodies take different times: the slots hold the serial values in order.
  auto values = [](unsigned threads) {
    ThreadPool pool(threads);
    std::vector<double> out(200);
    pool.parallel_for(out.size(), [&](std::size_t i) {
      double s = 0;
      for (std::size_t k = 0; k < (i % 13) * 2000; ++k) s += std::sin(static_cast<double>(k + i));
      out[i] = s;
    });
    return out;
  };
  const std::vector<double> serial = values(1);
  EXPECT_EQ(values(2), serial);
  EXPECT_EQ(values(5), serial);
}

TEST(ThreadPool, NestedLoopsFinishAndUseMoreThanOneThread) {
  ThreadPool pool(4);
  std::vector<std::vector<int>> grid(16, std::vector<int>(16, 0));
  std::mutex m;
  std::set<std::thread::id> ids;
  pool.parallel_for(16, [&](std::size_t i) {
    pool.parallel_for(16, [&](std::size_t j) {
      grid[i][j] = static_cast<int>(i * 16 + j);
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      std::lock_guard<std::mutex> lock(m);
      ids.insert(std::this_thread::get_id());
    });
  });
  for (std::size_t i = 0; i < 16; ++i)
    for (std::size_t j = 0; j < 16; ++j) ASSERT_EQ(grid[i][j], static_cast<int>(i * 16 + j));
  EXPECT_GT(ids.size(), 1u);
  EXPECT_LE(ids.size(), 4u);
}

TEST(ThreadPool, RethrowsTheExceptionOfTheLowestIndexAfterTheOthersRan) {
  ThreadPool pool(3);
  std::atomic<int> ran{0};
  try {
    pool.parallel_for(50, [&](std::size_t i) {
      ran.fetch_add(1);
      if (i == 31 || i == 17 || i == 44) throw std::runtime_error("index " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "index 17");
  }
  EXPECT_EQ(ran.load(), 50);
}

TEST(ThreadPool, TheSharedPoolFollowsTheThreadCount) {
  set_thread_count(3);
  EXPECT_EQ(thread_count(), 3u);
  EXPECT_EQ(shared_thread_pool().size(), 3u);
  set_thread_count(1);
  EXPECT_EQ(shared_thread_pool().size(), 1u);
  set_thread_count(0);
  EXPECT_EQ(thread_count(), hardware_threads());
  std::vector<int> v(10, 0);
  parallel_for(v.size(), [&](std::size_t i) { v[i] = static_cast<int>(i); });
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], static_cast<int>(i));
}

}  // namespace
}  // namespace ssimarch
