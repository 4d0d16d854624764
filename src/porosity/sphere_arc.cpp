// Closed forms for spheres. Source: seed 001 (thesis Appendix A §A.3, l = 0).
#include "ssimarch/porosity/sphere_arc.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rg.hpp>

namespace ssimarch {

namespace {

// Carlson's integrals in double precision: Boost's default policy promotes double arguments to
// long double (x87 arithmetic, about twice the time); the duplication algorithms are accurate to
// a few ulps in double (Carlson 1995, §2), far below the profiles' tolerances.
using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

double carlson_rd(double x, double y, double z) { return boost::math::ellint_rd(x, y, z, DoublePolicy()); }
double carlson_rg(double x, double y, double z) { return boost::math::ellint_rg(x, y, z, DoublePolicy()); }

// R_F(x, y, z) and R_D(x, y, z) at once, for x, y >= 0 (at most one zero) and z > 0. Carlson's
// duplication algorithms for both (Carlson 1995, Numer. Algorithms 10, §2, algorithms 1 and 4)
// move x, y, z by the same steps, so one loop serves both: the half-chord primitive needs the pair
// at every breakpoint, hundreds of thousands of times for a bed's overlap lenses. Each step divides
// the spread of the arguments by 4; it stops when the fifth-order series is exact to rounding
// (Carlson's bound with r = 2^-53).
struct CarlsonFD {
  double rf, rd;
};

CarlsonFD carlson_rf_rd(double x, double y, double z) {
  constexpr double r = std::numeric_limits<double>::epsilon() / 2;
  const double aF0 = (x + y + z) / 3, aD0 = (x + y + 3 * z) / 5;
  const double spread = std::max({std::abs(aD0 - x), std::abs(aD0 - y), std::abs(aD0 - z), std::abs(aF0 - x),
                                  std::abs(aF0 - y), std::abs(aF0 - z)});
  static const double kF = std::pow(3 * r, -1.0 / 6), kD = std::pow(r / 4, -1.0 / 6);
  const double QF = kF * spread, QD = kD * spread;
  const double x0 = x, y0 = y;
  double aF = aF0, aD = aD0, sum = 0, pow4 = 1;  // pow4 = 4^-m
  while (!(pow4 * QF < std::abs(aF) && pow4 * QD < std::abs(aD))) {
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lam = sx * sy + sx * sz + sy * sz;
    sum += pow4 / (sz * (z + lam));
    aF = (aF + lam) / 4, aD = (aD + lam) / 4;
    x = (x + lam) / 4, y = (y + lam) / 4, z = (z + lam) / 4;
    pow4 /= 4;
  }
  CarlsonFD out{};
  {
    const double X = (aF0 - x0) * pow4 / aF, Y = (aF0 - y0) * pow4 / aF, Z = -X - Y;
    const double E2 = X * Y - Z * Z, E3 = X * Y * Z;
    out.rf = (1 - E2 / 10 + E3 / 14 + E2 * E2 / 24 - 3 * E2 * E3 / 44) / std::sqrt(aF);
  }
  {
    const double X = (aD0 - x0) * pow4 / aD, Y = (aD0 - y0) * pow4 / aD, Z = -(X + Y) / 3;
    const double XY = X * Y, Z2 = Z * Z;
    const double E2 = XY - 6 * Z2, E3 = (3 * XY - 8 * Z2) * Z, E4 = 3 * (XY - Z2) * Z2, E5 = XY * Z2 * Z;
    const double series = 1 - 3 * E2 / 14 + E3 / 6 + 9 * E2 * E2 / 88 - 3 * E4 / 22 - 9 * E2 * E3 / 52 + 3 * E5 / 26;
    out.rd = pow4 * series / (aD * std::sqrt(aD)) + 3 * sum;
  }
  return out;
}

// Eq. 9 of docs/math/cylinder_in_sphere.md: G(t) = integral over [0, t] of the half chord, at the
// angle with sin(t/2) = sn and cos^2(t/2) = c2, where the half chord is sqrt(tau2).
double half_chord_primitive(double s, double twoB, double sn, double c2, double tau2) {
  const CarlsonFD c = carlson_rf_rd(s * c2, tau2, s);
  return 2 * s * sn * (c.rf - twoB / 3 * sn * sn * c.rd);
}

}  // namespace

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
    return 16 * r * std::sqrt(s) * carlson_rg(0.0, mc, 1.0);
  }
  // Arc |t| < t0 (m > 1): reciprocal modulus k = 1/m, L = 8 r s / sqrt(2B) * kc/3 * R_D(0, 1, kc)
  // with kc = 1 - 1/m = (B - A) / (2B); kc R_D(0, 1, kc) -> 3 as kc -> 0 (no cancellation).
  const double kc = excess / twoB;
  return 8 * r * s / std::sqrt(twoB) * kc / 3 * carlson_rd(0.0, 1.0, kc);
}

