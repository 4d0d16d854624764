#include "ssimarch/pipeline/trace_job.hpp"

#include <algorithm>
#include <sstream>
#include <limits>
#include <atomic>

#include "ssimarch/analytic/closed_form.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/core/progress.hpp"
#include "ssimarch/core/thread_pool.hpp"
#include "ssimarch/geometry/intersection_geometry.hpp"
#include "ssimarch/march/model_size.hpp"
#include "ssimarch/pipeline/branch_geometry.hpp"
#include "ssimarch/pipeline/face_clip.hpp"
#include "ssimarch/pipeline/shared_boundary.hpp"
#include "ssimarch/singular/locate.hpp"
#include "ssimarch/trace/trace_all.hpp"

namespace ssimarch {

bool run_complete(const IntersectionRun& r) {
  // No curve is a result when the start-point search proved there is none (issue 11 item 6);
  // otherwise an empty trace is incomplete. Coincident surfaces are never "proven empty": they
  // share a region.
  const bool proven_empty = r.result.curves.empty() && r.result.start_search.certified && !r.coincidence;
  return !((r.result.curves.empty() && !proven_empty) || r.result.failed_starts > 0 || !r.network.complete());
}

bool TraceJobResult::complete() const { return std::all_of(runs.begin(), runs.end(), run_complete); }

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

TraceJobOptions requested_options(const std::vector<OptionOverride>& overrides) {
  TraceJobOptions options;
  for (const OptionOverride& o : overrides) apply_trace_option(*o.option, o.value, Constants{}, o.where, &options);
  return options;
}

namespace {

// The options checked and resolved against the model once, before any work (march/
// resolved_options.hpp): an error names the scene key at fault and the usable range.
ResolvedTraceOptions resolved_options(const Scene& scene, const IntersectionSpec& spec, const Problem& problem) {
  if (problem.disjoint()) {
    ResolvedTraceOptions r{spec.options.trace, 0, 0};
    r.options.tolerance = resolved_tolerance(spec.options.trace, problem.scale());
    return r;
  }
  try {
    return resolve_trace_options(spec.options.trace, problem.scale());
  } catch (const InputError& e) {
    const std::string key = e.where() == "model size" ? "" : ".options." + e.where();
    throw InputError(scene.source + ": " + spec.name + key, e.message());
  }
}

// The distance within which a sample of one surface lies on the other: the corrector's
// tolerance with room for the rounding of the model's size.
double coincidence_tolerance(const IntersectionRun& run) {
  return std::max(1e3 * run.used.options.tolerance, 1e-12 * run.problem.scale());
}

// The curves of the run: the closed form when the pair has one, nothing when the surfaces share a
// region, else traced.
void find_curves(const IntersectionSpec& spec, IntersectionRun* run_ptr) {
  IntersectionRun& run = *run_ptr;
  // Pairs with a closed form are answered exactly (docs/math/closed_form_quadrics.md); given start
  // points ask for the curves through them, which the tracer answers.
  std::optional<ClosedFormResult> exact;
  if (spec.options.closed_form && spec.starts.empty()) exact = closed_form_intersection(run.problem, run.used);
  if (exact) {
    run.result = std::move(exact->result);
    run.conics = std::move(exact->conics);
    return;
  }
  // Surfaces that share a region are tangent all over it: no search can decide it, and a
  // coincident B-spline pair (a rod against its hole) ran for minutes. Probed before tracing
  // (closed forms decline coincident pairs themselves, so a pair they answer costs nothing more).
  if (spec.starts.empty() && !run.problem.disjoint())
    run.coincidence = probe_coincidence(run.problem, coincidence_tolerance(run));
  if (run.coincidence) {
    run.result.start_search.method = StartSearchMethod::kCoincident;
    run.result.start_search.note = "the surfaces share a region: nothing was traced";
  } else {
    TraceAllOptions all;
    all.hunt_isolated_points = spec.options.hunt_isolated_points;
    run.result = trace_all(Tracer(run.problem, run.used), spec.starts, all);
  }
}

// Whether the surfaces coincide over a region (issue 13 item 3), checked where the answer leaves
// room for it: no curve, a search that did not decide every box, or a curve of tangential contact
// (coincident surfaces are tangent everywhere in the shared region, so the tracer finds contact
// lines or uncertain boxes there, never a certified answer; issue 28: a rod in a hole of its own
// radius gave one "tangential contact" line). A shared region found beside curves withdraws the
// certificate: those curves lie in or along the region, and its boundary is not traced.
bool may_coincide(const IntersectionRun& run) {
  if (run.coincidence) return false;  // found before tracing (find_curves)
  // A closed form answers only distinct surfaces (closed_form.hpp: coincident ones are traced).
  // Surfaces in disjoint boxes share no region (and the tracer said so without work): skipping the
  // sampling here makes the empty pairs of a model's all-pairs batch cheap (issue 17).
  if (run.result.start_search.method == StartSearchMethod::kClosedForm || run.problem.disjoint()) return false;
  if (run.result.curves.empty() || !run.result.start_search.certified) return true;
  return std::any_of(run.result.curves.begin(), run.result.curves.end(),
                     [](const TracedCurve& c) { return c.tangential_contact; });
}

void report_coincidence(const IntersectionSpec& spec, IntersectionRun* run_ptr) {
  IntersectionRun& run = *run_ptr;
  if (may_coincide(run)) run.coincidence = find_coincidence(run.problem, coincidence_tolerance(run));
  if (!run.coincidence) return;
  const std::string& first = spec.surfaces[spec.swapped ? 1 : 0];
  const std::string& second = spec.surfaces[spec.swapped ? 0 : 1];
  const Box& b = run.coincidence->region;
  const std::string curves = run.result.curves.empty()
                                 ? "which has no intersection curve"
                                 : "which has no intersection curve: the " + std::to_string(run.result.curves.size()) +
                                       " curve(s) reported lie in or along it, and its boundary is not traced "
                                       "(not certified)";
  run.result.start_search.certified = false;
  run.result.warnings.push_back("the surfaces coincide (" + std::to_string(run.coincidence->shared) + " of " +
                                std::to_string(run.coincidence->samples) + " samples of " + first + " lie on " +
                                second + ", in the box x [" + std::to_string(b.x.lo) + ", " + std::to_string(b.x.hi) +
                                "], y [" + std::to_string(b.y.lo) + ", " + std::to_string(b.y.hi) + "], z [" +
                                std::to_string(b.z.lo) + ", " + std::to_string(b.z.hi) +
                                "]): they share a surface region, " + curves);
}

}  // namespace

namespace {

// The B-spline's tolerance against what double precision certifies for this model (issue 29: 1e-300
// halved pieces without end): the measured distances are between points computed to the rounding
// of the coordinates, kSplineToleranceRounding eps x the model size, so a tolerance below that is
// never met and the halving would stop only at its depth limit, having used all that memory.
constexpr double kSplineToleranceRounding = 64;  // units of DBL_EPSILON x the model size

void check_spline_tolerance(const Scene& scene, const IntersectionSpec& spec, const Problem& problem) {
  const double t = spec.options.spline.tolerance;
  if (!spec.options.bspline || t == 0 || problem.disjoint()) return;
  const double floor = kSplineToleranceRounding * std::numeric_limits<double>::epsilon() * problem.scale();
  if (t < floor) {
    std::ostringstream m;
    m.precision(3);
    m << t << " is below what double precision can certify for this model (size " << problem.scale() << "): at least "
      << floor << " (64 eps times the model size), or 0 for the automatic 1e-9 times the size";
    throw InputError(scene.source + ": " + spec.name + ".options.bspline_tolerance", m.str());
  }
}

}  // namespace

IntersectionRun run_intersection(const Scene& scene, const IntersectionSpec& spec) {
  IntersectionRun run{spec, scene.problem(spec), {}, {}, {}, {}, {}, {}, {}};
  run.used = resolved_options(scene, spec, run.problem);
  check_spline_tolerance(scene, spec, run.problem);
  // CAD faces: two faces of one solid meet where they share edges and vertices; others have their
  // curves cut to their trimming loops (docs/cad.md).
  auto region = [&](std::size_t k) {
    const auto it = scene.regions.find(spec.surfaces[spec.swapped ? 1 - k : k]);
    return it == scene.regions.end() ? nullptr : it->second.get();
  };
  std::optional<TraceResult> shared;
  if (spec.options.solid_topology && spec.starts.empty())
    shared = shared_boundary(run.problem, region(0), region(1), run.used);
  if (shared) {
    run.result = std::move(*shared);
  } else {
    find_curves(spec, &run);
    clip_to_regions({region(0), region(1)}, &run);
    report_coincidence(spec, &run);
  }
  run.network = build_curve_network(run.problem, run.result);
  for (const NetworkFailure& f : run.network.failures)
    run.result.warnings.push_back("curve " + std::to_string(f.curve) + " " + f.end + " stops away from the domain boundary (" +
                                  f.reason + "): " + f.message);
  if (spec.options.geometry)
    for (const TracedCurve& c : run.result.curves)
      run.geometry.push_back(geometry_along_curve(run.problem, c, *spec.options.geometry));
  if (spec.options.bspline)
    for (std::size_t c = 0; c < run.result.curves.size(); ++c) {
      run.splines.push_back(spline_of_curve(run.problem, run.result.curves[c], spec.options.spline,
                                            &run.result.singular_points, static_cast<int>(c)));
      // The certified spline's arc length (its parameter: Gauss-Legendre on each quintic piece)
      // replaces the circular-arc estimate over the traced points, which is off by O(h^4) per
      // segment (1.6e-6 on a torus section at the default deviation); a closed form's is exact.
      if (run.splines.back() && run.conics.empty())
        run.result.curves[c].length = run.splines.back()->length;
    }
  return run;
}

std::optional<CurveSpline> spline_of_curve(const Problem& problem, const TracedCurve& curve, const CurveSplineOptions& options,
                                           const std::vector<SingularPointReport>* singular, int index) {
  std::vector<VecX> x;
  std::vector<Vec3> t;
  // The half-branch tangents of the singular points this curve passes (exact points of it).
  std::vector<std::vector<Vec3>> branches;
  auto branches_at = [&](const CurvePoint& p) {
    std::vector<Vec3> h;
    if (!singular) return h;
    for (const SingularPointReport& r : *singular)
      if (std::find(r.curves.begin(), r.curves.end(), index) != r.curves.end() &&
          (r.p - p.p).norm() <= 1e-9 * problem.scale())
        for (const auto& b : r.half_branches) h.push_back(b.tangent);
    return h;
  };
  // A closed curve's last point is its first (march/result.hpp): it is added back below.
  const std::size_t m = curve.closed && curve.points.size() > 1 ? curve.points.size() - 1 : curve.points.size();
  for (std::size_t i = 0; i < m; ++i) {
    x.push_back(curve.points[i].x);
    t.push_back(curve.points[i].t);
    branches.push_back(branches_at(curve.points[i]));
  }
  if (curve.closed && x.size() > 1) {
    x.push_back(curve.points.front().x);
    t.push_back(curve.points.front().t);
    branches.push_back(branches.front());
  }
  if (x.size() < 2) return std::nullopt;
  return fit_curve_spline(problem, x, t, curve.closed, options, &branches);
}

TraceJobResult trace_scene(const Scene& scene, const TraceRequest& request) {
  // The intersections are independent (each its own Problem; surfaces and compiled programs are
  // read-only, docs/expressions.md): traced in parallel on the shared pool, kept in scene order.
  const std::vector<IntersectionSpec> specs = select_intersections(scene, request);
  std::vector<std::optional<IntersectionRun>> runs(specs.size());
  std::atomic<std::size_t> finished{0};
  const double total = static_cast<double>(specs.size());
  parallel_for(specs.size(), [&](std::size_t i) {
    throw_if_interrupted();  // Ctrl-C between intersections (core/interrupt.hpp)
    runs[i].emplace(run_intersection(scene, specs[i]));
    // Shown only for several intersections (one intersection's own stages report themselves). The
    // meter is the calling thread's (core/progress.hpp): it reports the count finished so far each
    // time it finishes one of its own; the pool's workers only count.
    const double done = static_cast<double>(++finished);
    if (specs.size() > 1) report_progress("trace", done, total);
  });
  TraceJobResult job;
  for (std::optional<IntersectionRun>& r : runs) job.runs.push_back(std::move(*r));
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
    // mixed at a singular point of the curve (sin theta at the rounding floor of its location):
    // the geometry along the half-branch the curve leaves by (pipeline/branch_geometry.hpp).
    if (method == GeometryMethod::kMixed) {
      const Linearization L = problem.linearize(curve.points[i].x);
      if (L.normal_first.cross(L.normal_second).norm() <= LocateOptions{}.sine_tolerance)
        if (auto g = singular_branch_geometry(problem, curve.points[i].x, &curve.points[i].t, 1e-9 * problem.scale())) {
          out.push_back(g->geometry);
          continue;
        }
    }
    out.push_back(evaluate_geometry(problem, curve.points[i].x, method, ctx));
  }
  return out;
}

std::array<std::string, 2> parametric_surface_names(const IntersectionRun& run) {
  const auto& s = run.spec.surfaces;
  return run.spec.swapped ? std::array<std::string, 2>{s[1], s[0]} : std::array<std::string, 2>{s[0], s[1]};
}

}  // namespace ssimarch
