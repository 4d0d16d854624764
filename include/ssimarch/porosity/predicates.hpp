// Case decisions of the circle-spherocylinder kernel, separated from the length construction and
// templated on the scalar so tests can rerun them in long double and check that the same case is
// chosen (style.md 3.8). Source: seed 001 (thesis Appendix A §A.2-A.5).
#pragma once

#include <cmath>

namespace ssimarch {

/// Part of the spherocylinder surface a point or crossing belongs to, by its axial coordinate lambda.
enum class SpherocylinderPart { kMinusCap, kCylinder, kPlusCap };

/// Region rule of A.61/A.65 with the junction band of KernelTolerances::junction: lambda within
/// l/2 + band counts as cylinder (A.27), beyond it as the caps (A.45, A.57).
template <class T>
inline SpherocylinderPart piece_of(T lambda, T half_length, T band) {
  if (lambda > half_length + band) return SpherocylinderPart::kPlusCap;
  if (lambda < -half_length - band) return SpherocylinderPart::kMinusCap;
  return SpherocylinderPart::kCylinder;
}

/// The seed's nullity test for a polynomial coefficient (§A.6): |c| <= tol.
template <class T>
inline bool negligible(T c, T tol) {
  return std::abs(c) <= tol;
}

/// Whether the circle point at theta is inside the solid, from the region value f (A.62/A.66):
/// f > 0 inside, f < 0 outside.
template <class T>
inline bool region_inside(T f) {
  return f > T(0);
}

/// Crossing count decision of A.60: only 0, 2 and 4 crossings describe closed arcs.
inline bool consistent_count(int n) { return n == 0 || n == 2 || n == 4; }

/// Whether theta = pi is in Theta (A.63): the largest crossing lies within tol of pi.
template <class T>
inline bool pi_in_crossings(T theta_last, T pi, T tol) {
  return std::abs(theta_last - pi) <= tol;
}

}  // namespace ssimarch
