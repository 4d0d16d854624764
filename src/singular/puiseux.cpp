#include "ssimarch/singular/puiseux.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ssimarch {

namespace {

// Truncated power series in tau: enough orders for exponent 6 with q <= 4 plus the order m of
// H_W (<= kLocalOrder). core/jet.hpp stops at order 12, so a plain coefficient array here.
constexpr int kSeriesOrder = 6 * 4 + kLocalOrder + 2;
struct Series {
  std::array<double, kSeriesOrder + 1> c{};
  double& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  double operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
};
Series operator*(const Series& a, const Series& b) {
  Series r;
  for (int i = 0; i <= kSeriesOrder; ++i)
    if (a[i] != 0.0)
      for (int j = 0; i + j <= kSeriesOrder; ++j) r[i + j] += a[i] * b[j];
  return r;
}

// sum c_ij X^i W^j for the polynomial H, X and W series in tau.
Series substitute(const LocalJet& H, const Series& X, const Series& W) {
  std::array<Series, kLocalOrder + 1> xp, wp;
  xp[0][0] = 1.0, wp[0][0] = 1.0;
  for (std::size_t i = 1; i <= kLocalOrder; ++i) xp[i] = xp[i - 1] * X, wp[i] = wp[i - 1] * W;
  Series out;
  for (int d = 0; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) {
      const double c = coef(H, d - j, j);
      if (c == 0.0) continue;
      const Series t = xp[static_cast<std::size_t>(d - j)] * wp[static_cast<std::size_t>(j)];
      for (int k = 0; k <= kSeriesOrder; ++k) out[k] += c * t[k];
    }
  return out;
}

// The lowest order of s with a coefficient above tol (or -1).
int order_of(const Series& s, double tol) {
  for (int i = 0; i <= kSeriesOrder; ++i)
    if (std::fabs(s[i]) > tol) return i;
  return -1;
}

// The leading coefficient b of W = b tau^p: a root of the edge polynomial P(b) = sum over the
// monomials X^i W^j of H on the Newton polygon's edge q i + p j = L, refined by Newton from `b`.
double refine_leading(const LocalJet& H, int p, int q, double b, double tol) {
  int L = 1 << 30;
  for (int d = 1; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j)
      if (std::fabs(coef(H, d - j, j)) > tol) L = std::min(L, q * (d - j) + p * j);
  for (int it = 0; it < 50; ++it) {
    double P = 0, dP = 0;
    for (int d = 1; d <= kLocalOrder; ++d)
      for (int j = 0; j <= d; ++j) {
        const double c = coef(H, d - j, j);
        if (std::fabs(c) <= tol || q * (d - j) + p * j != L) continue;
        P += c * std::pow(b, j);
        if (j > 0) dP += c * j * std::pow(b, j - 1);
      }
    if (!(std::fabs(dP) > 0)) break;
    const double step = P / dP;
    b -= step;
    if (std::fabs(step) <= 1e-15 * (1 + std::fabs(b))) break;
  }
  return b;
}

}  // namespace

std::pair<int, int> exponent_fraction(double gamma) {
  if (!(gamma > 0)) return {2, 1};
  for (int q = 1; q <= 4; ++q)
    if (std::fabs(gamma * q - std::round(gamma * q)) <= 1e-6 * q) return {static_cast<int>(std::round(gamma * q)), q};
  return {static_cast<int>(std::round(gamma * 4)), 4};
}

PuiseuxExpansion puiseux_expansion(const LocalJet& h, const Vec2& d, double leading, int p, int q, double order) {
  PuiseuxExpansion out;
  out.denominator = q;
  Eigen::Matrix2d frame;
  frame.col(0) = d;
  frame.col(1) = Vec2(-d[1], d[0]);
  const LocalJet H = linear_substitution(h, frame);
  const double tol = 1e-12 * std::max(1e-300, germ_scale(H));
  const LocalJet HW = partial(H, 1);
  Series X, W;
  X[q] = 1.0;
  W[p] = refine_leading(H, p, q, leading, tol);
  const int last = std::min(kSeriesOrder, static_cast<int>(std::floor(order * q + 1e-9)));
  int j = p + 1;
  for (; j <= last; ++j) {
    const Series r = substitute(H, X, W), g = substitute(HW, X, W);
    const int m = order_of(g, tol);
    if (m < 0 || j + m > kSeriesOrder || j + m > (kLocalOrder + 1) * q - 1) break;  // beyond the jet
    const int low = order_of(r, tol * 1e3);
    if (low >= 0 && low < j + m) break;  // not separated: the linear step does not apply
    W[j] = -r[j + m] / g[m];
  }
  out.max_exponent = static_cast<double>(j - 1) / q;
  out.complete = j > last;
  for (int i = p; i < j; ++i)
    if (std::fabs(W[i]) > 1e-12 * std::max(1.0, std::fabs(W[p]))) out.terms.push_back({static_cast<double>(i) / q, W[i]});
  return out;
}

}  // namespace ssimarch
