// First-order forward differentiation over any scalar S (Griewank & Walther, Evaluating
// Derivatives, 2008, ch. 3): a value and its N partial derivatives. Over IntervalNumber it gives
// interval enclosures of a function and its Jacobian on a box in one pass of the surfaces'
// templated evaluation (what the Krawczyk test needs); nested, Gradient<Gradient<IntervalNumber,
// N>, N>, it gives the Jacobian of an expression that itself holds first derivatives (the
// turning-point systems, docs/topology.md).
//
// Why not core/jet.hpp's Jet: its coefficients are doubles, and its elementary functions build
// Taylor series at the primal value, which has no meaning on an interval.
#pragma once

#include <array>
#include <cmath>

namespace ssimarch {

template <class S, int N>
struct Gradient {
  S v{};
  std::array<S, N> d{};

  Gradient() : v(0.0) { d.fill(S(0.0)); }
  Gradient(double x) : v(x) { d.fill(S(0.0)); }        // NOLINT: a constant
  Gradient(const S& value, int variable) : v(value) {  // the variable number `variable`
    d.fill(S(0.0));
    d[static_cast<std::size_t>(variable)] = S(1.0);
  }

  /// f(a) given f(a.v) and f'(a.v): the chain rule.
  static Gradient chain(const Gradient& a, const S& f, const S& df) {
    Gradient r;
    r.v = f;
    for (int i = 0; i < N; ++i) r.d[static_cast<std::size_t>(i)] = df * a.d[static_cast<std::size_t>(i)];
    return r;
  }

  friend Gradient operator-(const Gradient& a) {
    Gradient r;
    r.v = -a.v;
    for (int i = 0; i < N; ++i) r.d[static_cast<std::size_t>(i)] = -a.d[static_cast<std::size_t>(i)];
    return r;
  }
  friend Gradient operator+(const Gradient& a, const Gradient& b) {
    Gradient r;
    r.v = a.v + b.v;
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
  }
  friend Gradient operator-(const Gradient& a, const Gradient& b) {
    Gradient r;
    r.v = a.v - b.v;
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
  }
  friend Gradient operator*(const Gradient& a, const Gradient& b) {
    Gradient r;
    r.v = a.v * b.v;
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
    return r;
  }
  friend Gradient operator/(const Gradient& a, const Gradient& b) {
    Gradient r;
    r.v = a.v / b.v;
    for (std::size_t i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) / b.v;
    return r;
  }
  friend Gradient operator+(const Gradient& a, double b) {
    Gradient r = a;
    r.v = a.v + b;
    return r;
  }
  friend Gradient operator+(double a, const Gradient& b) { return b + a; }
  friend Gradient operator-(const Gradient& a, double b) { return a + (-b); }
  friend Gradient operator-(double a, const Gradient& b) { return (-b) + a; }
  friend Gradient operator*(const Gradient& a, double b) {
    Gradient r;
    r.v = a.v * b;
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] * b;
    return r;
  }
  friend Gradient operator*(double a, const Gradient& b) { return b * a; }
  friend Gradient operator/(const Gradient& a, double b) {
    Gradient r;
    r.v = a.v / b;
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] / b;
    return r;
  }
  friend Gradient operator/(double a, const Gradient& b) { return Gradient(a) / b; }
  Gradient& operator+=(const Gradient& b) { return *this = *this + b; }
  Gradient& operator-=(const Gradient& b) { return *this = *this - b; }
  Gradient& operator*=(const Gradient& b) { return *this = *this * b; }
};

template <class S, int N>
double primal(const Gradient<S, N>& a) {
  return primal(a.v);
}

