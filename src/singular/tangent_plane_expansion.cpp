#include "ssimarch/singular/tangent_plane_expansion.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "ssimarch/singular/expansion_tolerances.hpp"
#include "ssimarch/singular/series.hpp"

namespace ssimarch {

using series::Series;

PuiseuxExpansion tangent_plane_expansion(const LocalCurve& curve, const Vec2& d, const PuiseuxExpansion& chart) {
  const int Q = chart.denominator;
  const int N = static_cast<int>(std::floor(chart.max_exponent * Q + 1e-9));  // tau-order of the last exponent
  if (N <= Q) return chart;  // nothing beyond the tangent itself is known
  // X(tau) is needed to order Q + N - 1 (sigma to order N); the chart's W to order N suffices
  // there: W enters X only multiplied by tau^Q or more (n is normal to d at first order).
  const int M = Q + N - 1;
  const Vec2 n(-d[1], d[0]);
  Series s(static_cast<std::size_t>(M + 1), 0.0), t = s;
  s[static_cast<std::size_t>(Q)] = d[0], t[static_cast<std::size_t>(Q)] = d[1];
  for (const PuiseuxTerm& term : chart.terms) {
    const auto j = static_cast<std::size_t>(std::lround(term.exponent * Q));
    if (j <= static_cast<std::size_t>(N)) s[j] += n[0] * term.coefficient, t[j] += n[1] * term.coefficient;
  }
  // P(tau) - P0 and a bound on its rounding; X and W along T and N x T.
  const Vec3 T = curve.direction_3d(d), B = curve.direction_3d(n);
  std::array<Series, 3> P, Pmag;
  for (std::size_t k = 0; k < 3; ++k) {
    P[k] = series::compose(curve.point[k], s, t, Q, false);
    Pmag[k] = series::compose(curve.point[k], s, t, Q, true);
    P[k][0] = Pmag[k][0] = 0.0;
  }
  Series X(P[0].size(), 0.0), W = X, mag = X;
  for (std::size_t i = 0; i < X.size(); ++i) {
    const Vec3 v(P[0][i], P[1][i], P[2][i]);
    X[i] = v.dot(T), W[i] = v.dot(B);
    mag[i] = Pmag[0][i] + Pmag[1][i] + Pmag[2][i];
  }
  if (!(X[static_cast<std::size_t>(Q)] > 0)) return chart;
  // X = tau^Q g(tau): sigma = tau g^(1/Q) has X = sigma^Q; revert, substitute into W.
  const Series g(X.begin() + Q, X.begin() + Q + N);  // orders 0 .. N - 1
  const Series root = series::power(g, 1.0 / Q);
  Series sigma(static_cast<std::size_t>(N + 1), 0.0);
  for (std::size_t i = 0; i < root.size(); ++i) sigma[i + 1] = root[i];
  const Series tau = series::revert(sigma);
  const std::vector<Series> tp = series::powers(tau), tpmag = series::powers(series::absolute(tau));
  W.resize(static_cast<std::size_t>(N + 1));
  mag.resize(static_cast<std::size_t>(N + 1));
  const Series Wg = series::substitute(W, tp), Mg = series::substitute(mag, tpmag);
  PuiseuxExpansion out = chart;
  out.terms.clear();
  for (int j = Q + 1; j <= N; ++j) {
    const double c = Wg[static_cast<std::size_t>(j)];
    if (std::isfinite(c) && std::fabs(c) > kTangentPlaneTermZero * Mg[static_cast<std::size_t>(j)])
      out.terms.push_back({static_cast<double>(j) / Q, c});
  }
  return out;
}

}  // namespace ssimarch
