// Univariate Taylor coefficients f_k = f^(k)(x0)/k!, k = 0..K, of the elementary functions.
//
// Jet<NV,K> composes these with its non-constant part (jet.hpp). Functions without a simple
// closed form for f^(k) use the classical recurrences for y = f(u) with u(t) = x0 + t, read off
// an ODE y' = g(y, u) (Griewank & Walther, "Evaluating Derivatives", 2nd ed., ch. 13):
//   tan:  y' = 1 + y^2        tanh: y' = 1 - y^2
//   atan: y' = 1/(1 + u^2)    asin: y' = (1 - u^2)^(-1/2)
// and the binomial series for real powers, p = w^r  <=>  w p' = r w' p:
//   p_k = 1/(k w_0) * sum_{j=1..k} (r j - (k - j)) w_j p_{k-j}.
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace ssimarch::internal {

template <int K>
using Coeffs = std::array<double, K + 1>;

namespace detail {
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// p = w^r for a series w with w_0 != 0 (the power recurrence above).
template <int K>
Coeffs<K> power_of_series(const Coeffs<K>& w, double r) {
  Coeffs<K> p{};
  p[0] = std::pow(w[0], r);
  for (int k = 1; k <= K; ++k) {
    double s = 0.0;
    for (int j = 1; j <= k; ++j)
      s += (r * j - (k - j)) * w[static_cast<std::size_t>(j)] * p[static_cast<std::size_t>(k - j)];
    p[static_cast<std::size_t>(k)] = s / (k * w[0]);
  }
  return p;
}

// y with y_0 = y0 and y' = q, i.e. y_k = q_{k-1}/k.
template <int K>
Coeffs<K> integrate(double y0, const Coeffs<K>& q) {
  Coeffs<K> y{};
  y[0] = y0;
  for (int k = 1; k <= K; ++k) y[static_cast<std::size_t>(k)] = q[static_cast<std::size_t>(k - 1)] / k;
  return y;
}

// 1 - u^2 or 1 + u^2 with u = x0 + t, as a series in t.
template <int K>
Coeffs<K> one_plus_sign_u2(double x0, double sign) {
  Coeffs<K> w{};
  w[0] = 1.0 + sign * x0 * x0;
  if (K >= 1) w[1] = sign * 2.0 * x0;
  if (K >= 2) w[2] = sign;
  return w;
}

// y' = a + b y^2 with y_0 given: k y_k = a [k==1] + b sum_{i+j=k-1} y_i y_j.
template <int K>
Coeffs<K> riccati(double y0, double a, double b) {
  Coeffs<K> y{};
  y[0] = y0;
  for (int k = 1; k <= K; ++k) {
    double s = 0.0;
    for (int i = 0; i <= k - 1; ++i) s += y[static_cast<std::size_t>(i)] * y[static_cast<std::size_t>(k - 1 - i)];
    y[static_cast<std::size_t>(k)] = ((k == 1 ? a : 0.0) + b * s) / k;
  }
  return y;
}
}  // namespace detail

template <int K>
Coeffs<K> reciprocal(double x0) {  // 1/(x0+t) = sum (-1)^k t^k / x0^(k+1)
  Coeffs<K> f{};
  f[0] = 1.0 / x0;
  for (int k = 1; k <= K; ++k) f[static_cast<std::size_t>(k)] = -f[static_cast<std::size_t>(k - 1)] / x0;
  return f;
}

template <int K>
Coeffs<K> exp(double x0) {
  Coeffs<K> f{};
  f[0] = std::exp(x0);
  for (int k = 1; k <= K; ++k) f[static_cast<std::size_t>(k)] = f[static_cast<std::size_t>(k - 1)] / k;
  return f;
}

template <int K>
Coeffs<K> log(double x0) {
  Coeffs<K> f{};
  f[0] = std::log(x0);
  double p = 1.0;
  for (int k = 1; k <= K; ++k) {
    p /= x0;
    f[static_cast<std::size_t>(k)] = ((k % 2) ? 1.0 : -1.0) * p / k;
  }
  return f;
}

/// (x0+t)^r = x0^r * sum binom(r,k) (t/x0)^k. At x0 = 0 with r not a non-negative integer the
/// derivatives do not exist and come out infinite or NaN.
template <int K>
Coeffs<K> pow(double x0, double r) {
  Coeffs<K> f{};
  f[0] = std::pow(x0, r);
  for (int k = 1; k <= K; ++k)
    f[static_cast<std::size_t>(k)] = f[static_cast<std::size_t>(k - 1)] * (r - (k - 1)) / (k * x0);
  if (x0 == 0.0)
    for (int k = 1; k <= K; ++k)
      f[static_cast<std::size_t>(k)] = (r >= 0 && r == std::floor(r)) ? (k == r ? 1.0 : 0.0) : detail::kNaN;
  return f;
}

template <int K>
Coeffs<K> sqrt(double x0) {
  Coeffs<K> f = pow<K>(x0, 0.5);
  f[0] = std::sqrt(x0);
  return f;
}

template <int K>
Coeffs<K> cbrt(double x0) {  // odd: cbrt(-x) = -cbrt(x), so expand |x0| and flip signs
  double s = x0 < 0 ? -1.0 : 1.0;
  Coeffs<K> f = pow<K>(std::fabs(x0), 1.0 / 3.0);
  for (int k = 0; k <= K; ++k) f[static_cast<std::size_t>(k)] *= (k % 2 == 0) ? s : 1.0;
  f[0] = std::cbrt(x0);
  return f;
}

namespace detail {
// a cos-like (c) and sin-like (s) pair: g(x0+t) = g(x0) C(t) + g'(x0) S(t) with the even series C
// and odd series S of cos/sin (sign -1) or cosh/sinh (sign +1).
template <int K>
Coeffs<K> trig_like(double g0, double g1, double sign) {
  Coeffs<K> f{};
  double fact = 1.0, sgn = 1.0;
  for (int k = 0; k <= K; ++k) {
    if (k > 0) fact *= k;
    f[static_cast<std::size_t>(k)] = ((k % 2 == 0) ? g0 : g1) * sgn / fact;
    if (k % 2 == 1) sgn *= sign;
  }
  return f;
}
}  // namespace detail

template <int K>
Coeffs<K> sin(double x0) {
  return detail::trig_like<K>(std::sin(x0), std::cos(x0), -1.0);
}
template <int K>
Coeffs<K> cos(double x0) {
  return detail::trig_like<K>(std::cos(x0), -std::sin(x0), -1.0);
}
template <int K>
Coeffs<K> sinh(double x0) {
  return detail::trig_like<K>(std::sinh(x0), std::cosh(x0), 1.0);
}
template <int K>
Coeffs<K> cosh(double x0) {
  return detail::trig_like<K>(std::cosh(x0), std::sinh(x0), 1.0);
}
template <int K>
Coeffs<K> tan(double x0) {
  return detail::riccati<K>(std::tan(x0), 1.0, 1.0);
}
template <int K>
Coeffs<K> tanh(double x0) {
  return detail::riccati<K>(std::tanh(x0), 1.0, -1.0);
}
template <int K>
Coeffs<K> atan(double x0) {
  return detail::integrate<K>(std::atan(x0), detail::power_of_series<K>(detail::one_plus_sign_u2<K>(x0, 1.0), -1.0));
}
template <int K>
Coeffs<K> asin(double x0) {
  return detail::integrate<K>(std::asin(x0), detail::power_of_series<K>(detail::one_plus_sign_u2<K>(x0, -1.0), -0.5));
}
template <int K>
Coeffs<K> acos(double x0) {
  Coeffs<K> f = asin<K>(x0);
  for (auto& c : f) c = -c;
  f[0] = std::acos(x0);
  return f;
}
template <int K>
Coeffs<K> abs(double x0) {
  Coeffs<K> f{};
  f[0] = std::fabs(x0);
  if (K >= 1) f[1] = x0 > 0 ? 1.0 : (x0 < 0 ? -1.0 : detail::kNaN);
  return f;
}

}  // namespace ssimarch::internal
