// Cooperative cancellation (Ctrl-C): one process-wide flag that a SIGINT handler sets and that long
// loops (porosity profiles, packing generation, the trace of several intersections, the certified
// start-point search) check between units of work. A loop that sees it throws Interrupted, which
// unwinds the whole job: a half-done profile or trace is never returned, so nothing half-done can
// be written (io/output_files.hpp writes only after a job returned). The one exception besides
// InputError and I/O errors, for the same reason as std::bad_alloc: no partial result is wanted.
#pragma once

#include <atomic>
#include <csignal>
#include <stdexcept>

namespace ssimarch {

/// Thrown by throw_if_interrupted() once the flag is set; what() is "interrupted".
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

namespace internal {
// Lock-free, hence safe to set from a signal handler (C++20 [support.signal]).
inline std::atomic<bool> g_interrupt_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" inline void on_interrupt_signal(int) {
  g_interrupt_requested.store(true, std::memory_order_relaxed);
  // A second Ctrl-C ends the process at once (the default action), for a loop that does not check.
  std::signal(SIGINT, SIG_DFL);
}
}  // namespace internal

/// Whether cancellation was requested (by SIGINT or request_interrupt()). One relaxed atomic load.
inline bool interrupt_requested() noexcept { return internal::g_interrupt_requested.load(std::memory_order_relaxed); }

/// Asks every checking loop to stop (for front ends other than a terminal: Python, a GUI, tests).
inline void request_interrupt() noexcept { internal::g_interrupt_requested.store(true, std::memory_order_relaxed); }

/// Clears the flag (before a new job in a long-lived process).
inline void clear_interrupt() noexcept { internal::g_interrupt_requested.store(false, std::memory_order_relaxed); }

/// Throws Interrupted when cancellation was requested.
inline void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted();
}

/// Makes SIGINT (Ctrl-C) set the flag instead of ending the process; a second SIGINT ends it.
/// Returns false when the handler could not be installed.
inline bool install_interrupt_handler() noexcept { return std::signal(SIGINT, internal::on_interrupt_signal) != SIG_ERR; }

}  // namespace ssimarch
