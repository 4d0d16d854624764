// Subcommands of the ssimarch tool. Each add_*_command registers one subcommand with its options,
// help text and callback. Callbacks throw ssimarch::CliError (or any std::exception) for bad
// input; main() prints the message to stderr and exits with the error's code.
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

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

/// Exit status a subcommand sets when it ran but reported a failure (1); main() returns it.
inline int g_exit_status = 0;

void add_trace_command(CLI::App& app);
void add_eval_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_surfaces_command(CLI::App& app);
void add_curve_geometry_command(CLI::App& app);
void add_porosity_command(CLI::App& app);
void add_packing_command(CLI::App& app);
void add_singular_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_view_command(CLI::App& app);
void add_faces_command(CLI::App& app);

}  // namespace ssimarch::cli
