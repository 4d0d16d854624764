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
};

/// Every singular point of each intersection of `scene` (or of options.only), in scene order.
/// Throws InputError when options.grid is below 3 or options.only names no intersection.
std::vector<SingularJobResult> run_singular_job(const Scene& scene, const SingularJobOptions& options = {});

}  // namespace ssimarch
