// The library's entry point for a whole trace job: every intersection of a scene traced with its
// options (and the job's overrides), decorated as asked, returned as typed results. The CLI
// (`ssimarch trace`, `ssimarch demo`), and later Python and MPI drivers, call this; io/ writes
// the results (io/trace_writers.hpp).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/analytic/conic.hpp"
#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/trace/result.hpp"
#include "ssimarch/march/resolved_options.hpp"
#include "ssimarch/pipeline/coincidence.hpp"
#include "ssimarch/pipeline/scene.hpp"
#include "ssimarch/network/curve_network.hpp"

namespace ssimarch {

/// One traced intersection.
struct IntersectionRun {
  IntersectionSpec spec;  // as traced (overrides applied)
  Problem problem;        // refers to the scene's surfaces: the Scene must outlive the run
  TraceResult result;
  CurveNetwork network;  // vertices, edges, branches, components of result (docs/topology.md)
  /// With the "geometry" option: geometry[c][i] is the differential geometry at
  /// result.curves[c].points[i]; empty without it.
  std::vector<std::vector<CurveGeometry>> geometry;
  /// With the "bspline" option: splines[c] is curve c's certified B-spline and p-curves (empty
  /// optional for a curve of one point); empty without it.
  std::vector<std::optional<CurveSpline>> splines;
  /// When the closed form answered (option "closed_form"): conics[c] is result.curves[c]'s conic;
  /// empty when the curves were traced.
  std::vector<Conic> conics;
  /// When no curve was found: the region the two surfaces share, if they share one (a warning in
  /// result.warnings says so; docs/output-format.md "coincident").
  std::optional<Coincidence> coincidence;
  /// spec.options.trace checked and resolved against the problem once (resolve_trace_options):
  /// what the closed form, the tracer and the face clip use and the output reports. For
  /// surfaces in disjoint boxes (nothing traced) only the tolerance is resolved.
  ResolvedTraceOptions used;
};

/// The scene names of the problem's first and second surface (the parametric one first: a mixed
/// pair is traced with its surfaces swapped, IntersectionSpec::swapped).
std::array<std::string, 2> parametric_surface_names(const IntersectionRun& run);

/// An option set for the whole job (e.g. a command-line flag) over every intersection's own.
struct OptionOverride {
  const TraceOptionSpec* option;  // from trace_option_table()
  OptionValue value;
  std::string where;              // names it in messages ("--step-length")
};

struct TraceRequest {
  std::vector<std::string> only;           // names of the intersections to trace; empty: all
  std::string only_where = "intersection"; // names `only` in messages ("--intersection")
  std::vector<OptionOverride> overrides;
};

struct TraceJobResult {
  std::vector<IntersectionRun> runs;
  /// False when an intersection found no curve, a given start point could not be put on it, or
  /// its curve network has a failure (an open curve ending away from the domain boundary).
  bool complete() const;
};

/// One run by the rule of TraceJobResult::complete.
bool run_complete(const IntersectionRun& run);

/// The intersections the request selects, with the overrides applied and every option checked,
/// before anything is traced. Throws InputError for an unknown name in `only`, a bad override
/// (where = its `where`), or a scene with nothing to trace.
std::vector<IntersectionSpec> select_intersections(const Scene& scene, const TraceRequest& request);

/// The options of an intersection that has none of its own (a generated scene's pair, with no
/// constants) once the overrides are applied: what a caller that builds such a scene must know
/// before building it (intersect leaves out faces of one solid only under `solid_topology`).
/// Throws InputError (where = the override's `where`) for a bad value.
TraceJobOptions requested_options(const std::vector<OptionOverride>& overrides);

/// Traces one intersection and computes its decorations.
IntersectionRun run_intersection(const Scene& scene, const IntersectionSpec& spec);

/// select_intersections, then run_intersection on each, in scene order.
TraceJobResult trace_scene(const Scene& scene, const TraceRequest& request = {});

/// The differential geometry at every point of a traced curve by `method`, each point with its
/// neighbours along the curve as the estimate methods' samples (closed curves wrap).
/// The certified B-spline of a traced curve (geometry/curve_spline.hpp); empty for a single point.
/// `singular` (optional): the trace's singular points; those listing curve `index` give their
/// half-branch tangents to the pieces that end there.
std::optional<CurveSpline> spline_of_curve(const Problem& problem, const TracedCurve& curve, const CurveSplineOptions& options,
                                           const std::vector<SingularPointReport>* singular = nullptr, int index = -1);

std::vector<CurveGeometry> geometry_along_curve(const Problem& problem, const TracedCurve& curve,
                                                          GeometryMethod method);

}  // namespace ssimarch
