// Budgets of a whole run, set by flags every file-reading subcommand has: how large an input file
// may be (--max-input-mb), how long the run may take (--time-limit) and how much memory it may
// use (--memory-limit). Exceeding the time or memory budget ends the run with a message and exit
// status 4, leaving earlier outputs untouched (io/output_files.hpp). docs/reliability.md.
#pragma once

#include <CLI/CLI.hpp>

#include "ssimarch/core/input_limits.hpp"

namespace ssimarch::cli {

/// Exit status of a run that exceeded its time or memory budget.
inline constexpr int kBudgetExitStatus = 4;
/// Exit status of a run stopped by Ctrl-C (128 + SIGINT, as shells report it).
inline constexpr int kInterruptedExitStatus = 130;

/// The input limits the flags set (the library's defaults otherwise).
const InputLimits& input_limits();
/// The memory budget in MiB, 0 when none was set (for the message of std::bad_alloc).
double memory_limit_mib();

/// Adds --max-input-mb, --time-limit and --memory-limit to `cmd`. The time limit starts counting
/// and the memory limit applies as soon as the flag is parsed, before any input is read.
void add_budget_options(CLI::App* cmd);

}  // namespace ssimarch::cli
