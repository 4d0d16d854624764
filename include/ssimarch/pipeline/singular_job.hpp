// The singular points of a scene's intersections without tracing them (`ssimarch singular`;
// docs/singular.md): the hunt of singular/detection.hpp over each problem's domain, every point
// it finds analysed by singular/analysis.hpp.
#pragma once

#include <string>
#include <vector>

#include "ssimarch/pipeline/scene.hpp"
#include "ssimarch/singular/analysis.hpp"

namespace ssimarch {

struct SingularJobOptions {
  std::string only;  // the name of one intersection; empty: all
  int grid = 32;     // hunt samples per parameter direction (HuntOptions::grid), at least 3
};

struct SingularJobResult {
  std::string intersection;              // its name in the scene
  std::vector<SingularAnalysis> points;  // each located, with its local curve, class, half-branches
  /// Points of curves of tangential contact the hunt met (every point of such a curve is singular:
  /// they are counted, not listed; `ssimarch trace` gives the curves).
  int contact_points = 0;
};

/// Every singular point of each intersection of `scene` (or of options.only), in scene order.
/// Points of curves of tangential contact are not listed: near each, the crossings of the contact
/// curve with transversal branches are (tangent_line_crossing, trace/tangential_contact.hpp
/// crossing_near), and a node that is a crossing located off it is refined to it
/// (singular/third_order_point.hpp). Points closer than kSingularMergeDistance x the problem's
/// scale are one.
/// Throws InputError when options.grid is below 3 or options.only names no intersection.
std::vector<SingularJobResult> run_singular_job(const Scene& scene, const SingularJobOptions& options = {});

}  // namespace ssimarch
