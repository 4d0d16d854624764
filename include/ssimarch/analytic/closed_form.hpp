// Exact intersection curves of primitive pairs that have them (docs/math/closed_form_quadrics.md):
// a plane and a quadric (a plane section), two coaxial surfaces of revolution (circles), two
// spheres (coaxial about the line of their centres). The case list follows OpenCASCADE's
// IntAna_QuadQuadGeo (plane-plane aside, which marching handles as well); the mathematics is ours.
// The answer has the shape of a traced one (curves of points on both surfaces, clipped to the
// problem's box and to the primitives' trims: a plane's rectangle, a cylinder's or cone's axial
// range) plus the conic of each curve.
#pragma once

#include <optional>
#include <vector>

#include "ssimarch/analytic/conic.hpp"
#include "ssimarch/march/options.hpp"
#include "ssimarch/march/resolved_options.hpp"
#include "ssimarch/trace/result.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

struct ClosedFormResult {
  TraceResult result;        // curves, isolated (contact) points, stats; start_search.method "closed-form"
  std::vector<Conic> conics; // conics[i] is result.curves[i]'s conic piece (type, centre, axes, range)
  std::string pair;          // which closed form answered: "plane-quadric", "coaxial"
};

/// The exact intersection of an implicit-implicit problem whose surfaces are both recognised
/// primitives of a pair with a closed form; nullopt otherwise (another pair kind, another pair,
/// coincident surfaces), when the caller traces instead. Points: chords within the resolved
/// deviation and at most ResolvedTraceOptions::chord long, the same rule as the `chordal` step;
/// contact decided at the resolved tolerance (contact_gap_tolerance).
std::optional<ClosedFormResult> closed_form_intersection(const Problem& problem, const ResolvedTraceOptions& options);

/// The same with options not yet resolved (checked and resolved here, resolve_trace_options).
std::optional<ClosedFormResult> closed_form_intersection(const Problem& problem, const TraceOptions& options);

}  // namespace ssimarch
