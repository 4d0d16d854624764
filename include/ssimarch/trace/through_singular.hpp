// Marching a branch through the singular points it meets (issue 10 "Tracing through"; thesis
// ch. 6): a march that stops at a suspected singular point goes back and locates it; a located
// point becomes an exact point of the curve, which goes on along the half-branch continuing the
// arriving one analytically (straight across a node, over the tangent reversal of a cusp, on its
// own side at a tacnode); a near miss continues as a regular march.
#pragma once

#include <vector>

#include "ssimarch/march/tracer.hpp"
#include "ssimarch/trace/singular_registry.hpp"

namespace ssimarch {

struct BranchMarch {
  std::vector<CurvePoint> points;  // tangents along the direction of travel
  double length = 0;
  Event event;  // why the last march stopped (kClosed: the curve is closed)
  bool closed = false;
  int end_node = -1;  // the singular node the branch ended at, if any
};

/// Marches from `start` (tangent along the direction of travel) until an event that is not a
/// singular point passed through. `from_node` / `from_half`: the branch left that node along
/// that half-branch (start is then its exit point), and arriving back through its continuation
/// closes the curve. `close_at`: the point whose return closes the curve (null: no closure test
/// against a point). `curve`: the index the curve will have (recorded at each node). `base`: the
/// limits of every march (null: tracer.limits()), e.g. traced curves to stop at.
BranchMarch march_branch(const Tracer& tracer, const CurvePoint& start, const CurvePoint* close_at,
                         SingularRegistry* registry, int curve, TraceStats* stats, int from_node = -1,
                         int from_half = -1, const MarchLimits* base = nullptr);

}  // namespace ssimarch
