// Named tolerances of the exact porosity module. Every field states the inequality it enters and its
// unit; the defaults are the documented ones (docs/porosity.md, "Tolerances").
#pragma once

namespace ssimarch {

/// Tolerances of the circle-spherocylinder kernel (seed 001, thesis Appendix A §A.6;
/// docs/math/circle_spherocylinder.md §1).
/// The kernel's length scale s is sqrt(r^2 + z^2 + |r_i|^2 + sigma^2/4 + l^2) (model length): all
/// polynomial coefficients are sums of products of two such lengths, so their rounding error is
/// about eps * s^2.
struct KernelTolerances {
  /// A polynomial coefficient c (units length^2) is taken as zero when |c| <= coefficient * s^2
  /// (the seed's "nullity tolerance", A.6). Dimensionless; default 4e-15 (about 18 eps, just above
  /// the rounding error of the coefficients). Larger values lose near-tangent arcs at theta = pi:
  /// an arc whose polynomial minimum is below the tolerance has half-angle at most about
  /// sqrt(coefficient * s^2 / f''), so it is reported as a tangency (length 0).
  double coefficient = 4e-15;
  /// A crossing angle theta with theta + pi <= angle is mapped to pi, and a crossing with
  /// |theta - pi| <= angle counts as "pi in Theta" (A.63). Radians; default 1e-12.
  double angle = 1e-12;
  /// A critical point x_c of a polynomial with |p(x_c)| <= root * sum|c_i||x_c|^i is a double
  /// root (tangency). Dimensionless; default 1e-14 (about 50 eps, the rounding bound of Horner).
  double root = 1e-14;
  /// Crossings with |lambda| <= l/2 + junction * s belong to the cylindrical part; the caps take
  /// only lambda > l/2 + junction * s (resp. < -l/2 - junction * s), so that a crossing on the
  /// cylinder-cap junction is counted exactly once. Dimensionless; default 1e-10.
  double junction = 1e-10;
  /// Coaxial / cap-section special cases (A.14, A.38, A.52) apply when the horizontal offsets
  /// and |r - sigma/2| are <= special * s. Dimensionless; default 1e-12.
  double special = 1e-12;
};

}  // namespace ssimarch
