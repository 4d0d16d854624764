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
  // Breakpoints are located to `res`; changes closer than `merge` are one breakpoint, so that a
  // signature flickering in a rounding-sized band (a crossing exactly on a decision boundary) does
  // not shatter the range into thousands of pieces.
  const double res = 1e-12 * (b - a) + 4 * 2.220446049250313e-16 * std::max(std::abs(a), std::abs(b));
  const double merge = 1e-10 * (b - a);
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
  // Coarse samples, ends included (a change between an end and its neighbour is found as well).
  std::vector<double> xs(coarse + 1);
  std::vector<long> ss(coarse + 1);
  for (int k = 0; k <= coarse; ++k) {
    xs[k] = k == coarse ? b : a + (b - a) * k / coarse;
    ss[k] = sig(xs[k]);
  }
  out.evaluations += coarse + 1;
  for (int k = 0; k < coarse; ++k) refine(refine, xs[k], ss[k], xs[k + 1], ss[k + 1]);
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> merged;
  for (double x : breaks)
    if (merged.empty() || x - merged.back() > merge) merged.push_back(x);
  merged.push_back(b);
  breaks.swap(merged);
  const double total = b - a;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double lo = breaks[k], hi = breaks[k + 1];
    if (!(hi > lo)) continue;
    out += integrate_sqrt_ends(value, lo, hi, abs_tol * (hi - lo) / total);
  }
  return out;
}

}  // namespace ssimarch::porosity
