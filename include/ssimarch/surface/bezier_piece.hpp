// One tensor-product Bezier piece evaluated by its Taylor expansion (issue 27 item 1).
//
// A jet of F at (u0, v0) is F's Taylor polynomial there. de Casteljau or de Boor run in the jet
// type pay a truncated jet product for every blend (O(p^2 q) products of jets of 15 to 91
// coefficients); here the piece's homogeneous polynomial H is expanded at the primal point in
// doubles, and only the substitution of the argument jets into that expansion is done in jets:
//
//   H(u0 + du, v0 + dv) = sum_{a <= p, b <= q, a + b <= K} c_ab du^a dv^b,
//   c_ab = (1/(a! b!)) d^(a+b) H / du^a dv^b (u0, v0)
//
// The c_ab come from subdivision (Farin, "Curves and Surfaces for CAGD", 5th ed., sec. 5.4-5.6):
// split the piece at the point; the sub-piece on the longer side, reparametrised to [0, 1],
// has the point as an end, and its power coefficients at that end are the scaled forward
// differences C(n, k) Delta^k b_0. The sub-piece on the side of length >= 1/2 keeps the
// divisions by the length bounded by 2^k, so the expansion is as accurate as de Casteljau's
// point. Rows along v first (one curve per control row), then along u for each power of dv
// (the dv^b coefficients of the rows are themselves a Bezier curve in u).
//
// Only double and Jet<NV, K> go this way (TaylorEvaluable); interval types keep the blends in
// the interval type, whose rounding they account for.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <type_traits>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/spline_basis.hpp"

namespace ssimarch::internal {

/// A number type whose arithmetic is exact algebra of Taylor polynomials over double: the
/// piece may be expanded in doubles and the argument substituted.
template <class T>
struct TaylorEvaluable : std::false_type {};
template <>
struct TaylorEvaluable<double> : std::true_type {};
template <int NV, int K>
struct TaylorEvaluable<Jet<NV, K>> : std::true_type {};

template <class T>
struct TaylorOrder : std::integral_constant<int, 0> {};
template <int NV, int K>
struct TaylorOrder<Jet<NV, K>> : std::integral_constant<int, K> {};

/// (p + 1) x (q + 1) homogeneous control points (w x, w y, w z, w), row-major with i along u,
/// of the piece on [u_lo, u_hi] x [v_lo, v_hi].
struct BezierPieceView {
  const std::array<double, 4>* net = nullptr;
  int p = 0, q = 0;
  double u_lo = 0, u_hi = 1, v_lo = 0, v_hi = 1;
};

/// The expansion of one piece at a point: c(a, b)[k] for a <= a_max, b <= b_max(a).
template <std::size_t D>
class PieceTaylor {
 public:
  int a_max = 0;
  int b_cap = 0;  // b_max(a) = min(b_cap, order - a)
  int order = 0;
  int b_max(int a) const { return std::min(b_cap, order - a); }
  std::array<double, D>& operator()(int a, int b) { return c_[static_cast<std::size_t>(a * (b_cap + 1) + b)]; }
  const std::array<double, D>& operator()(int a, int b) const {
    return c_[static_cast<std::size_t>(a * (b_cap + 1) + b)];
  }
  void resize(int a, int b, int k) {
    a_max = a;
    b_cap = b;
    order = k;
    c_.resize(static_cast<std::size_t>((a + 1) * (b + 1)));
  }