template <class S, int N>
Gradient<S, N> sqrt(const Gradient<S, N>& a) {
  S r = sqrt(a.v);
  return Gradient<S, N>::chain(a, r, 0.5 / r);
}
template <class S, int N>
Gradient<S, N> cbrt(const Gradient<S, N>& a) {
  S r = cbrt(a.v);
  return Gradient<S, N>::chain(a, r, 1.0 / (3.0 * (r * r)));
}
template <class S, int N>
Gradient<S, N> exp(const Gradient<S, N>& a) {
  S r = exp(a.v);
  return Gradient<S, N>::chain(a, r, r);
}
template <class S, int N>
Gradient<S, N> log(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, log(a.v), 1.0 / a.v);
}
template <class S, int N>
Gradient<S, N> sin(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, sin(a.v), cos(a.v));
}
template <class S, int N>
Gradient<S, N> cos(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, cos(a.v), -sin(a.v));
}
template <class S, int N>
Gradient<S, N> tan(const Gradient<S, N>& a) {
  S r = tan(a.v);
  return Gradient<S, N>::chain(a, r, 1.0 + r * r);
}
template <class S, int N>
Gradient<S, N> asin(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, asin(a.v), 1.0 / sqrt(1.0 - a.v * a.v));
}
template <class S, int N>
Gradient<S, N> acos(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, acos(a.v), -1.0 / sqrt(1.0 - a.v * a.v));
}
template <class S, int N>
Gradient<S, N> atan(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, atan(a.v), 1.0 / (1.0 + a.v * a.v));
}
template <class S, int N>
Gradient<S, N> sinh(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, sinh(a.v), cosh(a.v));
}
template <class S, int N>
Gradient<S, N> cosh(const Gradient<S, N>& a) {
  return Gradient<S, N>::chain(a, cosh(a.v), sinh(a.v));
}
template <class S, int N>
Gradient<S, N> tanh(const Gradient<S, N>& a) {
  S r = tanh(a.v);
  return Gradient<S, N>::chain(a, r, 1.0 - r * r);
}
/// |a|: the derivative's enclosure is sign(a), [-1, 1] where a may vanish (a valid enclosure of
/// every one-sided derivative).
template <class S, int N>
Gradient<S, N> abs(const Gradient<S, N>& a) {
  const S s = abs(a.v);
  const double p = primal(a.v);
  // Over intervals sign(a) is decided by the enclosure of a; over doubles by its value.
  S sign = p > 0 ? S(1.0) : (p < 0 ? S(-1.0) : S(0.0));
  if constexpr (requires { a.v.contains_zero(); }) {
    if (a.v.contains_zero())
      sign = S(-1.0, 1.0);
    else
      sign = a.v.lo() > 0 ? S(1.0) : S(-1.0);
  } else if constexpr (requires { a.v.v.contains_zero(); }) {
    // Nested over intervals (second derivatives): sign(a) is a step where a may vanish, so its
    // own derivatives there are unbounded (entire), not 0 — or the Hessian of |u| + v^2 + 3uv
    // would miss the kink that makes the origin a minimum (start/saddle_box.hpp).
    using I = decltype(a.v.v);
    if (a.v.v.contains_zero()) {
      sign.v = I(-1.0, 1.0);
      sign.d.fill(I::entire());
    } else {
      sign = a.v.v.lo() > 0 ? S(1.0) : S(-1.0);
    }
  }
  return Gradient<S, N>::chain(a, s, sign);
}
template <class S, int N>
Gradient<S, N> atan2(const Gradient<S, N>& y, const Gradient<S, N>& x) {
  Gradient<S, N> r;
  r.v = atan2(y.v, x.v);
  const S den = x.v * x.v + y.v * y.v;
  for (std::size_t i = 0; i < N; ++i) r.d[i] = (x.v * y.d[i] - y.v * x.d[i]) / den;
  if constexpr (requires { y.v.contains_zero(); }) {
    // A box across the branch cut (x <= 0, y = 0): atan2 jumps by 2 pi there, which no bound on
    // the smooth derivative covers; the mean-value and Krawczyk tests need an enclosure of every
    // difference quotient, so the derivative is unbounded.
    if (y.v.contains_zero() && x.v.lo() <= 0)
      for (std::size_t i = 0; i < N; ++i) r.d[i] = S::entire();
  } else if constexpr (requires { y.v.v.contains_zero(); }) {
    using I = decltype(y.v.v);
    if (y.v.v.contains_zero() && x.v.v.lo() <= 0)
      for (std::size_t i = 0; i < N; ++i) {
        r.d[i].v = I::entire();
        r.d[i].d.fill(I::entire());
      }
  }
  return r;
}
template <class S, int N>
Gradient<S, N> pow(const Gradient<S, N>& a, int n) {
  if (n == 0) return Gradient<S, N>(1.0);
  return Gradient<S, N>::chain(a, pow(a.v, n), static_cast<double>(n) * pow(a.v, n - 1));
}
template <class S, int N>
Gradient<S, N> pow(const Gradient<S, N>& a, double r) {
  if (r == std::round(r) && std::abs(r) < 1 << 20) return pow(a, static_cast<int>(r));
  return Gradient<S, N>::chain(a, pow(a.v, r), r * pow(a.v, r - 1.0));
}
template <class S, int N>
Gradient<S, N> pow(const Gradient<S, N>& a, const Gradient<S, N>& b) {
  return exp(b * log(a));
}

}  // namespace ssimarch
