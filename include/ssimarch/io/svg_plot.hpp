// SVG pictures of traced curves: an axonometric 3D view and the curves in each parameter domain
// (or two orthographic views for implicit-implicit pairs). Self-contained SVG, no dependencies.
#pragma once

#include <ostream>
#include <string>

#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

struct SvgOptions {
  // The 3D view looks along the direction in which the points vary least (their smallest
  // principal axis), so a curve is seen as spread out as possible, unless `axonometric` is set:
  // then the view is rotated by azimuth about z and tilted by elevation.
  bool axonometric = false;
  double azimuth_deg = 35;
  double elevation_deg = 25;
  int panel_size = 380;       // pixels per panel
};

void write_svg(std::ostream& out, const IntersectionRun& run, const SvgOptions& options = {});

}  // namespace ssimarch
