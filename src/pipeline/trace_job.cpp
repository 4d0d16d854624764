#include "ssimarch/pipeline/trace_job.hpp"

#include <algorithm>

#include "ssimarch/core/error.hpp"
#include "ssimarch/geometry/intersection_geometry.hpp"
#include "ssimarch/march/model_size.hpp"
#include "ssimarch/topology/trace_all.hpp"

namespace ssimarch {

bool TraceJobResult::complete() const {
  return std::none_of(runs.begin(), runs.end(),
                      [](const IntersectionRun& r) {
                        // No curve is a result when the start-point search proved there is none
                        // (issue 11 item 6); otherwise an empty trace is incomplete.
                        const bool proven_empty = r.result.curves.empty() && r.result.start_search.certified;
                        return (r.result.curves.empty() && !proven_empty) || r.result.failed_starts > 0;
                      });
}

std::vector<IntersectionSpec> select_intersections(const Scene& scene, const TraceRequest& request) {
  for (const std::string& name : request.only)
    if (!scene.intersection(name))
      throw InputError(request.only_where,
                       "the scene has no intersection \"" + name + "\" (it has: " + scene.intersection_names() + ")");
  std::vector<IntersectionSpec> selected;
  for (IntersectionSpec spec : scene.intersections) {
    if (!request.only.empty() && std::find(request.only.begin(), request.only.end(), spec.name) == request.only.end())
      continue;
    for (const OptionOverride& o : request.overrides)
      apply_trace_option(*o.option, o.value, scene.constants, o.where, &spec.options);
    check_trace_options(spec.options, request.overrides.empty() ? scene.source + ": " + spec.name + ".options"
                                                                : std::string("command-line options"));
    selected.push_back(std::move(spec));
  }
  if (selected.empty()) throw InputError(scene.source, "the scene has no intersections to trace");
  return selected;
}

IntersectionRun run_intersection(const Scene& scene, const IntersectionSpec& spec) {
  IntersectionRun run{spec, scene.problem(spec), {}, {}};
  // The options against the model before any work (march/model_size.hpp): the key at fault
  // and the usable range.
  std::string key, error;
  if (!run.problem.disjoint() && !fits_model(spec.options.trace, run.problem.scale(), &key, &error))
    throw InputError(scene.source + ": " + spec.name + (key == "model size" ? "" : ".options." + key), error);
  run.result = trace_all(run.problem, spec.options.trace, spec.starts);
  if (spec.options.geometry)
    for (const TracedCurve& c : run.result.curves)
      run.geometry.push_back(geometry_along_curve(run.problem, c, *spec.options.geometry));
  return run;
}

TraceJobResult trace_scene(const Scene& scene, const TraceRequest& request) {
  TraceJobResult job;
  for (const IntersectionSpec& spec : select_intersections(scene, request)) job.runs.push_back(run_intersection(scene, spec));
  return job;
}

std::vector<CurveGeometry> geometry_along_curve(const Problem& problem, const TracedCurve& curve,
                                                          GeometryMethod method) {
  std::vector<CurveGeometry> out;
  // Neighbours along the traced curve (closed curves wrap; the closing point repeats the first).
  const std::size_t n = curve.points.size();
  const std::size_t m = curve.closed && n > 1 ? n - 1 : n;
  for (std::size_t i = 0; i < n; ++i) {
    GeometryContext ctx;
    const std::size_t k = (curve.closed && i + 1 == n) ? 0 : std::min(i, m - 1);  // the closing point is point 0
    for (std::size_t back = 3; back >= 1; --back) {
      if (k >= back) ctx.previous.push_back(curve.points[k - back].x);
      else if (curve.closed && m > back) ctx.previous.push_back(curve.points[m + k - back].x);
    }
    if (k + 1 < m) ctx.next.push_back(curve.points[k + 1].x);
    else if (curve.closed && m > 1) ctx.next.push_back(curve.points[0].x);
    ctx.orientation = curve.points[i].t;
    out.push_back(evaluate_geometry(problem, curve.points[i].x, method, ctx));
  }
  return out;
}

}  // namespace ssimarch
