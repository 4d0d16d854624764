// Viviani's curve (thesis pair 2) in its three pair kinds, and a point on it: the common case of
// the allocation tests of problem/ and march/.
#pragma once

#include <optional>
#include <stdexcept>
#include <vector>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/problem.hpp"
#include "testing/surface_pairs.hpp"

namespace ssimarch::testing {

/// Parametric cylinder and sphere, the parametric cylinder and the implicit sphere, both implicit.
inline std::vector<Problem> viviani_problems() {
  return {Problem(cylinder_f2(), sphere_g2_parametric(), PairKind::kParametricParametric),
          Problem(cylinder_f2(), sphere_g2_implicit(), PairKind::kParametricImplicit),
          Problem(sphere_g2_implicit(), cylinder_f2_implicit(), PairKind::kImplicitImplicit)};
}

/// The unknowns of the curve point at viviani(1.0), corrected onto the curve.
inline UnknownVec start_on_viviani(const Problem& P) {
  const std::optional<VecX> x = unknowns_near(P, viviani(1.0));
  if (!x) throw std::runtime_error("no unknowns near the start");
  const CorrectorResult r = gauss_newton(P, *x, CorrectorOptions{});
  if (r.status != CorrectorStatus::kConverged) throw std::runtime_error("the start is not on the curve");
  return r.x;
}

}  // namespace ssimarch::testing