 private:
  std::vector<std::array<double, D>> c_;
};

/// Taylor coefficients out[k] = B^(k)(t) / k! (k = 0..order, order <= n) of the degree-n
/// Bezier curve with control points w[0..n], in powers of the curve's own parameter; w is
/// overwritten (subdivision and differences in place).
template <std::size_t D>
void bezier_curve_taylor(std::span<std::array<double, D>> w, double t, int order, std::array<double, D>* out) {
  const int n = static_cast<int>(w.size()) - 1;
  const double s = 1.0 - t;
  const bool right = t <= 0.5;
  if (right) {
    // de Casteljau in place leaves w[i] = b_i^(n-i): the control points of the piece on [t, 1].
    de_casteljau<double, D>(w, t);
  } else {
    // In place from the right, w[i] becomes b_0^i: the piece on [0, t], then reversed so that
    // both sides start at the point.
    for (int r = 1; r <= n; ++r)
      for (int i = n; i >= r; --i)
        for (std::size_t c = 0; c < D; ++c) w[i][c] = s * w[i - 1][c] + t * w[i][c];
    std::reverse(w.begin(), w.end());
  }
  // The sub-piece spans (1 - t) (right) or t (left, traversed backwards) of the curve.
  const double inv_len = right ? 1.0 / s : -1.0 / t;
  out[0] = w[0];
  double scale = 1.0, binom = 1.0;
  for (int k = 1; k <= order; ++k) {
    for (int i = 0; i + k <= n; ++i)
      for (std::size_t c = 0; c < D; ++c) w[i][c] = w[i + 1][c] - w[i][c];
    binom = binom * (n - k + 1) / k;
    scale *= inv_len;
    for (std::size_t c = 0; c < D; ++c) out[k][c] = binom * scale * w[0][c];
  }
}

/// Scratch of the expansion, one per thread, grown to the largest piece seen: an expansion
/// allocates nothing once a thread has met its largest degree and order.
template <std::size_t D>
struct PieceScratch {
  std::vector<std::array<double, D>> work, rows, along_u;
  PieceTaylor<D> table;
};
template <std::size_t D>
PieceScratch<D>& piece_scratch() {
  thread_local PieceScratch<D> s;
  return s;
}

/// The expansion of the piece's homogeneous polynomial (its first D coordinates) at (u, v), to
/// total order `order`, in powers of (u - u0) and (v - v0) in the units of u and v. The table
/// lives in this thread's scratch until the next expansion.
template <std::size_t D>
const PieceTaylor<D>& piece_taylor(const BezierPieceView& piece, double u, double v, int order) {
  PieceScratch<D>& s = piece_scratch<D>();
  const int p = piece.p, q = piece.q;
  const int a_max = std::min(p, order), b_cap = std::min(q, order);
  const double wu = piece.u_hi - piece.u_lo, wv = piece.v_hi - piece.v_lo;
  const double su = (u - piece.u_lo) / wu, sv = (v - piece.v_lo) / wv;
  const auto row_at = [b_cap](int i, int b) { return static_cast<std::size_t>(i * (b_cap + 1) + b); };
  s.work.resize(static_cast<std::size_t>(std::max(p, q) + 1));
  s.rows.resize(row_at(p + 1, 0));
  s.along_u.resize(static_cast<std::size_t>(a_max + 1));
  s.table.resize(a_max, b_cap, order);
  for (int i = 0; i <= p; ++i) {  // rows[row_at(i, b)]: the dv^b coefficient of control row i
    for (int j = 0; j <= q; ++j)
      for (std::size_t c = 0; c < D; ++c)
        s.work[static_cast<std::size_t>(j)][c] = piece.net[static_cast<std::size_t>(i * (q + 1) + j)][c];
    bezier_curve_taylor<D>(std::span(s.work.data(), static_cast<std::size_t>(q + 1)), sv, b_cap,
                           s.rows.data() + row_at(i, 0));
  }
  double scale_v = 1.0;
  for (int b = 0; b <= b_cap; ++b, scale_v /= wv) {
    const int a_top = std::min(a_max, order - b);
    for (int i = 0; i <= p; ++i) s.work[static_cast<std::size_t>(i)] = s.rows[row_at(i, b)];
    bezier_curve_taylor<D>(std::span(s.work.data(), static_cast<std::size_t>(p + 1)), su, a_top, s.along_u.data());
    double scale = scale_v;
    for (int a = 0; a <= a_top; ++a, scale /= wu)
      for (std::size_t c = 0; c < D; ++c) s.table(a, b)[c] = scale * s.along_u[static_cast<std::size_t>(a)][c];
  }
  return s.table;
}

/// Whether the jet h (constant term zero) is exactly the variable at monomial index `index`.
template <class T>
bool is_seed(const T& h, int index) {
  for (int i = 0; i < T::kSize; ++i)
    if (h[i] != (i == index ? 1.0 : 0.0)) return false;
  return true;
}

/// The monomials (u - u0)^a (v - v0)^b of one substitution, shared by the D components, one
/// per thread (order-12 jets are 728 bytes each).
template <class T>
std::vector<T>& monomial_scratch() {
  thread_local std::vector<T> m;
  return m;
}

/// sum_ab c_ab (u - u0)^a (v - v0)^b for the argument jets u, v (any number of variables):
/// placed directly when they are the seeds of a Jet<2, K> (the surface's own derivatives);
/// otherwise each monomial is formed once (a + b products in all, a_max b_cap products of
/// powers) and the D components are sums of scaled monomials. Horner per component took D times
/// the products (issue 27: order-12 substitutions into a rational piece were 72 % of a NURBS
/// tangential contact's trace).
template <class T, std::size_t D>
std::array<T, D> substitute(const PieceTaylor<D>& c, const T& u, const T& v) {
  std::array<T, D> r;
  if constexpr (std::is_same_v<T, double>) {
    for (std::size_t k = 0; k < D; ++k) r[k] = c(0, 0)[k];
    (void)u;
    (void)v;
  } else {
    T hu = u, hv = v;
    hu[0] = 0.0;
    hv[0] = 0.0;
    if constexpr (T::kVars == 2) {
      if (T::kOrder >= 1 && is_seed(hu, 1) && is_seed(hv, 2)) {
        const auto& layout = T::Layout::get();
        for (int idx = 0; idx < T::kSize; ++idx) {
          const int a = layout.exponents[static_cast<std::size_t>(idx)][0];
          const int b = layout.exponents[static_cast<std::size_t>(idx)][1];
          const bool present = a <= c.a_max && b <= c.b_max(a);
          for (std::size_t k = 0; k < D; ++k) r[k][idx] = present ? c(a, b)[k] : 0.0;
        }
        return r;
      }
    }
    // powers[0..a_max] = hu^a, then powers[a_max + 1 + b] = hv^b.
    std::vector<T>& powers = monomial_scratch<T>();
    powers.resize(static_cast<std::size_t>(c.a_max + c.b_cap + 2));
    T* pu = powers.data();
    T* pv = powers.data() + c.a_max + 1;
    pu[0] = T(1.0);
    pv[0] = T(1.0);
    for (int a = 1; a <= c.a_max; ++a) pu[a] = a == 1 ? hu : pu[a - 1] * hu;
    for (int b = 1; b <= c.b_cap; ++b) pv[b] = b == 1 ? hv : pv[b - 1] * hv;
    for (std::size_t k = 0; k < D; ++k) r[k] = T(c(0, 0)[k]);
    for (int a = 0; a <= c.a_max; ++a)
      for (int b = a == 0 ? 1 : 0; b <= c.b_max(a); ++b) {
        const T term = a == 0 ? pv[b] : b == 0 ? pu[a] : pu[a] * pv[b];
        for (std::size_t k = 0; k < D; ++k) r[k] += c(a, b)[k] * term;
      }
  }
  return r;
}

/// H(u, v) of the piece in doubles: de Casteljau along v on each row, then along u, in the
/// piece's own parameters (no expansion: a point needs no differences). Working points on the
/// stack up to degree kStackDegree, in this thread's scratch above it.
inline constexpr int kStackDegree = 15;
template <std::size_t D>
std::array<double, D> piece_value(const BezierPieceView& piece, double u, double v) {
  const double su = (u - piece.u_lo) / (piece.u_hi - piece.u_lo), sv = (v - piece.v_lo) / (piece.v_hi - piece.v_lo);
  const std::size_t cols = static_cast<std::size_t>(piece.q) + 1, rows = static_cast<std::size_t>(piece.p) + 1;
  std::array<std::array<double, D>, kStackDegree + 1> row_stack, col_stack;
  std::span<std::array<double, D>> row(row_stack.data(), cols), col(col_stack.data(), rows);
  if (piece.p > kStackDegree || piece.q > kStackDegree) {
    PieceScratch<D>& s = piece_scratch<D>();
    s.work.resize(cols);
    s.rows.resize(rows);
    row = std::span(s.work.data(), cols);
    col = std::span(s.rows.data(), rows);
  }
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j)
      for (std::size_t c = 0; c < D; ++c) row[j][c] = piece.net[i * cols + j][c];
    de_casteljau<double, D>(row, sv);
    col[i] = row[0];
  }
  de_casteljau<double, D>(col, su);
  return col[0];
}

