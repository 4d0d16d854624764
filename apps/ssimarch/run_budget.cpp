#include "run_budget.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "commands.hpp"
#include "ssimarch/io/output_files.hpp"

namespace ssimarch::cli {

namespace {

InputLimits g_limits;
double g_memory_mib = 0;

// Ends the process when the budget is spent: the run's temporaries are removed (no half-written
// output), the message names the flag, and the status is kBudgetExitStatus. A watchdog thread and
// _Exit rather than a check in every loop: the budget must also hold inside a long library call.
void start_watchdog(double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::thread([deadline, seconds] {
    std::this_thread::sleep_until(deadline);
    remove_pending_outputs();
    std::fprintf(stderr, "ssimarch: error: the run exceeded its time budget (--time-limit %g s); no output was written\n",
                 seconds);
    std::fflush(stderr);
    std::_Exit(kBudgetExitStatus);
  }).detach();
}

void limit_memory(double mib) {
  const rlim_t bytes = static_cast<rlim_t>(mib * 1024 * 1024);
  rlimit r{};
  if (getrlimit(RLIMIT_AS, &r) != 0) throw CliError("--memory-limit: the operating system's limit cannot be read");
  if (r.rlim_max != RLIM_INFINITY && bytes > r.rlim_max)
    throw CliError("--memory-limit: above the hard limit of this process (" + std::to_string(r.rlim_max >> 20) + " MiB)");
  r.rlim_cur = bytes;
  if (setrlimit(RLIMIT_AS, &r) != 0) throw CliError("--memory-limit: the operating system refused the limit");
}

}  // namespace

const InputLimits& input_limits() { return g_limits; }
double memory_limit_mib() { return g_memory_mib; }

void add_budget_options(CLI::App* cmd) {
  cmd->add_option_function<double>(
         "--max-input-mb",
         [](double mib) {
           if (!(mib >= 1 && mib <= 1024 * 1024))
             throw CliError("--max-input-mb: must be a number of MiB in [1, 1048576]");
           const auto bytes = static_cast<std::uint64_t>(mib * 1024 * 1024);
           g_limits.max_scene_bytes = bytes;
           g_limits.max_packing_bytes = bytes;
           g_limits.max_step_bytes = bytes;
         },
         "largest input file read, MiB (default 64 for scenes, 1024 for STEP files, 2048 for packings); guards against a wrong path "
         "such as /dev/zero")
      ->type_name("MIB");
  cmd->add_option_function<double>(
         "--time-limit",
         [](double s) {
           if (!(s > 0 && s <= 1e7)) throw CliError("--time-limit: must be a number of seconds in (0, 1e7]");
           start_watchdog(s);
         },
         "end the run with exit status 4 after this many seconds of wall-clock time (default: none)")
      ->type_name("SECONDS");
  cmd->add_option_function<double>(
         "--memory-limit",
         [](double mib) {
           // Below 64 MiB the program's own code and libraries do not fit (the address space counts them).
           if (!(mib >= 64 && mib <= 1e9)) throw CliError("--memory-limit: must be a number of MiB in [64, 1e9]");
           g_memory_mib = mib;
           limit_memory(mib);
         },
         "address space the run may use, MiB; exceeding it ends the run with exit status 4 (default: none)")
      ->type_name("MIB");
}

}  // namespace ssimarch::cli
