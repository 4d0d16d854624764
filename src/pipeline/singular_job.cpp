#include "ssimarch/pipeline/singular_job.hpp"

#include "ssimarch/core/error.hpp"
#include "ssimarch/singular/detection.hpp"

namespace ssimarch {

std::vector<SingularJobResult> run_singular_job(const Scene& scene, const SingularJobOptions& options) {
  if (options.grid < 3) throw InputError("--grid", "must be at least 3, got " + std::to_string(options.grid));
  std::vector<SingularJobResult> out;
  for (const IntersectionSpec& spec : scene.intersections) {
    if (!options.only.empty() && spec.name != options.only) continue;
    const Problem problem = scene.problem(spec);
    HuntOptions hunt;
    hunt.grid = options.grid;
    SingularJobResult r{spec.name, {}};
    // The hunt's locations are converged; each is analysed where it was located.
    SingularAnalysisOptions analyse;
    analyse.locate = false;
    for (const SingularLocation& s : hunt_singular_points(problem, hunt))
      r.points.push_back(analyse_singular_point(problem, s, analyse));
    out.push_back(std::move(r));
  }
  if (out.empty() && !options.only.empty())
    throw InputError("--intersection", "the scene has no intersection \"" + options.only + "\"");
  return out;
}

}  // namespace ssimarch
