// Ctrl-C during a long library call from Python (docs/python.md, "Interrupting").
//
// Python runs its SIGINT handler's Python part only when the main thread executes bytecode, never
// while C++ runs. So for the duration of a long call from the main thread, run_interruptible puts
// its own C handler in front of Python's: it raises the stop flag and chains to Python's handler,
// which records the signal as usual. The library stops early where it polls the flag (porosity
// jobs through their progress callback, pipeline/porosity_job.hpp; the module's own loops
// directly); other calls (a trace, the packing generator) run to their end. When the call
// returns, PyErr_CheckSignals runs Python's handler, which raises KeyboardInterrupt, and the
// result is discarded. No thread is started and nothing polls: the cost is two sigaction calls.
//
// The handler raises the library's cancellation flag (core/interrupt.hpp), checked by the
// library's long loops and the module's own; their Interrupted is caught here.
#pragma once

#include "ssimarch/core/interrupt.hpp"

#include <pybind11/pybind11.h>

#include <atomic>
#include <csignal>
#include <optional>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>

namespace ssimarch::python {

// The library's cancellation flag (core/interrupt.hpp) is the one flag: the module's own loops and
// callbacks check it with throw_if_interrupted, the library's long loops too.
// Async-signal-safe (a lock-free atomic store).
inline void request_stop() { request_interrupt(); }

// Lowers the flag; returns whether it was up.
inline bool clear_stop() {
  const bool was = interrupt_requested();
  clear_interrupt();
  return was;
}

/// The thread that imported the module (Python's main thread, which alone handles signals).
inline std::thread::id& main_thread() {
  static std::thread::id id;
  return id;
}

namespace internal {

inline struct sigaction& chained_sigint() {
  static struct sigaction previous {};
  return previous;
}

// Async-signal-safe: an atomic store and Python's own handler (which only records the signal).
inline void on_sigint(int sig, siginfo_t* info, void* context) {
  request_stop();
  const struct sigaction& p = chained_sigint();
  if (p.sa_flags & SA_SIGINFO) p.sa_sigaction(sig, info, context);
  else if (p.sa_handler != SIG_DFL && p.sa_handler != SIG_IGN) p.sa_handler(sig);
}

// on_sigint in front of the current SIGINT handler for one call; only on the main thread and only
// where Python (or the program) handles SIGINT with a function (SIG_DFL and SIG_IGN are kept).
class SigintScope {
 public:
  SigintScope() {
    struct sigaction current {};
    if (std::this_thread::get_id() != main_thread() || sigaction(SIGINT, nullptr, &current) != 0) return;
    if (!(current.sa_flags & SA_SIGINFO) && (current.sa_handler == SIG_DFL || current.sa_handler == SIG_IGN)) return;
    chained_sigint() = current;
    struct sigaction mine {};
    mine.sa_sigaction = &on_sigint;
    mine.sa_flags = SA_SIGINFO | (current.sa_flags & SA_ONSTACK);
    sigemptyset(&mine.sa_mask);
    installed_ = sigaction(SIGINT, &mine, nullptr) == 0;
  }
  ~SigintScope() {
    if (installed_) sigaction(SIGINT, &chained_sigint(), nullptr);
  }
  SigintScope(const SigintScope&) = delete;
  SigintScope& operator=(const SigintScope&) = delete;

 private:
  bool installed_ = false;
};

}  // namespace internal

/// Runs f() (no Python objects inside) with the GIL released and returns its value; after Ctrl-C
/// raises KeyboardInterrupt instead (once f returns, or throws at a poll of the flag).
/// Must be called with the GIL held.
template <class F>
auto run_interruptible(F&& f) -> std::invoke_result_t<F&> {
  using R = std::invoke_result_t<F&>;
  using Stored = std::conditional_t<std::is_void_v<R>, bool, std::optional<R>>;
  Stored result{};
  bool interrupted = false;
  clear_stop();
  {
    internal::SigintScope sigint;
    pybind11::gil_scoped_release release;
    try {
      if constexpr (std::is_void_v<R>) {
        f();
        result = true;
      } else {
        result.emplace(f());
      }
    } catch (const Interrupted&) {  // core/interrupt.hpp
    }
    interrupted = clear_stop();
  }
  if (interrupted) {
    // Python's handler recorded the signal: raise what it raises (KeyboardInterrupt by default).
    if (PyErr_CheckSignals() != 0 || !result) {
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
      throw pybind11::error_already_set();
    }
  }
  if constexpr (!std::is_void_v<R>) return std::move(*result);
}

}  // namespace ssimarch::python