namespace {

// G(t) = integral over [0, t] of h = sqrt(s - 2B sin^2(u/2)) du at the angle where h = tau, for
// 0 < tau with tau^2 between h(T)^2 and s (docs/math/cylinder_in_sphere.md §4, eq. 9):
// G = 2 s sin(t/2) (R_F(s c2, tau^2, s) - (2B/3) sin^2(t/2) R_D(s c2, tau^2, s)), c2 = cos^2(t/2).
void angle_and_integral(double s, double twoB, double excess, double tau, double& t, double& G) {
  const double sn2 = (s - tau * tau) / twoB, c2 = (excess + tau * tau) / twoB;
  const double sn = std::sqrt(sn2);
  t = 2 * std::atan2(sn, std::sqrt(c2));
  G = half_chord_primitive(s, twoB, sn, c2, tau * tau);
}

}  // namespace

double cylinder_area_in_sphere_slab(double rho, double a, double r, double below, double above) {
  // L = 2 r * integral over t in [0, T] of len(h(t)), len(h) = max(0, min(h, above) + min(h, below)),
  // h(t) = sqrt(A + B cos t) decreasing in t; len is linear in h between its breakpoints, so each
  // piece is alpha (G(t1) - G(t0)) + beta (t1 - t0) (docs/math/cylinder_in_sphere.md §4).
  const double pi = std::numbers::pi;
  if (!(r > 0) || !(a > 0)) return 0.0;
  const double s = (a - r + rho) * (a + r - rho);
  if (!(s > 0)) return 0.0;
  auto len = [&](double h) { return std::max(0.0, std::min(h, above) + std::min(h, below)); };
  const double h0 = std::sqrt(s);
  if (rho == 0) return 2 * pi * r * len(h0);
  const double twoB = 4 * r * rho, excess = (r + rho - a) * (r + rho + a);
  const double hT = excess < 0 ? std::sqrt(-excess) : 0.0;  // h at the end T of the range of t
  const double T = excess < 0 ? pi : 2 * std::atan2(std::sqrt(s / twoB), std::sqrt(std::max(0.0, excess) / twoB));
  const double GT = cylinder_area_in_sphere(rho, a, r) / (4 * r);
  std::array<double, 6> br{h0, hT};
  std::size_t n = 2;
  for (double v : {above, below, -above, -below})
    if (v > hT && v < h0) br[n++] = v;
  for (std::size_t i = 1; i < n; ++i)  // descending insertion sort (std::sort on a 6-array trips GCC 12's -Warray-bounds)
    for (std::size_t j = i; j > 0 && br[j] > br[j - 1]; --j) std::swap(br[j], br[j - 1]);
  double total = 0, t_hi = 0, G_hi = 0;  // at h = br[0] = h0: t = 0, G = 0
  for (std::size_t k = 1; k < n; ++k) {
    double t_lo = T, G_lo = GT;
    if (br[k] > hT) angle_and_integral(s, twoB, excess, br[k], t_lo, G_lo);
    const double mid = 0.5 * (br[k - 1] + br[k]);
    const double alpha = (mid < above) + (mid < below);
    const double beta = (mid < above ? 0.0 : above) + (mid < below ? 0.0 : below);
    if (br[k - 1] > br[k] && alpha * mid + beta > 0) total += alpha * (G_lo - G_hi) + beta * (t_lo - t_hi);
    t_hi = t_lo;
    G_hi = G_lo;
  }
  return 2 * r * total;
}

double half_chord_integral(double s, double twoB, double phi) {
  if (!(s > 0) || phi == 0) return 0.0;
  const double sn = std::sin(phi / 2), c2 = std::cos(phi / 2) * std::cos(phi / 2), sn2 = sn * sn;
  const double tau2 = std::max(0.0, s - twoB * sn2);
  // Internal tangency at the far side (phi = pi, A = B): both arguments vanish and the two terms of
  // eq. 9 are infinite; the limit is 2 sqrt(s) E(1) = 2 sqrt(s).
  if (s * c2 == 0 && tau2 == 0) return std::copysign(2 * std::sqrt(s), phi);
  return half_chord_primitive(s, twoB, sn, c2, tau2);
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
