// Quadrature of a function that is analytic between unknown breakpoints, given a "signature" that
// changes exactly at those breakpoints (for the kernel: the number of crossings on each surface part;
// a tangency changes the count and brings a square-root singularity, a crossing moving from the
// cylinder to a cap brings a curvature jump). The signature is sampled on a coarse grid, every change
// is located by bisection to the resolution of double, and each analytic piece is integrated with
// integrate_sqrt_ends. Used by the seed-kernel formulation of the profiles (docs/porosity.md,
// "Methods") and by the tests that integrate p_i(z, r) over r and z.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "ssimarch/porosity/quadrature.hpp"

namespace ssimarch::porosity {

/// Default number of coarse signature samples over the integration range.
inline constexpr int kPiecewiseCoarseSamples = 32;

/// @param value  x -> integrand
/// @param sig    x -> integer signature, constant where `value` is analytic
template <class V, class S>
QuadResult integrate_piecewise(V&& value, S&& sig, double a, double b, double abs_tol,
                               int coarse = kPiecewiseCoarseSamples) {
  QuadResult out;
  if (!(b > a)) return out;
  const double res = 4 * 2.220446049250313e-16 * std::max({std::abs(a), std::abs(b), b - a});
  std::vector<double> breaks{a};
  // Bisection on [l, r] with sig(l) = sl != sr = sig(r); finds every change that the halves expose.
  auto refine = [&](auto&& self, double l, long sl, double r, long sr) -> void {
    if (sl == sr) return;
    if (r - l <= res) {
      breaks.push_back((l + r) / 2);
      return;
    }
    const double m = (l + r) / 2;
    const long sm = sig(m);
    ++out.evaluations;
    self(self, l, sl, m, sm);
    self(self, m, sm, r, sr);
  };
  // Samples strictly inside (a, b): the ends themselves are often exactly at a tangency.
  std::vector<double> xs(coarse + 1);
  std::vector<long> ss(coarse + 1);
  for (int k = 0; k <= coarse; ++k) {
    const double t = (k + 0.5) / (coarse + 1);
    xs[k] = a + (b - a) * t;
    ss[k] = sig(xs[k]);
  }
  out.evaluations += coarse + 1;
  for (int k = 0; k < coarse; ++k) refine(refine, xs[k], ss[k], xs[k + 1], ss[k + 1]);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  const double total = b - a;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double lo = breaks[k], hi = breaks[k + 1];
    if (!(hi > lo)) continue;
    out += integrate_sqrt_ends(value, lo, hi, abs_tol * (hi - lo) / total);
  }
  return out;
}

}  // namespace ssimarch::porosity
