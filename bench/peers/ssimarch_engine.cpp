#include <chrono>

#include "peer_engines.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace peers {

using namespace ssimarch;

Outcome run_ssimarch(const Scene& scene, const IntersectionSpec& spec, double* ms) {
  const auto t0 = std::chrono::steady_clock::now();
  const IntersectionRun run = run_intersection(scene, spec);
  *ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  Outcome out;
  const Surface& a = scene.surface(spec.surfaces[0]);
  const Surface& b = scene.surface(spec.surfaces[1]);
  out.curves = static_cast<int>(run.result.curves.size());
  out.isolated = static_cast<int>(run.result.isolated_points.size());
  for (const TracedCurve& c : run.result.curves) {
    out.closed += c.closed ? 1 : 0;
    out.length += c.length;
    for (const CurvePoint& p : c.points) out.residual = std::max(out.residual, residual(a, b, p.p));
  }
  if (run.result.start_search.method == StartSearchMethod::kClosedForm) out.note = "closed form";
  return out;
}

}  // namespace peers
