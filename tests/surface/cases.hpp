// Surfaces of every kind, at general positions and orientations, with sample points, shared by
// the surface tests.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "ssimarch/surface/surface.hpp"

namespace ssimarch::testing {

struct SurfaceCase {
  std::string name;
  std::function<Surface()> make;
  /// Regular interior parameter points (away from poles, apexes and capsule joins by > 1e-3).
  std::vector<std::array<double, 2>> uv;
  /// Points on the surface for surfaces without a parametric form.
  std::vector<Vec3> xyz;
  /// |grad f| = 1 on the surface (documented in the type's header).
  bool unit_gradient = false;
  /// Sign of (parametric normal . grad f) on the samples: +1, -1, or 0 where it varies.
  int normal_sign = 0;
};

/// Every surface kind (primitives, both expression forms, Bezier and B-spline, rational too).
std::vector<SurfaceCase> all_surface_cases();

}  // namespace ssimarch::testing

#include <ostream>
namespace ssimarch::testing {
inline void PrintTo(const SurfaceCase& c, std::ostream* os) { *os << c.name; }
}  // namespace ssimarch::testing
