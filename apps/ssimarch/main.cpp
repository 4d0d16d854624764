// ssimarch: command-line front end. Exit status: 0 success, 1 the computation ran but reported a
// failure (see each subcommand's help), 2 invalid input or usage, or an output that could not be
// written, 3 internal error, 4 the run exceeded its time or memory budget (run_budget.hpp), 130
// interrupted by Ctrl-C (SIGINT; core/interrupt.hpp), with no output written.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ssimarch: intersection curves of surfaces, their differential geometry, and exact porosity profiles"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ssimarch 0.1.0");
  ssimarch::cli::Commands commands;
  ssimarch::cli::add_trace_command(app, commands);
  ssimarch::cli::add_section_command(app, commands);
  ssimarch::cli::add_intersect_command(app, commands);
  ssimarch::cli::add_eval_command(app, commands);
  ssimarch::cli::add_demo_command(app, commands);
  ssimarch::cli::add_surfaces_command(app, commands);
  ssimarch::cli::add_faces_command(app, commands);
  ssimarch::cli::add_curve_geometry_command(app, commands);
  ssimarch::cli::add_porosity_command(app, commands);
  ssimarch::cli::add_packing_command(app, commands);
  ssimarch::cli::add_singular_command(app, commands);
  ssimarch::install_interrupt_handler();
  ssimarch::cli::add_batch_command(app, commands);
  ssimarch::cli::add_view_command(app, commands);
  try {
    app.parse(argc, argv);
    return commands.run_selected(app);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const ssimarch::cli::CliError& e) {
    std::cerr << "ssimarch: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const ssimarch::InputError& e) {
    std::cerr << "ssimarch: error: " << e.what() << "\n";
    return 2;
  } catch (const ssimarch::Interrupted&) {
    std::cerr << "ssimarch: interrupted; no output was written\n";
    return ssimarch::cli::kInterruptedExitStatus;
  } catch (const std::bad_alloc&) {
    const double mib = ssimarch::cli::memory_limit_mib();
    std::cerr << "ssimarch: error: out of memory"
              << (mib > 0 ? " (the run exceeded its memory budget, --memory-limit " + std::to_string(static_cast<long>(mib)) + " MiB)"
                          : " (reduce the problem, e.g. fewer points or particles)")
              << "; no output was written\n";
    return ssimarch::cli::kBudgetExitStatus;
  } catch (const std::logic_error& e) {
    std::cerr << "ssimarch: internal error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "ssimarch: error: " << e.what() << "\n";
    return 2;
  }
}
