// Evaluation kernels shared by Bezier patches and B-spline surfaces, generic in the parameter's
// number type T (double or jets) while knots stay double. Points are homogeneous D-tuples
// (D = 3 polynomial, D = 4 rational: (w x, w y, w z, w)).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace ssimarch::internal {

/// The working points of one de Casteljau / de Boor evaluation, without a heap allocation per
/// call (issue 12: the marching loop evaluates surfaces at every corrector iteration). Up to
/// kInlineBytes of points live in the object itself (8 points of degree 7 for double and
/// first-order jets; fewer for high-order jets, whose points are large), beyond that on the heap:
/// only degrees far above CAD practice or very high-order jets pay for an allocation.
template <class T, std::size_t D>
class PointScratch {
 public:
  static constexpr std::size_t kInlineBytes = 8192;
  static constexpr std::size_t kInline = std::min<std::size_t>(8, kInlineBytes / sizeof(std::array<T, D>));

  explicit PointScratch(std::size_t n) : n_(n) {
    if (n_ > kInline) heap_.resize(n_);
  }
  std::span<std::array<T, D>> span() {
    return n_ <= kInline ? std::span<std::array<T, D>>(inline_.data(), n_) : std::span<std::array<T, D>>(heap_);
  }
  std::array<T, D>& operator[](std::size_t i) { return span()[i]; }

 private:
  std::size_t n_;
  std::array<std::array<T, D>, kInline == 0 ? 1 : kInline> inline_;
  std::vector<std::array<T, D>> heap_;
};

/// Index k of the knot span [knots[k], knots[k+1]) containing t, restricted to the domain spans
/// degree <= k < n_ctrl (t below the domain gives the first span, t at or above its end the
/// last one, so the end of the domain evaluates the last polynomial piece). Needs a validated
/// knot vector (BSplineSurface): non-decreasing, size n_ctrl + degree + 1, non-empty domain, no
/// multiplicity above degree + 1.
int find_span(std::span<const double> knots, int degree, int n_ctrl, double t);

/// de Casteljau's algorithm (Farin, "Curves and Surfaces for CAGD", 5th ed., sec. 4.2): on
/// return d[0] is the point of the Bezier curve with control points d at t. O(n^2) blends.
template <class T, std::size_t D>
void de_casteljau(std::span<std::array<T, D>> d, const T& t) {
  const T s = 1.0 - t;
  for (std::size_t r = 1; r < d.size(); ++r)
    for (std::size_t i = 0; i + r < d.size(); ++i)
      for (std::size_t c = 0; c < D; ++c) d[i][c] = s * d[i][c] + t * d[i + 1][c];
}

/// de Boor's algorithm (Piegl & Tiller, "The NURBS Book", 2nd ed., A3.1 / de Boor 1972): d holds
/// the p + 1 control points P[k-p..k] active on span k; on return d[p] is the curve point at t.
template <class T, std::size_t D>
void de_boor(std::span<std::array<T, D>> d, std::span<const double> knots, int p, int k, const T& t) {
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const std::size_t i = static_cast<std::size_t>(j + k - p);
      const double lo = knots[i], hi = knots[static_cast<std::size_t>(j + 1 + k - r)];
      const T alpha = (t - lo) / (hi - lo);
      const T beta = 1.0 - alpha;
      auto& dj = d[static_cast<std::size_t>(j)];
      const auto& dm = d[static_cast<std::size_t>(j - 1)];
      for (std::size_t c = 0; c < D; ++c) dj[c] = beta * dm[c] + alpha * dj[c];
    }
}

}  // namespace ssimarch::internal
