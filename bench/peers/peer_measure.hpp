// What the peer benchmark records of one engine's answer on one case, and how a point's distance
// from the case's surfaces is measured (the same for every engine: the ssimarch scene's surfaces).
#pragma once

#include <string>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/surface.hpp"

namespace peers {

struct Outcome {
  int curves = 0;        // curves returned
  int isolated = 0;      // isolated points returned (contact points)
  int closed = 0;        // of the curves, closed ones
  double length = 0;     // total length of the curves (model units)
  double residual = 0;   // max over sampled points of the larger distance from the two surfaces
  std::string note;      // failure or remark
};

/// Distance of p from the surface: |f| / |grad f| for implicit forms (first order, exact to
/// O(d^2)), the nearest point otherwise (closest_parameters).
double distance_to(const ssimarch::Surface& s, const ssimarch::Vec3& p);

/// max(distance to a, distance to b).
double residual(const ssimarch::Surface& a, const ssimarch::Surface& b, const ssimarch::Vec3& p);

/// Median of the times (ms).
double median(std::vector<double> t);

}  // namespace peers
