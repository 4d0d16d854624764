// Tracing the intersections of a scene and writing the results (JSON, CSV, OBJ).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/march/result.hpp"

namespace ssimarch {

struct IntersectionRun {
  IntersectionSpec spec;
  Problem problem;
  TraceResult result;
};

/// Traces one intersection of the scene.
IntersectionRun run_intersection(const Scene& scene, const IntersectionSpec& spec);

/// Adds keys to the JSON object of point `index` of `curve` (e.g. differential geometry).
using PointDecorator = std::function<void(const IntersectionRun&, const TracedCurve& curve, std::size_t index, nlohmann::json* point)>;

/// {"name", "surfaces", "pair_kind", "unknowns", "curves": [{"closed", "length", "ends", "points":
/// [{"xyz", "params"}]}], "stats": {"points", "rejected_steps", "iterations": {"1".."5+"}, ...},
/// "warnings"}. Schema: docs/output-format.md.
nlohmann::json to_json(const IntersectionRun& run, const PointDecorator& decorate = {});
nlohmann::json stats_to_json(const TraceStats& stats);

/// {"intersections": [...]} for every run.
void write_json(std::ostream& out, const std::vector<IntersectionRun>& runs, const PointDecorator& decorate = {});
/// One row per point: intersection,curve,point,closed,x,y,z,u,v,p,q (unused unknowns empty).
void write_csv(std::ostream& out, const std::vector<IntersectionRun>& runs);
/// Wavefront OBJ: the points as vertices and each curve as a polyline `l` (closed curves repeat
/// their first vertex), one object `o` per curve.
void write_obj(std::ostream& out, const std::vector<IntersectionRun>& runs);

}  // namespace ssimarch
