// When a start point counts as lying on a singular point (topology/start_points.cpp,
// regular_start; topology/trace_all.cpp, register_singular_start): in model units, tied to the
// corrector tolerance, never to the step length (a coarse step must not make a regular point
// 0.03 from the four-petal rose's quadruple point "singular").
#pragma once

#include <cmath>

namespace ssimarch {

/// Radius (model units) within which a start point is on the singular point located from it:
/// scale (tolerance / scale)^(1/4). Along any direction from a singular point of multiplicity m
/// the residual grows like d^m / scale^(m-1) (the local curve's lowest terms, scaled by the
/// model), so within (tolerance scale^(m-1))^(1/m) a point cannot be told from the singular
/// point by the residual the corrector drives to the tolerance; m = 4, the quadruple point, the
/// highest multiplicity the classifier names short of `multiple_point`, gives the largest such
/// radius. Default tolerance 1e-12: 0.0245 for the four-petal rose (scale 71), 0.0101 for the
/// devil's curve (scale 22), whose certified starts lie within 5e-6 of its node.
inline double singular_start_radius(double tolerance, double scale) {
  return scale * std::sqrt(std::sqrt(tolerance / scale));
}

}  // namespace ssimarch
