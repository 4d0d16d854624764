// Meeting circles of two balls and a cylinder's crossings of them (meeting_circle.hpp). Source:
// docs/math/particle_union.md §2.
#include "meeting_circle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/porosity/polynomial_roots.hpp"

namespace ssimarch::internal {

namespace {

// Relative size below which a trigonometric polynomial's value counts as a double root.
constexpr double kRootTolerance = 1e-12;

// Roots of a trigonometric polynomial of degree 2 whose first harmonic outweighs the second,
// A = |(c1, s1)| > 4.5 B = 4.5 |(c2, s2)|, and the constant: |c0| < A - B. Turned by alpha, the
// first harmonic's phase, f = c0 + A cos u + B cos(2u - gamma) (u = psi - alpha) has exactly one
// maximum and one minimum on the circle: the zeros of f' = -(A sin u + 2B sin(2u - gamma)) lie
// where |cos u| > 4B/A, since elsewhere |A sin u| >= A sqrt(1 - 16 B^2/A^2) > 2B when A^2 > 20 B^2,
// and f' is monotone there (its derivative has the sign of -A cos u); one stretch around u = 0,
// one around pi. As f(0) >= c0 + A - B > 0 > c0 - A + B >= f(pi), f has one root in (0, pi) and one
// in (-pi, 0): with t = tan(u/2), one positive and one negative root of the quartic
// P = (1 + t^2)^2 f, whose value at 0 is positive and whose leading coefficient is negative. Each
// is found by Newton's method kept inside a bracket, started at the first harmonic's root
// t = +-sqrt((A + c0) / (A - c0)): the quartic's general isolation (real_roots) is not needed.
// False where the conditions do not hold with a margin for rounding.
bool dominant_harmonic_roots(double c0, double c1, double s1, double c2, double s2, std::array<TrigRoot, 4>& out) {
  const double A = std::hypot(c1, s1), B = std::hypot(c2, s2);
  if (!(A > 4.5 * B) || !(A - B - std::abs(c0) > 1e-9 * A)) return false;
  const double ca = c1 / A, sa = s1 / A, c2a = ca * ca - sa * sa, s2a = 2 * sa * ca;
  const double C2 = c2 * c2a + s2 * s2a, S2 = s2 * c2a - c2 * s2a;
  const double p[5] = {c0 + A + C2, 4 * S2, 2 * c0 - 6 * C2, -4 * S2, c0 - A + C2};
  const double t0 = std::sqrt((A + c0) / (A - c0));
  for (int k = 0; k < 2; ++k) {
    const double sign = k == 0 ? 1.0 : -1.0;
    // Bracket [lo, hi] on the side `sign`: P(lo) > 0 > P(hi), hi doubled until P changes sign
    // (P(t) ~ p[4] t^4 < 0 for large |t|, so the doubling ends).
    double lo = 0, hi = sign * (2 * t0 + 1);
    while (internal::poly_eval(p, 4, hi) >= 0) lo = hi, hi *= 2;
    double t = sign * t0;
    if (!(std::min(lo, hi) < t && t < std::max(lo, hi))) t = (lo + hi) / 2;
    // Each step lands inside the bracket and shrinks it, or halves it: the loop ends once the step
    // or the bracket reaches rounding.
    for (;;) {
      const double v = internal::poly_eval(p, 4, t), dv = internal::poly_deriv(p, 4, t);
      if (v == 0) break;
      (v > 0 ? lo : hi) = t;
      double next = dv != 0 ? t - v / dv : (lo + hi) / 2;
      if (!(std::min(lo, hi) < next && next < std::max(lo, hi))) next = (lo + hi) / 2;
      const double eps = 4 * std::numeric_limits<double>::epsilon() * std::abs(t);
      const bool done = std::abs(next - t) <= eps || std::abs(hi - lo) <= eps;
      t = next;
      if (done) break;
    }
    const double q = 1 + t * t, cu = (1 - t * t) / q, su = 2 * t / q;
    out[static_cast<std::size_t>(k)] = {cu * ca - su * sa, su * ca + cu * sa};
  }
  return true;
}

}  // namespace

// Real roots psi of c0 + c1 cos psi + s1 sin psi + c2 cos 2psi + s2 sin 2psi through
// t = tan(psi'/2) after turning psi' = psi - phi by a quarter turn phi = k pi/2
// so that psi' = pi (t = infinity) falls where the polynomial is largest in size, never on a root.
// Every cosine and sine there is rational in t and the quarter turns, so no angle is formed.
int trig2_roots(double c0, double c1, double s1, double c2, double s2, std::array<TrigRoot, 4>& out) {
  // cos, sin of k pi/2 and of psi = k pi/2 + pi (where psi' = pi lands), k = 0..3.
  constexpr double kc[4] = {1, 0, -1, 0}, ks[4] = {0, 1, 0, -1};
  // No root where the constant outweighs both harmonics at their largest (the common case of a
  // circle that a cylinder does not reach); the margin keeps rounding's near-tangencies to the solver.
  if (std::abs(c0) > (1 + 1e-9) * (std::hypot(c1, s1) + std::hypot(c2, s2))) return 0;
  if (dominant_harmonic_roots(c0, c1, s1, c2, s2, out)) return 2;
  int turn = 0;
  double best = -1;
  for (int k = 0; k < 4; ++k) {
    const double cp = -kc[k], sp = -ks[k], c2p = cp * cp - sp * sp, s2p = 2 * sp * cp;
    const double v = std::abs(c0 + c1 * cp + s1 * sp + c2 * c2p + s2 * s2p);
    if (v > best) best = v, turn = k;
  }
  if (!(best > 0)) return 0;
  const double cf = kc[turn], sf = ks[turn], c2f = cf * cf - sf * sf, s2f = 2 * sf * cf;
  const double c1r = c1 * cf + s1 * sf, s1r = s1 * cf - c1 * sf;
  const double c2r = c2 * c2f + s2 * s2f, s2r = s2 * c2f - c2 * s2f;
  // (1 + t^2)^2 times each term (cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2)).
  const double c[5] = {c0 + c1r + c2r, 2 * s1r + 4 * s2r, 2 * c0 - 6 * c2r, 2 * s1r - 4 * s2r, c0 - c1r + c2r};
  const RealRoots<double> roots = real_roots(c, 4, kRootTolerance);
  for (int k = 0; k < roots.count; ++k) {
    const double t = roots.x[k], q = 1 + t * t, cr = (1 - t * t) / q, sr = 2 * t / q;
    out[static_cast<std::size_t>(k)] = {cr * cf - sr * sf, sr * cf + cr * sf};
  }
  return roots.count;
}

bool meet_circle(const Particle& p, const Particle& q, MeetCircle& m) {
  const Vec3 d = q.centre - p.centre;
  const double D = d.norm(), a = p.radius(), b = q.radius();
  if (!(D > 0) || D >= a + b || D <= std::abs(a - b)) return false;
  const Vec3 n = d / D;
  const double t = (D * D + a * a - b * b) / (2 * D);
  m.rho = std::sqrt(std::max(0.0, (a - t) * (a + t)));
  m.c = p.centre + t * n;
  m.e1 = n.unitOrthogonal();
  m.e2 = n.cross(m.e1);
  return true;
}

std::array<double, 5> planar_radius2(const MeetCircle& m) {
  const double Px = m.c.x(), Py = m.c.y();
  const double Ux = m.rho * m.e1.x(), Uy = m.rho * m.e1.y(), Vx = m.rho * m.e2.x(), Vy = m.rho * m.e2.y();
  const double UU = Ux * Ux + Uy * Uy, VV = Vx * Vx + Vy * Vy, UV = Ux * Vx + Uy * Vy;
  return {Px * Px + Py * Py + (UU + VV) / 2, 2 * (Px * Ux + Py * Uy), 2 * (Px * Vx + Py * Vy), (UU - VV) / 2, UV};
}

void meet_angles(const MeetCircle& m, const std::array<double, 5>& f, double r, std::vector<double>& out) {
  std::array<TrigRoot, 4> psi{};
  const int n = trig2_roots(f[0] - r * r, f[1], f[2], f[3], f[4], psi);
  for (int k = 0; k < n; ++k) {
    const Vec3 p = meet_point(m, psi[static_cast<std::size_t>(k)]);
    out.push_back(std::atan2(p.y(), p.x()));
  }
}

void meeting_circles(const OverlapGroup& g, std::vector<MeetCircle>& out) {
  auto member = [&](std::size_t k) -> const Particle& { return k == 0 ? g.particle : g.earlier[k - 1]; };
  const std::size_t n = g.earlier.size() + 1;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      MeetCircle m;
      if (member(a).length == 0 && member(b).length == 0 && meet_circle(member(a), member(b), m)) out.push_back(m);
    }
}

}  // namespace ssimarch::internal
