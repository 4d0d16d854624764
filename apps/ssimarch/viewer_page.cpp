#include "viewer_page.hpp"

#include <sstream>

#include "commands.hpp"
#include "ssimarch/io/html_writer.hpp"
#include "ssimarch/io/trace_writers.hpp"

namespace ssimarch::cli {

std::string_view require_viewer_script() {
  const std::string_view s = viewer_script();
  if (s.empty())
    throw CliError(
        "this ssimarch was built without the HTML viewer: its bundle is made from viewer/ with node and the npm "
        "packages of viewer/package-lock.json (scripts/install-deps installs them; then reconfigure and rebuild, "
        "docs/viewer.md)");
  return s;
}

IntersectionRun with_geometry(IntersectionRun run) {
  if (!run.geometry.empty() || run.result.curves.empty()) return run;
  for (const auto& c : run.result.curves) run.geometry.push_back(geometry_along_curve(run.problem, c, GeometryMethod::kExact));
  return run;
}

void write_trace_page(std::ostream& out, const std::vector<IntersectionRun>& runs, const Scene& scene,
                      const std::string& title) {
  const std::string_view script = require_viewer_script();
  nlohmann::json result = {{"intersections", nlohmann::json::array()}};
  for (const auto& r : runs) result["intersections"].push_back(to_json(with_geometry(r)));
  write_viewer_page(out, trace_page_data(result, &scene, title), script);
}

}  // namespace ssimarch::cli
