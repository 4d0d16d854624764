// ssimarch view RESULT.json [--scene SCENE.json] [-o PAGE.html]: the 3D viewer page of a trace result
// (docs/viewer.md). The result names its surfaces but does not hold them: with --scene the page
// also shows the surfaces' meshes.
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "run_budget.hpp"
#include "ssimarch/io/html_writer.hpp"
#include "ssimarch/io/json_reader.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/scene.hpp"
#include "viewer_page.hpp"

namespace ssimarch::cli {

namespace {

struct ViewArgs {
  std::string result;
  std::string scene;
  std::string output;
};

void run_view(const ViewArgs& a) {
  const std::string_view script = require_viewer_script();
  const std::filesystem::path in(a.result);
  // A result holds every point with 17 digits: allow well above the scene limit.
  const nlohmann::json result =
      parse_json_text(read_text_file(in, "result file", input_limits().max_packing_bytes), a.result);
  std::optional<Scene> scene;
  if (!a.scene.empty()) scene = load_scene(a.scene, input_limits());
  const std::filesystem::path out = a.output.empty() ? std::filesystem::path(in).replace_extension(".html")
                                                    : std::filesystem::path(a.output);
  OutputFiles files;
  write_viewer_page(files.open(out), trace_page_data(result, scene ? &*scene : nullptr, in.stem().string()), script);
  files.commit();
}

}  // namespace

void add_view_command(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand("view", "Write the interactive 3D viewer page (one offline HTML file) of a trace result");
  cmd->footer(
      "The page holds the data and the viewer's script inline and opens offline in a browser (docs/viewer.md). "
      "Curvature and torsion show where the result has them (ssimarch trace --geometry exact, or --format html). "
      "Exit status 2 when this binary was built without the viewer (viewer/node_modules absent at build time).");
  cmd->add_option("result", args->result, "Result of ssimarch trace (JSON, docs/output-format.md)")->required();
  cmd->add_option("--scene", args->scene, "The scene that was traced: adds the surfaces' meshes");
  cmd->add_option("-o,--output", args->output, "Page to write (default: RESULT with extension .html)");
  add_budget_options(cmd);
  commands.add(cmd, [args] {
    run_view(*args);
    return 0;
  });
}

}  // namespace ssimarch::cli
