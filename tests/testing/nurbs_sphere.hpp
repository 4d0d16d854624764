// The exact rational B-spline sphere, shared by the pole and collapsed-row tests (style.md 3.12.5).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "ssimarch/surface/bspline_surface.hpp"

namespace ssimarch::testing {

// The sphere of radius R about the origin: a full circle (9 control points, 4 quarter arcs) in u
// times a half circle from pole to pole (5 control points) in v, the poles at -R a and +R a
// (a = the coordinate axis number `axis`), every control point of an edge row on its pole; u
// closes a seam.
inline BSplineSurface nurbs_sphere(double R = 1, int axis = 2) {
  const double s = std::sqrt(0.5);
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  const double wu[9] = {1, s, 1, s, 1, s, 1, s, 1};
  const double rho[5] = {0, 1, 1, 1, 0}, h[5] = {-1, -1, 0, 1, 1}, wv[5] = {1, s, 1, s, 1};
  ControlNet points(9, std::vector<Vec3>(5));
  WeightNet weights(9, std::vector<double>(5));
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 5; ++j) {
      Vec3 p;  // (circle, circle, axis) rotated so that the axis is coordinate `axis`
      p[(axis + 1) % 3] = R * rho[j] * cx[i];
      p[(axis + 2) % 3] = R * rho[j] * cy[i];
      p[axis] = R * h[j];
      points[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = p;
      weights[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = wu[i] * wv[j];
    }
  return BSplineSurface(2, 2, {0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1}, {0, 0, 0, .5, .5, 1, 1, 1}, points, weights);
}

}  // namespace ssimarch::testing
