// Writing the results of a trace job (pipeline/trace_job.hpp): JSON, CSV, OBJ.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <ostream>
#include <vector>

#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

/// {"name", "surfaces", "pair_kind", "unknowns", "curves": [{"closed", "length", "ends", "points":
/// [{"xyz", "params"}]}], "stats": {"points", "rejected_steps", "iterations": {"1".."5+"}, ...},
/// "warnings"}; with the geometry option every point also has t, n, b, kappa, tau,
/// kappa_prime, theta (null where undetermined) and geometry_status. Schema: docs/output-format.md.
/// With the bspline option each curve also has "bspline" {degree, periodic, knots,
/// control_points, tolerance, within_tolerance, pieces, inserted_points, c0_knots, c1_knots}, "pcurves"
/// [{surface, degree, periodic, knots, control_points}] and "max_deviation".
nlohmann::json to_json(const IntersectionRun& run);
nlohmann::json stats_to_json(const TraceStats& stats);

/// {"intersections": [...]} for every run.
void write_json(std::ostream& out, const std::vector<IntersectionRun>& runs);
/// One row per point: intersection,curve,point,closed,x,y,z,u,v,p,q (unused unknowns empty).
void write_csv(std::ostream& out, const std::vector<IntersectionRun>& runs);
/// Wavefront OBJ: the points as vertices and each curve as a polyline `l` (closed curves repeat
/// their first vertex), one object `o` per curve.
void write_obj(std::ostream& out, const std::vector<IntersectionRun>& runs);

}  // namespace ssimarch
