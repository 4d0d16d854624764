// Length of the part of a horizontal circle lying inside a spherocylinder.
//
// Circle: p_c(theta) = (r cos theta, r sin theta, z), theta in (-pi, pi], centred on the z axis.
// Spherocylinder: centre r_i, unit axis u, diameter sigma, length l (closed solid: all points within
// sigma/2 of the segment r_i +- (l/2) u).
// Method (seed 001: thesis Appendix A §A.2-A.5 and its flowchart, Fig. A.9, with two
// corrections): crossings with the infinite cylinder are the real roots of a quartic in
// phi = tan(theta/2) kept where |lambda| <= l/2; crossings with the two cap spheres are roots of
// quadratics kept where lambda > l/2 (resp. < -l/2); theta = pi (phi = infinity) is tested through
// the leading coefficients, and accepted only if its lambda is valid (the flowchart fix). The
// crossings are sorted, their arcs summed (A.60), and the arcs or their complement are taken by the
// sign of the region function at theta = pi (A.61-A.62) or at theta_m = (theta_1 - pi)/2 (A.63-A.66).
// Robustness beyond the seed (§A.6): near-double roots count as tangencies, a junction band
// assigns a crossing on the cylinder-cap seam to the cylinder only, and if the crossing count still
// comes out inconsistent (odd or > 4) the arcs between all candidate roots are classified one by one
// with the exact point-in-spherocylinder test (case `kFallback`).
//
// References: seed 001 (thesis Appendix A, eqs A.1-A.66, Fig. A.9); derivation and the two
// corrections in docs/math/circle_spherocylinder.md §1; reference values tests/reference/oracle.json
// (keys s001.*).
#pragma once

#include <array>

#include "ssimarch/porosity/particle.hpp"
#include "ssimarch/porosity/predicates.hpp"
#include "ssimarch/porosity/tolerances.hpp"

namespace ssimarch {

/// Which rule produced the length.
enum class ArcCase {
  kOutside,           ///< no crossing, the test point is outside: length 0
  kInside,            ///< no crossing, the test point is inside: length 2 pi r
  kArcs,              ///< 2 or 4 crossings (tangencies counted twice), arcs or their complement
  kCoaxialOnSurface,  ///< A.14: the circle lies on the cylindrical surface
  kCapSection,        ///< A.38 / A.52: the circle lies on a cap sphere
  kFallback,          ///< inconsistent crossing count: arcs classified by the point-in-solid test
};

const char* to_string(ArcCase c);

template <class T>
struct CircleSpherocylinderResult {
  ArcCase which = ArcCase::kOutside;
  T inside_length = T(0);                   ///< p_i(z, r), model length
  std::array<T, 4> crossing_angles{};       ///< sorted, in (-pi, pi]
  std::array<SpherocylinderPart, 4> crossing_pieces{};   ///< surface part of each crossing
  int count = 0;                            ///< number of valid entries in crossing_angles
  bool theta_m_test = false;                ///< A.63-A.66 decided instead of A.61-A.62
};

/// p_i(z, r): length of the circle (radius r > 0, height z) inside the spherocylinder `s`
/// (unit axis, diameter > 0, length >= 0).
template <class T>
CircleSpherocylinderResult<T> circle_spherocylinder(const SpherocylinderT<T>& s, T z, T r,
                                                    const KernelTolerances& tol = {});

/// sigma/2 minus the distance from `p` to the axis segment: > 0 strictly inside, < 0 outside.
template <class T>
T inside_margin(const SpherocylinderT<T>& s, const typename SpherocylinderT<T>::Point& p);

extern template CircleSpherocylinderResult<double> circle_spherocylinder(const SpherocylinderT<double>&, double,
                                                                         double, const KernelTolerances&);
extern template CircleSpherocylinderResult<long double> circle_spherocylinder(
    const SpherocylinderT<long double>&, long double, long double, const KernelTolerances&);
extern template double inside_margin(const SpherocylinderT<double>&, const Vec3&);
extern template long double inside_margin(const SpherocylinderT<long double>&, const SpherocylinderT<long double>::Point&);

}  // namespace ssimarch
