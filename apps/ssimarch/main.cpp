// ssimarch: command-line front end. Exit status: 0 success, 1 the computation ran but reported a
// failure (see each subcommand's help), 2 invalid input or usage, 3 internal error.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "commands.hpp"
#include "ssimarch/core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ssimarch: intersection curves of surfaces, their differential geometry, and exact porosity profiles"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ssimarch 0.1.0");
  ssimarch::cli::add_trace_command(app);
  ssimarch::cli::add_eval_command(app);
  ssimarch::cli::add_demo_command(app);
  ssimarch::cli::add_surfaces_command(app);
  ssimarch::cli::add_curve_geometry_command(app);
  ssimarch::cli::add_porosity_command(app);
  ssimarch::cli::add_packing_command(app);
  ssimarch::cli::add_singular_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const ssimarch::cli::CliError& e) {
    std::cerr << "ssimarch: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const ssimarch::InputError& e) {
    std::cerr << "ssimarch: error: " << e.what() << "\n";
    return 2;
  } catch (const std::logic_error& e) {
    std::cerr << "ssimarch: internal error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "ssimarch: error: " << e.what() << "\n";
    return 2;
  }
  return ssimarch::cli::g_exit_status;
}
