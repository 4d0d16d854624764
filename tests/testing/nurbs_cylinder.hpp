// The rational B-spline cylinder CAD writes, shared by the enclosure and coincidence tests
// (style.md 3.12.5).
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "ssimarch/surface/bspline_surface.hpp"

namespace ssimarch::testing {

// A cylinder of radius 1 about the z axis, z in [-1, 1]: u along four rational quarter arcs
// (double interior knots: C0 pieces, a C1 circle), closed; v linear.
inline BSplineSurface quarter_arc_cylinder() {
  const double w = std::sqrt(0.5), h = std::numbers::pi / 2;
  const std::vector<Vec3> circle{{1, 0, 0},   {1, 1, 0},  {0, 1, 0},  {-1, 1, 0}, {-1, 0, 0},
                                 {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
  ControlNet P;
  WeightNet W;
  for (std::size_t i = 0; i < circle.size(); ++i) {
    P.push_back({circle[i] - Vec3(0, 0, 1), circle[i] + Vec3(0, 0, 1)});
    W.push_back(std::vector<double>(2, i % 2 ? w : 1.0));
  }
  return BSplineSurface(2, 1, {0, 0, 0, h, h, 2 * h, 2 * h, 3 * h, 3 * h, 4 * h, 4 * h, 4 * h}, {0, 0, 1, 1}, P, W);
}

}  // namespace ssimarch::testing
