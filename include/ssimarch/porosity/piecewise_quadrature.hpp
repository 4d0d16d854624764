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

namespace ssimarch {

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
  auto find_breaks = [&](double lo, double hi, int n) {
    std::vector<double> xs(n + 1);
    std::vector<long> ss(n + 1);
    for (int k = 0; k <= n; ++k) {
      xs[k] = k == n ? hi : lo + (hi - lo) * k / n;
      ss[k] = sig(xs[k]);
    }
    out.evaluations += n + 1;
    for (int k = 0; k < n; ++k) refine(refine, xs[k], ss[k], xs[k + 1], ss[k + 1]);
  };
  find_breaks(a, b, coarse);
  auto merged_breaks = [&] {
    std::sort(breaks.begin(), breaks.end());
    std::vector<double> m;
    for (double x : breaks)
      if (m.empty() || x - m.back() > merge) m.push_back(x);
    if (b - m.back() <= merge) m.pop_back();
    m.push_back(b);
    return m;
  };
  std::vector<double> pieces = merged_breaks();
  const double total = b - a;
  // A piece that does not converge may hide a pair of changes between two coarse samples: sample
  // it finer once and integrate its sub-pieces.
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    const double lo = pieces[k], hi = pieces[k + 1];
    if (!(hi > lo)) continue;
    const double tol = abs_tol * (hi - lo) / total;
    QuadResult q = integrate_sqrt_ends(value, lo, hi, tol);
    if (q.status != QuadStatus::kConverged) {
      breaks.assign({lo});
      find_breaks(lo, hi, 4 * coarse);
      const std::vector<double> sub = [&] {
        std::sort(breaks.begin(), breaks.end());
        std::vector<double> m;
        for (double x : breaks)
          if (m.empty() || x - m.back() > merge) m.push_back(x);
        if (hi - m.back() <= merge) m.pop_back();
        m.push_back(hi);
        return m;
      }();
      if (sub.size() > 2) {
        QuadResult r;
        r.evaluations = q.evaluations;
        for (std::size_t j = 0; j + 1 < sub.size(); ++j)
          r += integrate_sqrt_ends(value, sub[j], sub[j + 1], tol * (sub[j + 1] - sub[j]) / (hi - lo));
        q = r;
      }
    }
    out += q;
  }
  return out;
}

}  // namespace ssimarch
