// Subcommands of the ssimarch tool. Each add_*_command registers one subcommand with its options and
// help text, and its run with `Commands`. A run returns the process's exit status (0, or 1 when it
// ran but reported a failure) and throws ssimarch::CliError (or any std::exception) for bad input;
// main() parses, runs the subcommand the user named and returns its status, or prints the
// message to stderr and exits with the error's code.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ssimarch::cli {

/// An error the user can fix (bad file, bad option). `exit_code` is the process exit status.
class CliError : public std::runtime_error {
 public:
  explicit CliError(const std::string& what, int exit_code = 2)
      : std::runtime_error(what), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

/// A subcommand's run: the exit status of a run that went to its end (0 success, 1 it ran but
/// reported a failure: an incomplete trace, a face that could not be read, ...).
using CommandRun = std::function<int()>;

/// The runs of the subcommands, by the CLI11 subcommand that selects them. Runs are called after
/// the whole command line is parsed, never from inside CLI11's parse.
class Commands {
 public:
  void add(const CLI::App* subcommand, CommandRun run) { runs_.emplace_back(subcommand, std::move(run)); }
  /// Runs the deepest parsed subcommand that has a run ("packing spheres" rather than "packing")
  /// and returns its exit status.
  int run_selected(const CLI::App& app) const {
    const CommandRun* chosen = nullptr;
    for (const CLI::App* at = &app; at;) {
      for (const auto& [sub, run] : runs_)
        if (sub == at) chosen = &run;
      const auto parsed = at->get_subcommands();
      at = parsed.empty() ? nullptr : parsed.front();
    }
    if (!chosen) throw CliError("no subcommand given (ssimarch --help)");
    return (*chosen)();
  }

 private:
  std::vector<std::pair<const CLI::App*, CommandRun>> runs_;
};

void add_trace_command(CLI::App& app, Commands& commands);
void add_section_command(CLI::App& app, Commands& commands);
void add_intersect_command(CLI::App& app, Commands& commands);
void add_eval_command(CLI::App& app, Commands& commands);
void add_demo_command(CLI::App& app, Commands& commands);
void add_surfaces_command(CLI::App& app, Commands& commands);
void add_curve_geometry_command(CLI::App& app, Commands& commands);
void add_porosity_command(CLI::App& app, Commands& commands);
void add_packing_command(CLI::App& app, Commands& commands);
void add_singular_command(CLI::App& app, Commands& commands);
void add_batch_command(CLI::App& app, Commands& commands);
void add_view_command(CLI::App& app, Commands& commands);
void add_faces_command(CLI::App& app, Commands& commands);

}  // namespace ssimarch::cli
