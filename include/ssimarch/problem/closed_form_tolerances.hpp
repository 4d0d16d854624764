// Every tolerance of the closed-form sections (module analytic/, docs/math/closed_form_quadrics.md),
// in one place beside problem/singular_tolerances.hpp, each with its unit and why it has its
// value. Like those, they decide "tangential" (a double root, a touching point) and "degenerate"
// (a member of a pencil of rank < 3); all are relative, so scale-free. The last one is the
// primitives' implicit forms standing in for their parametric forms (start/patch_exclusion).
#pragma once

#include <algorithm>
#include <limits>

namespace ssimarch {

/// Relative size (of the largest coefficient of a plane conic or of the axial polynomial of two
/// coaxial surfaces, for their shape: a vanishing eigenvalue or leading term, a circle; of the
/// terms of the discriminant Delta along the rulings, for a double root of Delta) at or below
/// which a closed-form section counts it as zero. Plane sections and coaxial surfaces do not
/// decide tangency by it (a gap of 1e-10 of the model size is far above double precision): they
/// measure the gap in model units and compare it with contact_gap_tolerance below. The coefficients come from a few products of the inputs, so
/// they carry ~1e-15 relative rounding; 1e-10 leaves five orders of margin and is the order at
/// which kCurveJetRankTolerance stops trusting the jets of a near-tangency. Dimensionless;
/// default 1e-10. (Was in analytic/.)
inline constexpr double kClosedFormDegeneracy = 1e-10;

/// Rounding of a closed form's gap (units of DBL_EPSILON x the model size): the coefficients of a
/// section are products of a few inputs of size ~scale, so a gap computed from them carries a few
/// eps x scale; 64 is the margin of march/model_size.hpp's step floor (64 eps scale).
/// Dimensionless; default 64.
inline constexpr double kClosedFormGapRounding = 64;

/// Gap (model units) at or below which two surfaces of a closed form touch rather than cross or
/// miss (plane sections: the distance the plane must move along its normal to become tangent to
/// the quadric; coaxial surfaces: the distance between them along the axis at a pole, or across
/// a double circle): the corrector tolerance (TraceOptions::tolerance, model units, default 1e-12:
/// a point within it of both surfaces is on the curve, so a contact within it is a contact), but
/// never below the rounding of the gap, kClosedFormGapRounding eps scale.
inline double contact_gap_tolerance(double tolerance, double scale) {
  return std::max(tolerance, kClosedFormGapRounding * std::numeric_limits<double>::epsilon() * scale);
}

/// Relative rounding of a discriminant b^2 - ac formed from coefficients that carry ~1e-15
/// relative error each: a negative discriminant within kDiscriminantRounding (b^2 + |ac|) is a
/// double root (a plane through a cone's apex: the gap is exactly 0, its discriminant rounds to
/// either sign). Not a tolerance of the geometry. Dimensionless; default 1e-12.
inline constexpr double kDiscriminantRounding = 1e-12;

/// Delta''/2 at a double root of the discriminant along the rulings, relative to Delta's scale,
/// above which the closed form reports the root as an ordinary node itself (analytic/
/// ruled_crossing.hpp: the branches' slopes differ by sqrt(Delta''/2) / |a|); at or below it the
/// point (a tacnode or higher contact, or a node too flat to tell from one) goes to the general
/// classifier. A root of multiplicity 4 is found by bisection of Delta' ~ u^3 only to
/// u ~ (1e-16)^(1/3) ~ 5e-6, where Delta''/2 ~ 6 u^2 ~ 1e-10 of the scale; 1e-6 leaves four
/// orders. Dimensionless; default 1e-6.
inline constexpr double kRuledNodeSeparation = 1e-6;

/// Magnitude of the next-smallest eigenvalue of a singular member of a quadric pencil (scaled to
/// unit largest entry), and of the semi-axes' eigenvalues of its section ellipse relative to the
/// conic's largest entry, above which the member counts as of rank exactly 3 (a cone or cylinder,
/// analytic/quadric_pencil.hpp) and its ellipse as proper; at or below it the member is taken as
/// a plane pair or too close to one to parametrise, and the next member (or the tracer) answers.
/// Dimensionless; default 1e-6 (five orders above kClosedFormDegeneracy, which the smallest one
/// must meet).
inline constexpr double kPencilRankGap = 1e-6;

/// |w| of a pencil member's unit vertex (homogeneous) relative to |xyz| at or below which the
/// vertex is at infinity for choosing the axis (a cylinder; its axis is then the vertex's
/// direction) — the rulings keep the vertex as it is, so the choice costs no accuracy.
/// Dimensionless; default 1e-9.
inline constexpr double kPencilFiniteVertex = 1e-9;

/// Largest first-order distance (model units, times max(1, scale)) of a point of a pencil
/// section from the second quadric: the points are computed on the first quadric and a cone or
/// cylinder of the pencil, so this checks that the member was found to rounding (otherwise the
/// answer is declined and the pair traced). Default 1e-12, the residual every closed form promises.
inline constexpr double kPencilResidual = 1e-12;

/// Gap (relative to the problem's scale) and sine of the angle between the normals at or below
/// which a double root of the discriminant along the rulings is taken as the singular point it
/// stands for (else the closed form declines and the pair is traced); the tracer's
/// locate_singular_point converges to 1e-10 (LocateOptions::gap_tolerance) and 1e-6
/// (sine_tolerance), and a double root found by bisection is much closer. Dimensionless; default 1e-7.
inline constexpr double kClosedFormCrossing = 1e-7;

/// Relative difference between two quadratures of a closed-form curve's length (Gauss-Legendre on
/// n and 2n pieces; the trapezoidal rule on N / 2 and N nodes of a whole loop) at or below which
/// the finer one is taken: lengths are promised to 1e-12 relative, and both rules converge
/// geometrically on these analytic integrands, so the finer one's error is far below the
/// difference. Not smaller: within ~1e-2 of a loop's turning points |dX/dphi| carries rounding
/// noise of ~1e-13 relative (sqrt of a Delta formed with cancellation), so finer rules, which put
/// nodes there, stop agreeing below that (the old 1e-14 doubled Gauss-Legendre into the noise:
/// 1e-11 errors on narrow loops). Dimensionless; default 5e-13 (was 1e-14).
inline constexpr double kClosedFormLengthTolerance = 5e-13;

/// Gap (radians) below which the eigenvalue angles of a trigonometric polynomial's companion
/// matrix (analytic/trig_polynomial.hpp) count as one cluster of roots: a real root of
/// multiplicity m moves by ~(eps kappa)^(1/m) under the eigensolver's backward error (kappa: the
/// coefficients' spread), ~1e-8 for m = 2 and ~6e-6 for m = 3 (the most the derivative of a
/// degree-2 discriminant can have: a 4-fold root of its derivative would give it a nonzero mean),
/// so 1e-4 keeps a cluster whole with an order to spare; two distinct sign changes closer than
/// this are seen as their cluster's net change (the 96-point grid this replaced saw 0.065).
/// Radians; default 1e-4.
inline constexpr double kTrigRootCluster = 1e-4;

/// How far (relative to the problem's scale, model units) a primitive's implicit value at a point
/// of its own parametric form may be from 0: the two forms are one shape computed through the
/// same stored frame, which is orthonormal to a few ulps, so f(F(u, v)) is a few 1e-16 of the
/// size (the implicit forms are normalised to a distance to first order). The interval search of
/// a parametric-parametric pair excludes a patch of F whose enclosure of f_G misses
/// [-slack, slack] (start/patch_exclusion.hpp); 1e-9 leaves six orders above that rounding
/// and costs nothing in exclusion (a patch is excluded when it misses G by far more).
/// Dimensionless; default 1e-9.
inline constexpr double kImplicitFormSlack = 1e-9;

}  // namespace ssimarch
