// The control data of a spline surface as its source gave it (a scene's "bspline" / "bezier",
// a STEP B-spline surface): what a CAD writer needs to write the surface back
// (step/writer.hpp). The surface classes (surface/bspline_surface.hpp, bezier_patch.hpp)
// keep the net only in their evaluation form.
#pragma once

#include <vector>

#include "ssimarch/surface/bezier_patch.hpp"

namespace ssimarch {

struct SplineSurfaceData {
  int degree_u = 0, degree_v = 0;
  std::vector<double> knots_u, knots_v;  // a Bezier patch: degree + 1 zeros, degree + 1 ones
  ControlNet points;                     // [i][j], i along u
  WeightNet weights;                     // empty: polynomial
};

}  // namespace ssimarch