/// F(u, v) of the piece in the number type T (TaylorEvaluable), D = 4 rational, 3 polynomial.
template <class T, std::size_t D>
Vec3T<T> piece_point(const BezierPieceView& piece, const T& u, const T& v) {
  static_assert(TaylorEvaluable<T>::value);
  if constexpr (std::is_same_v<T, double>) {
    const std::array<double, D> h = piece_value<D>(piece, u, v);
    if constexpr (D == 4)
      return {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
    else
      return {h[0], h[1], h[2]};
  } else {
    const PieceTaylor<D>& c = piece_taylor<D>(piece, primal(u), primal(v), TaylorOrder<T>::value);
    const std::array<T, D> h = substitute<T, D>(c, u, v);
    if constexpr (D == 4) {
      const T inv = reciprocal(h[3]);
      return {h[0] * inv, h[1] * inv, h[2] * inv};
    } else {
      return {h[0], h[1], h[2]};
    }
  }
}

/// piece_point of a rational (D = 4) or polynomial (D = 3) piece.
template <class T>
Vec3T<T> piece_point(const BezierPieceView& piece, bool rational, const T& u, const T& v) {
  return rational ? piece_point<T, 4>(piece, u, v) : piece_point<T, 3>(piece, u, v);
}

}  // namespace ssimarch::internal
