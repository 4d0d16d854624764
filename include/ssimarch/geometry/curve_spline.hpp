// A traced branch as a B-spline with a certified distance from the true intersection curve:
// the piecewise quintic Hermite interpolant of the exact curve jets at the points (3D curve and
// the unknowns of H together), its exact conversion to a degree-5 B-spline in 3D and to one
// p-curve per parametric surface, and the a-posteriori check that refines it
// (docs/math/curve_spline.md; Piegl & Tiller, The NURBS Book, §2.4, §5.4; de Boor, A Practical
// Guide to Splines, ch. II for the Hermite error formula).
#pragma once

#include <string>
#include <vector>

#include "ssimarch/geometry/bspline_curve.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

struct CurveSplineOptions {
  /// Largest distance (model length) of the spline and of each p-curve's image from the true
  /// curve; 0 = 1e-9 * problem.scale() (the diagonal of the problem's region).
  double tolerance = 0;
  /// Halvings of one original piece before the check gives up on it (it then reports the
  /// distance it measured, above the tolerance).
  int max_halvings = 24;
};

/// Reported bound = measured maximum over the check points u = 1/4, 1/2, 3/4 of every piece
/// times this factor (docs/math/curve_spline.md §3: the leading error term's maximum over its
/// sampled values is 1 for the quintic, <= 1.11 for the lowered degrees at singular points).
inline constexpr double kSplineDeviationSafety = 1.25;

struct CurveSpline {
  /// 3D, degree 5. Parameter: the arc length from the first point, except on a piece at a
  /// singular point, whose parameter u in [0, 2h] has s = u^2 / (4h) (docs/math/curve_spline.md §1).
  BSplineCurve curve;
  /// One per parametric surface of the problem, same knots: problem.first() (u,v) first, then
  /// problem.second() (p,q) for parametric pairs; none for implicit pairs.
  std::vector<BSplineCurve> pcurves;
  double max_deviation = 0;          // the a-posteriori bound (model length)
  double tolerance = 0;              // what was asked (model length)
  bool within_tolerance = true;      // max_deviation <= tolerance
  int pieces = 0;                    // polynomial pieces after refinement
  int inserted_points = 0;           // exact curve points the refinement added
  int c0_knots = 0;                  // knots at singular points of the branch (C0 there)
  int c1_knots = 0;                  // C1 knots: where a piece at a singular point meets the next
  double length = 0;                 // arc length of the 3D spline (Gauss-Legendre per piece)
  double time_ms = 0;                // wall time of the fit and its check (steady clock)
};

/// The certified spline of a traced branch. `points`: the unknowns of H at the branch's points
/// in order (periodic ones wrapped; closed: the last point repeats the first); `tangents`: the
/// 3D unit tangent along the direction of travel at each (at a singular point, the half-branch's).
/// `half_branches` (optional, one list per point): at a singular point, the unit 3D tangents of
/// its half-branches, pointing away from it (singular/half_branches); each piece ending there
/// takes the one along its chord. Points where the curve jet is singular get a C0 knot. A closed
/// branch without singular points becomes one periodic spline. Requires at least two points.
CurveSpline fit_curve_spline(const Problem& problem, const std::vector<VecX>& points, const std::vector<Vec3>& tangents,
                             bool closed, const CurveSplineOptions& options,
                             const std::vector<std::vector<Vec3>>* half_branches = nullptr);

}  // namespace ssimarch
