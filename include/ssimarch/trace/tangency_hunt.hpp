// Where the surfaces touch away from the traced curves (issue 10 item 5): isolated points (no
// real branch through them, thesis Ex. 16) and curves of tangential contact, which no march
// reaches (every point of them is singular). Reported by default: the hunt looks only where a
// singular point can be (docs/math/tangential_contact.md §4):
//   * after a certified start-point search that decided every box, nowhere: a singular point is
//     a root of every turning system with a singular Jacobian, which the Krawczyk test never
//     certifies, so a fully certified domain has none;
//   * after a certified search with uncertain regions, in those boxes only (a small grid each);
//   * after sampling or given start points (parametric-implicit pairs; the others' grids cost
//     seconds), over a grid of the whole domain where sin(theta) <= 0.2, at the grid points within
//     a cell of the boxes one turning system's interval search leaves undecided or unexplored
//     (singular_point_regions; every point when the surfaces do not evaluate on intervals);
//   * in every case, a grid start whose cell provably holds no singular point (an interval test
//     of the gap and sin(theta), start/patch_exclusion.hpp) is skipped.
#pragma once

#include <vector>

#include "ssimarch/march/tracer.hpp"
#include "ssimarch/trace/result.hpp"
#include "ssimarch/trace/singular_registry.hpp"
#include "ssimarch/trace/tangential_contact.hpp"

namespace ssimarch {

/// When x (a start point of the tracer) is a point of a curve of tangential contact that is not
/// traced yet, traces that curve, appends it to *curves (index = its position), records the
/// transversal branches crossing it in the registry, and returns true.
bool trace_contact_from(const Tracer& tracer, const VecX& x, std::vector<TracedCurve>* curves,
                        SingularRegistry* registry);

/// A transversal branch marched over its crossing with a contact curve (no watch fires there:
/// the rank ratio dips only within the crossing's own scale) passes the crossing between two
/// of its points: the crossing becomes an exact point of that curve and the half-branches along
/// it count as followed (each traced exactly once). For every tangent_line_crossing node, and
/// for every node no curve has met (a singular point the hunt found that a march stepped over).
void attach_crossings(SingularRegistry* registry, std::vector<TracedCurve>* curves, double radius);

/// Hunts the isolated points and the curves of tangential contact of the tracer's problem that
/// the curves traced so far did not meet; contact curves are appended to *curves, isolated
/// points to *isolated, singular points with real branches to the registry (attach_crossings).
void hunt_tangencies(const Tracer& tracer, const StartPointSearch& search, SingularRegistry* registry,
                     std::vector<TracedCurve>* curves, std::vector<SingularPointReport>* isolated);

}  // namespace ssimarch
