// ssimarch surfaces: the surface types a scene file may use.
#include <iostream>

#include "commands.hpp"
#include "ssimarch/io/surface_json.hpp"

namespace ssimarch::cli {

void add_surfaces_command(CLI::App& app, Commands& commands) {
  CLI::App* cmd = app.add_subcommand("surfaces", "List the surface types a scene file may use (keys: docs/scene-format.md)");
  commands.add(cmd, [] {
    for (const auto& n : surface_type_names()) std::cout << n << "\n";
    return 0;
  });
}

}  // namespace ssimarch::cli
