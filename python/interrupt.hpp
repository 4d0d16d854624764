// Ctrl-C during a long library call from Python (docs/python.md, "Interrupting").
//
// Python runs its SIGINT handler only when the main thread executes bytecode, never while C++
// runs. So a long call runs on a worker thread with the GIL released while the calling thread
// polls PyErr_CheckSignals every kPollSeconds; on a signal it raises the stop flag, waits for the
// worker and raises the pending KeyboardInterrupt. The library stops early where it polls the flag:
// porosity jobs through their progress callback (pipeline/porosity_job.hpp), the module's own
// loops directly. Other calls (traces, the packing generator) run to their end and their result
// is discarded.
//
// The flag lives here until the library has a cancellation flag of its own (core/interrupt,
// issue 15/16); then stop_requested() and request_stop() forward to it.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <optional>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>

namespace ssimarch::python {

/// Seconds between two checks of Python's pending signals while a call runs.
inline constexpr double kPollSeconds = 0.02;

inline std::atomic<bool>& stop_flag() {
  static std::atomic<bool> flag{false};
  return flag;
}
inline bool stop_requested() { return stop_flag().load(std::memory_order_relaxed); }

/// Thrown by the module's loops and callbacks when the stop flag is up; never reaches Python
/// (run_interruptible raises the KeyboardInterrupt instead).
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

inline void throw_if_stop_requested() {
  if (stop_requested()) throw Interrupted();
}

/// Runs f() (no Python objects inside) on a worker thread, the GIL released, and returns its
/// value; Ctrl-C raises KeyboardInterrupt as soon as f returns or throws. Exceptions of f are
/// rethrown on the calling thread. Must be called with the GIL held.
template <class F>
auto run_interruptible(F&& f) -> std::invoke_result_t<F&> {
  using R = std::invoke_result_t<F&>;
  std::packaged_task<R()> task(std::forward<F>(f));
  std::future<R> result = task.get_future();
  bool interrupted = false;
  {
    pybind11::gil_scoped_release release;
    stop_flag().store(false);
    std::thread worker(std::move(task));
    const auto poll = std::chrono::duration<double>(kPollSeconds);
    while (result.wait_for(poll) != std::future_status::ready) {
      if (interrupted) continue;
      pybind11::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {  // the handler raised (KeyboardInterrupt): keep it pending
        interrupted = true;
        stop_flag().store(true);
      }
    }
    worker.join();
    stop_flag().store(false);
  }
  if (interrupted) throw pybind11::error_already_set();
  if constexpr (std::is_void_v<R>) {
    result.get();
  } else {
    return result.get();
  }
}

}  // namespace ssimarch::python
