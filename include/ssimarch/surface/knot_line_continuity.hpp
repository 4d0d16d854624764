// Whether a B-spline surface is C1 across its knot lines and its closed seams (issue 27 item 2).
//
// The interval enclosures of a box across a knot line hull the one-sided derivatives of the
// pieces on either side (surface/piece_enclosure.hpp). That bounds every difference quotient of F
// where F is continuous, and of F's first derivatives (what the turning-point systems' Krawczyk
// test and the saddle boxes differentiate) only where F is C1. A knot of multiplicity m makes the
// polynomial pieces C^(p - m); a knot of multiplicity p is only C0 in general, yet the rational
// arcs CAD writes for circles (quarter arcs with double knots) are C1 there. So every knot line of
// multiplicity >= p, and every closed seam (whose two sides are two ends of the knot vector), is
// checked: with A the homogeneous point and W the weight, F_u = (A_u W - A W_u) / W^2, and at the
// line between pieces L (ending there) and R (starting there), in their boundary rows,
//
//   F_u^L = p (A_p W_(p-1) - A_(p-1) W_p) / (h_L W_p^2),   F_u^R = p (A_1 W_0 - A_0 W_1) / (h_R W_0^2)
//
// (h the pieces' widths), two rational functions of v; they agree iff the polynomials
// (A_p W_(p-1) - A_(p-1) W_p) W_0^2 / h_L and (A_1 W_0 - A_0 W_1) W_p^2 / h_R agree, compared by
// their Bernstein coefficients (Farin, "Curves and Surfaces for CAGD", 5th ed., sec. 5.8 products
// of Bernstein polynomials); likewise F itself (A_p W_0 = A_0 W_p) at a seam. Along v the same
// with columns.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "ssimarch/surface/bezier_extraction.hpp"

namespace ssimarch::internal {

/// Relative defect (to the size of the compared terms) below which a knot line counts as C1: a
/// jump of the derivative that small is the data's rounding (the weights sqrt(2)/2 of a rational
/// circle are not exact in doubles), far below the certified search's resolution (root_width
/// 1e-12, start/krawczyk.hpp).
inline constexpr double kKnotLineC1Relative = 1e-12;

struct KnotLineKink {
  char parameter = 'u';  // the knot line is u = at (or v = at)
  double at = 0;
  double defect = 0;  // the relative defect found
  bool seam = false;  // the closed seam (the two ends of a periodic direction)
  std::string describe() const;
};

/// The first knot line or closed seam across which the surface of these pieces is not C1 (a
/// knot of multiplicity < degree is C1 by construction and not checked); std::nullopt if none.
std::optional<KnotLineKink> first_kink(const BezierExtraction& pieces, std::span<const double> knots_u,
                                       std::span<const double> knots_v, bool periodic_u, bool periodic_v);

}  // namespace ssimarch::internal
