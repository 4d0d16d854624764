// Non-uniform B-spline curves of any dimension, and the exact conversion of a chain of quintic
// Bézier pieces into one (knot removal where the pieces join C2; Piegl & Tiller, The NURBS
// Book, 2nd ed., §5.4; derivation by blossoms in docs/math/curve_spline.md §2).
#pragma once

#include <vector>

#include "ssimarch/geometry/quintic_hermite.hpp"

namespace ssimarch {

/// C(t) = sum_i N_{i,p}(t) P_i on t in [knots[p], knots[n]] (n control points, n + p + 1 knots).
/// periodic: the knots continue with the period knots[n] - knots[p] and the last p control
/// points repeat the first p (the unclamped form of a closed C^(p-multiplicity) curve, as
/// STEP's closed_curve = .T. with knot_spec .UNSPECIFIED. writes it).
struct BSplineCurve {
  int degree = 5;
  bool periodic = false;
  std::vector<double> knots;
  std::vector<VecX> control_points;

  double start() const { return knots[static_cast<std::size_t>(degree)]; }
  double end() const { return knots[control_points.size()]; }
  /// The curve at t (clamped into [start, end]): de Boor's algorithm (Piegl & Tiller A3.1 form).
  VecX at(double t) const;
  /// The coordinates [first, first + count) of every control point (3D part, a p-curve).
  BSplineCurve slice(int first, int count) const;
  /// The knots as distinct values with multiplicities (STEP's form).
  void distinct_knots(std::vector<double>* values, std::vector<int>* multiplicities) const;
};

/// One B-spline of degree 5 through the pieces, piece i on [t_i, t_i + h_i] with t_0 = 0.
/// continuity[i] (0, 1 or 2): how the pieces i and i+1 (for periodic, the last and the first at
/// i = n-1) join in the spline's parameter. 2: equal first and second derivatives, so two of the
/// five copies of their common knot are removed exactly (multiplicity 3: C2); 1: equal first
/// derivatives only, one copy removed (multiplicity 4: C1; a piece at a singular point in its own
/// parameter, docs/math/curve_spline.md §1); 0: multiplicity 5 (C0).
/// periodic requires every continuity[i] == 2; the result is then the periodic form.
BSplineCurve bspline_from_pieces(const std::vector<QuinticPiece>& pieces, const std::vector<int>& continuity, bool periodic);

}  // namespace ssimarch
