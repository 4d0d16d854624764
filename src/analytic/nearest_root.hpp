// The root nearest 0 of a quadratic k0 + 2 k1 h + k2 h^2, internal to analytic/: the gap (model
// units) that plane sections and coaxial surfaces compare with contact_gap_tolerance
// (docs/math/closed_form_quadrics.md, "Tangency by the gap").
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch::internal {

/// The real root of k0 + 2 k1 h + k2 h^2 = 0 of least |h| (k2 = 0: the linear root), computed
/// without cancellation (the product of the roots is k0 / k2); +infinity when there is none. A
/// discriminant k1^2 - k0 k2 negative within kDiscriminantRounding is a double root.
inline double nearest_root(double k0, double k1, double k2) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  double disc = k1 * k1 - k0 * k2;
  if (disc < 0) {
    if (disc < -kDiscriminantRounding * (k1 * k1 + std::fabs(k0 * k2))) return kNone;
    disc = 0;
  }
  const double q = -(k1 + std::copysign(std::sqrt(disc), k1));  // roots q / k2 and k0 / q
  double best = kNone;
  if (q != 0) best = k0 / q;
  if (k2 != 0 && std::fabs(q / k2) < std::fabs(best)) best = q / k2;
  if (q == 0 && k2 != 0) best = 0;  // k1 = 0 and k0 k2 = 0: a double root at 0
  return std::isfinite(best) ? best : kNone;
}

}  // namespace ssimarch::internal
