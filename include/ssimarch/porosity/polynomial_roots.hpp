// Real roots of polynomials of degree <= 4 by derivative isolation: the critical points (roots of p')
// split the real line into intervals on which p is monotone, so every simple root is bracketed and
// found by safeguarded Newton-bisection. A critical point where |p| is within the rounding bound is a
// (near-)double root and is reported twice (a tangency), which keeps crossing counts even where a
// closed-form solver would return a complex pair with a tiny imaginary part
// (seed 001, thesis Appendix A §A.6).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ssimarch {

template <class T>
struct RealRoots {
  std::array<T, 4> x{};  ///< sorted ascending, repeated by multiplicity (2 for a tangency)
  int count = 0;
  void push(T v) {
    if (count < 4) x[count++] = v;
  }
};

namespace internal {

// Insertion sort for the few (<= 9) entries of these fixed arrays (std::sort trips -Warray-bounds
// false positives on them in GCC 12).
template <class T, class Less>
inline void small_sort(T* a, int n, Less less) {
  for (int i = 1; i < n; ++i) {
    T v = a[i];
    int j = i - 1;
    while (j >= 0 && less(v, a[j])) {
      a[j + 1] = a[j];
      --j;
    }
    a[j + 1] = v;
  }
}
template <class T>
inline void small_sort(T* a, int n) {
  small_sort(a, n, [](const T& x, const T& y) { return x < y; });
}

// Horner evaluation of c[0] + c[1] x + ... + c[n] x^n, with the magnitude sum for the rounding bound.
template <class T>
inline T poly_eval(const T* c, int n, T x, T* magnitude = nullptr) {
  T v = c[n];
  T m = std::abs(c[n]);
  const T ax = std::abs(x);
  for (int i = n - 1; i >= 0; --i) {
    v = v * x + c[i];
    m = m * ax + std::abs(c[i]);
  }
  if (magnitude) *magnitude = m;
  return v;
}

template <class T>
inline T poly_deriv(const T* c, int n, T x) {
  T v = T(n) * c[n];
  for (int i = n - 1; i >= 1; --i) v = v * x + T(i) * c[i];
  return v;
}

// Root of p in [lo, hi] with p(lo), p(hi) of strictly opposite signs (Newton steps kept inside the
// bracket, bisection otherwise).
template <class T>
inline T bracketed_root(const T* c, int n, T lo, T hi, T plo) {
  T x = (lo + hi) / T(2);
  for (int it = 0; it < 200; ++it) {
    const T px = poly_eval(c, n, x);
    if (px == T(0)) return x;
    if ((px < T(0)) == (plo < T(0))) {
      lo = x;
      plo = px;
    } else {
      hi = x;
    }
    const T dp = poly_deriv(c, n, x);
    T next = (dp != T(0)) ? x - px / dp : lo;
    if (!(next > lo && next < hi)) next = lo + (hi - lo) / T(2);
    const T eps = std::numeric_limits<T>::epsilon();
    if (std::abs(next - x) <= T(2) * eps * std::max(T(1), std::abs(x)) || hi - lo <= T(4) * eps * std::abs(x))
      return next;
    x = next;
  }
  return x;
}

}  // namespace internal

/// Real roots of c[0] + c[1] x + ... + c[n] x^n (1 <= n <= 4, c[n] != 0).
/// @param rel_tol a critical point x_c with |p(x_c)| <= rel_tol * sum |c_i| |x_c|^i is a double root.
template <class T>
RealRoots<T> real_roots(const T* c, int n, T rel_tol) {
  RealRoots<T> out;
  if (n == 1) {
    out.push(-c[0] / c[1]);
    return out;
  }
  // Critical points: roots of p' (degree n-1), deduplicated.
  std::array<T, 4> dc{};
  for (int i = 1; i <= n; ++i) dc[i - 1] = T(i) * c[i];
  const RealRoots<T> crit = real_roots(dc.data(), n - 1, rel_tol);
  std::array<T, 6> pts{};
  std::array<T, 6> val{};
  std::array<bool, 6> is_crit{};
  int m = 0;
  // Cauchy bound: every root lies in (-bound, bound).
  T bound = T(0);
  for (int i = 0; i < n; ++i) bound = std::max(bound, std::abs(c[i] / c[n]));
  bound = T(1) + bound;
  pts[m] = -bound;
  is_crit[m++] = false;
  for (int k = 0; k < crit.count; ++k) {
    if (m > 1 && crit.x[k] == pts[m - 1]) continue;
    pts[m] = crit.x[k];
    is_crit[m++] = true;
  }
  pts[m] = bound;
  is_crit[m++] = false;
  for (int k = 0; k < m; ++k) {
    T mag;
    val[k] = internal::poly_eval(c, n, pts[k], &mag);
    if (is_crit[k] && std::abs(val[k]) <= rel_tol * mag) val[k] = T(0);
  }
  for (int k = 0; k < m; ++k) {
    if (k > 0) {
      const bool change = (val[k - 1] < T(0) && val[k] > T(0)) || (val[k - 1] > T(0) && val[k] < T(0));
      if (change) out.push(internal::bracketed_root(c, n, pts[k - 1], pts[k], val[k - 1]));
    }
    if (is_crit[k] && val[k] == T(0)) {
      // A flat zero: even multiplicity if p keeps its sign across it (tangency), odd otherwise.
      const T left = k > 0 ? val[k - 1] : T(0);
      const T right = k + 1 < m ? val[k + 1] : T(0);
      out.push(pts[k]);
      if ((left > T(0)) == (right > T(0)) || left == T(0) || right == T(0)) out.push(pts[k]);
    }
  }
  internal::small_sort(out.x.data(), out.count);
  return out;
}

}  // namespace ssimarch
