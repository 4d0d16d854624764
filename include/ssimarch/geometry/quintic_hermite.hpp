// One piece of a piecewise quintic Hermite interpolant in Bézier form: position, first and
// second derivatives with respect to arc length at both ends of a piece of length h
// (Piegl & Tiller, The NURBS Book, 2nd ed., §2.4 eq. 2.9 and §3.3 for Bézier derivatives;
// derivation in docs/math/curve_spline.md §1). Coordinates are stacked vectors of any dimension
// (3D point and the unknowns of H together).
#pragma once

#include <array>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

/// The Hermite data of one end: value, d/ds and d^2/ds^2. `order` = how many derivatives are
/// known (2 at a regular point; 1 at a singular point, where only the half-branch tangent is
/// defined; 0 where nothing but the position is known).
struct HermiteEnd {
  VecX value;
  VecX first;   // d/ds (unused when order < 1)
  VecX second;  // d^2/ds^2 (unused when order < 2)
  int order = 2;
};

/// A polynomial piece on s in [0, h], stored as its six Bézier control points on u = s/h.
struct QuinticPiece {
  double h = 0;
  std::array<VecX, 6> bezier;

  /// The piece at u in [0, 1] (de Casteljau).
  VecX at(double u) const;
  /// d/ds at u in [0, 1] (the hodograph, Piegl & Tiller eq. 1.10, divided by h).
  VecX derivative(double u) const;
};

/// The piece interpolating both ends' data over a length h > 0. With order 2 at both ends it is
/// the quintic Hermite interpolant; with less data the missing conditions are replaced by
/// lowering the degree (quartic when one second derivative is missing, cubic or lower when
/// more are), degree-elevated to five (docs/math/curve_spline.md §1).
QuinticPiece quintic_hermite(const HermiteEnd& a, const HermiteEnd& b, double h);

/// The length of the piece's first three coordinates (the 3D curve): 8-point Gauss-Legendre.
double piece_length_3d(const QuinticPiece& piece);

}  // namespace ssimarch
