// Closed forms for spheres. Source: seed 001 (thesis Appendix A §A.3, l = 0).
#include "ssimarch/porosity/sphere_arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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
