// Closed forms for spheres. Source: seed 001 (thesis Appendix A §A.3, l = 0).
#include "ssimarch/porosity/sphere_arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rg.hpp>

namespace ssimarch {

double circle_sphere_arc(const Vec3& c, double diameter, double z, double r) {
  const double a = diameter / 2;
  const double dz = z - c.z();
  const double s2 = a * a - dz * dz;
  if (s2 < 0) return 0.0;
  const double rho = std::hypot(c.x(), c.y());
  const double pi = std::numbers::pi;
  if (rho == 0.0) return r * r <= s2 ? 2 * pi * r : 0.0;
  const double cosa = (r * r + rho * rho - s2) / (2 * r * rho);
  if (cosa >= 1) return 0.0;
  if (cosa <= -1) return 2 * pi * r;
  return 2 * r * std::acos(cosa);
}

double cylinder_area_in_sphere(double rho, double a, double r) {
  // L = r * integral of the chord 2 sqrt(A + B cos t) over the angles t where it is real, with
  // A = a^2 - r^2 - rho^2, B = 2 r rho; t = 2 phi turns it into a Legendre integral of modulus
  // m = 2B / (A + B) (docs/math/cylinder_in_sphere.md, eqs. 3-6).
  const double pi = std::numbers::pi;
  if (!(r > 0) || !(a > 0)) return 0.0;
  const double s = (a - r + rho) * (a + r - rho);  // A + B = a^2 - (r - rho)^2, factored: no cancellation
  if (!(s > 0)) return 0.0;
  if (rho == 0) return 4 * pi * r * std::sqrt(s);  // the chord 2 sqrt(a^2 - r^2) all around
  const double twoB = 4 * r * rho;
  const double excess = (r + rho - a) * (r + rho + a);  // B - A: > 0 when the circle leaves the shadow
  if (excess <= 0) {
    // Whole circle inside the shadow (m <= 1): L = 8 r sqrt(s) E(m), E(m) = 2 R_G(0, 1 - m, 1).
    const double mc = -excess / s;  // 1 - m = (A - B) / (A + B)
    return 16 * r * std::sqrt(s) * boost::math::ellint_rg(0.0, mc, 1.0);
  }
  // Arc |t| < t0 (m > 1): reciprocal modulus k = 1/m, L = 8 r s / sqrt(2B) * kc/3 * R_D(0, 1, kc)
  // with kc = 1 - 1/m = (B - A) / (2B); kc R_D(0, 1, kc) -> 3 as kc -> 0 (no cancellation).
  const double kc = excess / twoB;
  return 8 * r * s / std::sqrt(twoB) * kc / 3 * boost::math::ellint_rd(0.0, 1.0, kc);
}

double disk_disk_area(double r1, double r2, double d) {
  const double pi = std::numbers::pi;
  if (r1 <= 0 || r2 <= 0) return 0.0;
  if (d >= r1 + r2) return 0.0;
  if (d <= std::abs(r1 - r2)) {
    const double m = std::min(r1, r2);
    return pi * m * m;
  }
  // Sum of the two circular segments cut by the common chord.
  const double c1 = std::clamp((d * d + r1 * r1 - r2 * r2) / (2 * d * r1), -1.0, 1.0);
  const double c2 = std::clamp((d * d + r2 * r2 - r1 * r1) / (2 * d * r2), -1.0, 1.0);
  const double a1 = std::acos(c1), a2 = std::acos(c2);
  return r1 * r1 * (a1 - std::sin(2 * a1) / 2) + r2 * r2 * (a2 - std::sin(2 * a2) / 2);
}

}  // namespace ssimarch
