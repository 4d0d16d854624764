// Private to surface/: the sampled comparison of a parametric form's two edges across one
// parameter, shared by closes_seam (degenerate_edges.cpp) and the periodic test of a B-spline
// patch (splines.cpp, issue 27).
#pragma once

#include <algorithm>
#include <cmath>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/degenerate_edges.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch::internal {

/// Points sampled along an edge.
inline constexpr int kEdgeSamples = 33;

/// kDegenerateEdgeRelative times the diagonal of `box` (of 1 where it has none).
inline double edge_eps(const Box& b) {
  const double diagonal = Vec3(b.x.width(), b.y.width(), b.z.width()).norm();
  return kDegenerateEdgeRelative * (std::isfinite(diagonal) && diagonal > 0 ? diagonal : 1.0);
}

/// Whether the edges at the two ends of `parameter` (0 = u, 1 = v) of `d` agree within eps at
/// kEdgeSamples points; `point(u, v)` gives F as a Vec3. *extent (if given): the largest distance
/// of the lower edge's samples from its first one (0 for a collapsed edge).
template <class PointFn>
bool edges_agree(const PointFn& point, int parameter, const ParamDomain& d, double eps, double* extent = nullptr) {
  const Interval& across = parameter == 0 ? d.u : d.v;
  const Interval& along = parameter == 0 ? d.v : d.u;
  auto at = [&](double c, double w) { return parameter == 0 ? point(c, w) : point(w, c); };
  const Vec3 first = at(across.lo, along.lo);
  double reach = 0;
  for (int i = 0; i < kEdgeSamples; ++i) {
    const double w = along.lo + along.width() * i / (kEdgeSamples - 1);
    const Vec3 a = at(across.lo, w), b = at(across.hi, w);
    if (!(a - b).allFinite() || (a - b).norm() > eps) return false;
    reach = std::max(reach, (a - first).norm());
  }
  if (extent) *extent = reach;
  return true;
}

}  // namespace ssimarch::internal
