// Independent brute-force references for the porosity tests: they use only the point-in-solid test
// (distance to the axis segment <= sigma/2), never the seed's algebra.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "ssimarch/porosity/circle_spherocylinder.hpp"

namespace ssimarch::testing {

/// Length of the circle (r, z) inside the particle: the margin g(theta) = sigma/2 - dist is sampled
/// at n points; every sign change is refined by bisection to double resolution, every sampled local
/// extremum near zero is refined by golden-section search (so pairs of close crossings between two
/// samples are not missed), and the arcs between all crossings are classified at their midpoints.
/// The same for any solid given by its margin g(theta) at the circle's points (> 0 inside).
template <class Margin>
double brute_arc_length_of(Margin&& g, double r, int n = 4096) {
  const double pi = std::numbers::pi;
  auto bisect = [&](double lo, double hi) {
    double glo = g(lo);
    for (int it = 0; it < 200 && hi - lo > 1e-16 * std::max(1.0, std::abs(lo)); ++it) {
      const double m = (lo + hi) / 2, gm = g(m);
      if ((gm > 0) == (glo > 0)) {
        lo = m;
        glo = gm;
      } else {
        hi = m;
      }
    }
    return (lo + hi) / 2;
  };
  // Periodic sampling (sample n is sample 0 shifted by 2 pi), started off any special angle.
  std::vector<double> th(n + 1), gv(n + 1);
  for (int k = 0; k < n; ++k) {
    th[k] = -pi + 2 * pi * (k + 0.318309886) / n;
    gv[k] = g(th[k]);
  }
  th[n] = th[0] + 2 * pi;
  gv[n] = gv[0];
  std::vector<double> roots;
  for (int k = 0; k < n; ++k)
    if ((gv[k] > 0) != (gv[k + 1] > 0)) roots.push_back(bisect(th[k], th[k + 1]));
  // Local extrema that might hide a pair of crossings.
  for (int k = 0; k < n; ++k) {
    const int km = (k + n - 1) % n, kp = (k + 1) % n;
    const bool is_max = gv[k] >= gv[km] && gv[k] >= gv[kp] && gv[k] <= 0;
    const bool is_min = gv[k] <= gv[km] && gv[k] <= gv[kp] && gv[k] > 0;
    if (!is_max && !is_min) continue;
    double lo = th[k] - 2 * pi / n, hi = th[k] + 2 * pi / n;
    const double sgn = is_max ? 1.0 : -1.0;
    const double gr = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 120; ++it) {
      const double a = hi - gr * (hi - lo), b = lo + gr * (hi - lo);
      if (sgn * g(a) > sgn * g(b)) hi = b; else lo = a;
    }
    const double te = (lo + hi) / 2, ge = g(te);
    if ((is_max && ge > 0) || (is_min && ge <= 0)) {
      roots.push_back(bisect(th[k] - 2 * pi / n, te));
      roots.push_back(bisect(te, th[k] + 2 * pi / n));
    }
  }
  std::sort(roots.begin(), roots.end());
  if (roots.empty()) return g(0.0) > 0 ? 2 * pi * r : 0.0;
  double total = 0;
  for (std::size_t k = 0; k < roots.size(); ++k) {
    const double lo = roots[k], hi = k + 1 < roots.size() ? roots[k + 1] : roots[0] + 2 * pi;
    if (hi > lo && g((lo + hi) / 2) > 0) total += hi - lo;
  }
  return total * r;
}

inline double brute_arc_length(const SpherocylinderT<double>& s, double z, double r, int n = 4096) {
  return brute_arc_length_of([&](double t) { return inside_margin(s, Vec3(r * std::cos(t), r * std::sin(t), z)); }, r,
                             n);
}

/// Length of the circle (r, z) inside the union of the particles: the largest margin of any.
inline double brute_union_arc_length(const std::vector<SpherocylinderT<double>>& ps, double z, double r, int n = 4096) {
  return brute_arc_length_of(
      [&](double t) {
        const Vec3 p(r * std::cos(t), r * std::sin(t), z);
        double m = -std::numeric_limits<double>::infinity();
        for (const auto& s : ps) m = std::max(m, inside_margin(s, p));
        return m;
      },
      r, n);
}

}  // namespace ssimarch::testing
