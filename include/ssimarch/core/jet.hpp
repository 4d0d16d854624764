// Truncated multivariate Taylor jets: automatic differentiation to any fixed order.
//
// A Jet<NV, K> is an element of the ring R[x_1..x_NV] / (monomials of degree > K): the Taylor
// polynomial of a function around a point, truncated after total degree K. We store *normalised*
// coefficients c_a = (d^a f)(x0) / a! (a a multi-index), not derivatives, so a product is a plain
// truncated Cauchy product with no binomial factors (style.md 3.3).
//
//   Example: f(u,v) = u*v at (u0,v0) = (2,3) as a Jet<2,2>:
//     u = 2 + du, v = 3 + dv  ->  u*v = 6 + 3 du + 2 dv + 1 du dv
//     coef({1,1}) = 1, derivative({1,1}) = d2f/dudv = 1, derivative({1,0}) = 3.
//
// sin, cos, exp, log, sqrt and real powers use recurrences in the graded order (Jet::sin_cos:
// one product's work). The other elementary functions use f(a0 + h) = sum_k f_k h^k, with the
// univariate Taylor coefficients f_k = f^(k)(a0)/k! of f at the primal value a0 (computed by the
// recurrences in univariate_series.hpp) and Horner's rule in h = a - a0, whose constant term is
// zero. Both are exact to order K; Horner costs K truncated products.
//
// Singular inputs are not hidden: sqrt, log, real powers at 0 produce infinite or NaN
// coefficients, which callers detect with is_finite(). No silent zeros (style.md 3.16).
//
// Why our own type and not a library: Eigen/Ceres jets are first order only, autodiff stores
// derivatives (binomial factors in every product), and we need fixed-size jets of order up to 8
// in 1..4 variables with composition of jets (a curve's jet substituted into a surface's jet).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <span>
#include <utility>
#include <vector>

#include "ssimarch/core/univariate_series.hpp"

namespace ssimarch {

namespace internal {

constexpr int binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  long long r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return static_cast<int>(r);
}

// Monomials of NV variables and total degree <= K, in graded order (all degree-0, then degree 1
// in lexicographic order of exponents with x_1 first, ...). Built once per (NV, K).
template <int NV, int K>
struct JetLayout {
  static constexpr int kSize = binomial(NV + K, K);
  struct Product {
    int i, j, k;  // c[k] += a[i] * b[j]
  };
  std::array<std::array<int, NV>, kSize> exponents{};
  std::array<int, kSize> degree{};
  std::array<int, K + 2> degree_begin{};  // first index of each total degree
  std::vector<Product> products;          // every (i,j) with deg i + deg j <= K, k-sorted

  JetLayout() {
    int n = 0;
    std::array<int, NV> e{};
    for (int d = 0; d <= K; ++d) {
      degree_begin[static_cast<std::size_t>(d)] = n;
      enumerate(d, 0, e, n);
    }
    degree_begin[K + 1] = n;
    for (int k = 0; k < kSize; ++k) {
      // For each target, list the pairs (i, j) whose exponents sum to it.
      for (int i = 0; i < kSize; ++i) {
        if (degree[static_cast<std::size_t>(i)] > degree[static_cast<std::size_t>(k)]) break;
        std::array<int, NV> rest{};
        bool ok = true;
        for (int v = 0; v < NV; ++v) {
          rest[static_cast<std::size_t>(v)] = exponents[static_cast<std::size_t>(k)][static_cast<std::size_t>(v)] -
                                              exponents[static_cast<std::size_t>(i)][static_cast<std::size_t>(v)];
          if (rest[static_cast<std::size_t>(v)] < 0) ok = false;
        }
        if (ok) products.push_back({i, index_of(rest), k});
      }
    }
  }

  int index_of(const std::array<int, NV>& a) const {
    int d = 0;
    for (int x : a) d += x;
    if (d > K) return -1;
    for (int i = degree_begin[static_cast<std::size_t>(d)]; i < degree_begin[static_cast<std::size_t>(d) + 1]; ++i)
      if (exponents[static_cast<std::size_t>(i)] == a) return i;
    return -1;
  }

  static const JetLayout& get() {
    static const JetLayout layout;
    return layout;
  }

 private:
  void enumerate(int remaining, int var, std::array<int, NV>& e, int& n) {
    if (var == NV - 1) {
      e[static_cast<std::size_t>(var)] = remaining;
      exponents[static_cast<std::size_t>(n)] = e;
      int d = 0;
      for (int x : e) d += x;
      degree[static_cast<std::size_t>(n)] = d;
      ++n;
      return;
    }
    for (int p = remaining; p >= 0; --p) {
      e[static_cast<std::size_t>(var)] = p;
      enumerate(remaining - p, var + 1, e, n);
    }
  }
};

}  // namespace internal

/// Truncated Taylor polynomial in NV variables to total degree K (normalised coefficients).
template <int NV, int K>
class Jet {
  static_assert(NV >= 1 && NV <= 6, "Jet supports 1..6 variables");
  static_assert(K >= 0 && K <= 12, "Jet supports orders 0..12");

 public:
  static constexpr int kVars = NV;
  static constexpr int kOrder = K;
  static constexpr int kSize = internal::JetLayout<NV, K>::kSize;
  using Layout = internal::JetLayout<NV, K>;
  using MultiIndex = std::array<int, NV>;

  Jet() { c_.fill(0.0); }
  Jet(double constant) {  // NOLINT: implicit, so that constants mix freely in formulas
    c_.fill(0.0);
    c_[0] = constant;
  }

  /// The independent variable number `i` (0-based) at the value x0.
  static Jet variable(int i, double x0) {
    Jet j(x0);
    if (K >= 1) j.c_[static_cast<std::size_t>(1 + i)] = 1.0;  // degree-1 monomials follow x_1, x_2, ... in order
    return j;
  }

  double value() const { return c_[0]; }
  double& operator[](int i) { return c_[static_cast<std::size_t>(i)]; }
  double operator[](int i) const { return c_[static_cast<std::size_t>(i)]; }
  const std::array<double, kSize>& coefficients() const { return c_; }

  /// Normalised coefficient of the monomial x^a, i.e. (d^a f)/a!; 0 if |a| > K.
  double coef(const MultiIndex& a) const {
    int i = Layout::get().index_of(a);
    return i < 0 ? 0.0 : c_[static_cast<std::size_t>(i)];
  }
  /// Partial derivative d^|a| f / dx^a at the expansion point.
  double derivative(const MultiIndex& a) const {
    double f = 1.0;
    for (int x : a)
      for (int m = 2; m <= x; ++m) f *= m;
    return coef(a) * f;
  }
  /// First partial derivative with respect to variable i.
  double d(int i) const { return K >= 1 ? c_[static_cast<std::size_t>(1 + i)] : 0.0; }

  // --- ring operations -----------------------------------------------------------------------
  Jet& operator+=(const Jet& o) {
    for (int i = 0; i < kSize; ++i) c_[static_cast<std::size_t>(i)] += o.c_[static_cast<std::size_t>(i)];
    return *this;
  }
  Jet& operator-=(const Jet& o) {
    for (int i = 0; i < kSize; ++i) c_[static_cast<std::size_t>(i)] -= o.c_[static_cast<std::size_t>(i)];
    return *this;
  }
  Jet& operator+=(double s) {
    c_[0] += s;
    return *this;
  }
  Jet& operator-=(double s) {
    c_[0] -= s;
    return *this;
  }
  Jet& operator*=(double s) {
    for (auto& x : c_) x *= s;
    return *this;
  }
  Jet& operator/=(double s) {
    for (auto& x : c_) x /= s;
    return *this;
  }
  Jet& operator*=(const Jet& o) { return *this = *this * o; }
  Jet& operator/=(const Jet& o) { return *this = *this / o; }

  friend Jet operator+(Jet a, const Jet& b) { return a += b; }
  friend Jet operator-(Jet a, const Jet& b) { return a -= b; }
  friend Jet operator+(Jet a, double s) { return a += s; }
  friend Jet operator+(double s, Jet a) { return a += s; }
  friend Jet operator-(Jet a, double s) { return a -= s; }
  friend Jet operator-(double s, const Jet& a) { return -a + s; }
  friend Jet operator*(Jet a, double s) { return a *= s; }
  friend Jet operator*(double s, Jet a) { return a *= s; }
  friend Jet operator/(Jet a, double s) { return a /= s; }
  friend Jet operator-(Jet a) {
    for (auto& x : a.c_) x = -x;
    return a;
  }
  friend Jet operator+(const Jet& a) { return a; }

  // (a*b)_k = sum_{i+j=k} a_i b_j: the truncated Cauchy product.
  friend Jet operator*(const Jet& a, const Jet& b) {
    Jet r;
    if constexpr (K == 1) {
      r.c_[0] = a.c_[0] * b.c_[0];
      for (int i = 1; i <= NV; ++i)
        r.c_[static_cast<std::size_t>(i)] = a.c_[0] * b.c_[static_cast<std::size_t>(i)] +
                                            a.c_[static_cast<std::size_t>(i)] * b.c_[0];
    } else {
      for (const auto& p : Layout::get().products)
        r.c_[static_cast<std::size_t>(p.k)] += a.c_[static_cast<std::size_t>(p.i)] * b.c_[static_cast<std::size_t>(p.j)];
    }
    return r;
  }
  // c = a / b from b c = a in the graded order: b_0 c_k = a_k - sum_{i+j=k, j != 0} c_i b_j,
  // where every c_i on the right has a lower degree than c_k, so is known. One product's work;
  // the reciprocal's Taylor series by Horner took K products (issue 27: 8 times a product at
  // order 4, 45 times at order 12, most of a rational B-spline's jet). b_0 = 0 gives non-finite
  // coefficients, as the series did.
  friend Jet operator/(const Jet& a, const Jet& b) {
    Jet c;
    const double inv = 1.0 / b.c_[0];
    const auto& products = Layout::get().products;
    std::size_t e = 0;
    for (int k = 0; k < kSize; ++k) {
      double s = a.c_[static_cast<std::size_t>(k)];
      for (; e < products.size() && products[e].k == k; ++e)
        if (products[e].j != 0)
          s -= c.c_[static_cast<std::size_t>(products[e].i)] * b.c_[static_cast<std::size_t>(products[e].j)];
      c.c_[static_cast<std::size_t>(k)] = s * inv;
    }
    return c;
  }
  friend Jet operator/(double s, const Jet& b) { return Jet(s) / b; }

  /// f(a) for the univariate series f_k = f^(k)(a0)/k!, k = 0..K (Horner in a - a0).
  static Jet apply(const Jet& a, const std::array<double, K + 1>& f) {
    Jet h = a;
    h.c_[0] = 0.0;
    Jet r(f[K]);
    for (int k = K - 1; k >= 0; --k) {
      r = r * h;
      r.c_[0] += f[static_cast<std::size_t>(k)];
    }
    return r;
  }

  friend Jet reciprocal(const Jet& b) { return Jet(1.0) / b; }

  // --- elementary functions by recurrences in the graded order -------------------------------
  // The Euler operator E = sum_i x_i d/dx_i multiplies a monomial of degree d by d, so an ODE
  // such as d sin a = cos a da becomes, coefficient by coefficient,
  //   d_k S_k = sum_{i+j=k} C_i (d_j a_j),        d_k C_k = -sum_{i+j=k} S_i (d_j a_j),
  // where every C_i, S_i on the right has a lower degree than k (d_j >= 1 where d_j a_j != 0),
  // so is known (Griewank & Walther, "Evaluating Derivatives", 2nd ed., §13.2, Table 13.2, the
  // univariate recurrences; the Euler operator makes them multivariate). One product's work per
  // result where Horner's rule in apply() took K products: a torus's point as an order-12 jet in
  // two variables (the local curve of a parametric-parametric pair) cost 48 products in its four
  // sines and cosines, 8 now.

  /// (sin a, cos a) together.
  static std::pair<Jet, Jet> sin_cos(const Jet& a) {
    const Jet da = euler(a);
    Jet s(std::sin(a.c_[0])), c(std::cos(a.c_[0]));
    graded([&](int k, const auto& products) {
      double ds = 0, dc = 0;
      for (const auto& p : products) {
        ds += c.c_[static_cast<std::size_t>(p.i)] * da.c_[static_cast<std::size_t>(p.j)];
        dc -= s.c_[static_cast<std::size_t>(p.i)] * da.c_[static_cast<std::size_t>(p.j)];
      }
      const double d = Layout::get().degree[static_cast<std::size_t>(k)];
      s.c_[static_cast<std::size_t>(k)] = ds / d;
      c.c_[static_cast<std::size_t>(k)] = dc / d;
    });
    return {s, c};
  }
  /// exp a: E v = v E a.
  static Jet exp_of(const Jet& a) {
    const Jet da = euler(a);
    Jet v(std::exp(a.c_[0]));
    graded([&](int k, const auto& products) {
      double dv = 0;
      for (const auto& p : products) dv += v.c_[static_cast<std::size_t>(p.i)] * da.c_[static_cast<std::size_t>(p.j)];
      v.c_[static_cast<std::size_t>(k)] = dv / Layout::get().degree[static_cast<std::size_t>(k)];
    });
    return v;
  }
  /// a^r for real r: a E y = r y E a, so a_0 d_k y_k = r sum y_i (d_j a_j) - sum_{i != 0} a_i (d_j y_j).
  /// log a (r = 0 marks it): a E y = E a, so a_0 d_k y_k = d_k a_k - sum_{i != 0} a_i (d_j y_j).
  /// A zero or negative a_0 gives non-finite coefficients, as the series did.
  static Jet power_of(const Jet& a, double r, bool logarithm) {
    const Jet da = euler(a);
    Jet y(logarithm ? std::log(a.c_[0]) : std::pow(a.c_[0], r)), dy;
    const double inv = 1.0 / a.c_[0];
    graded([&](int k, const auto& products) {
      const std::size_t kk = static_cast<std::size_t>(k);
      double sum = logarithm ? da.c_[kk] : 0.0;
      for (const auto& p : products) {
        const std::size_t i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
        if (!logarithm) sum += r * y.c_[i] * da.c_[j];
        if (i != 0) sum -= a.c_[i] * dy.c_[j];
      }
      const double d = Layout::get().degree[kk];
      y.c_[kk] = sum * inv / d;
      dy.c_[kk] = sum * inv;
    });
    return y;
  }

  // Comparisons act on the primal value only (branching code must use primal(), style.md 3.3).
  friend bool operator<(const Jet& a, const Jet& b) { return a.value() < b.value(); }
  friend bool operator>(const Jet& a, const Jet& b) { return a.value() > b.value(); }

  friend std::ostream& operator<<(std::ostream& os, const Jet& a) {
    os << "Jet[";
    for (int i = 0; i < kSize; ++i) os << (i ? ", " : "") << a.c_[static_cast<std::size_t>(i)];
    return os << "]";
  }

 private:
  std::array<double, kSize> c_;

  // E a: coefficient k times its degree.
  static Jet euler(const Jet& a) {
    Jet r;
    for (int k = 1; k < kSize; ++k)
      r.c_[static_cast<std::size_t>(k)] =
          Layout::get().degree[static_cast<std::size_t>(k)] * a.c_[static_cast<std::size_t>(k)];
    return r;
  }
  // Calls f(k, products of k) for k = 1 .. kSize - 1 in the graded order (products: a range of
  // the layout's (i, j, k) entries with i + j = k).
  template <class F>
  static void graded(F&& f) {
    const auto& products = Layout::get().products;
    std::size_t e = 0;
    while (e < products.size() && products[e].k == 0) ++e;
    for (int k = 1; k < kSize; ++k) {
      const std::size_t first = e;
      while (e < products.size() && products[e].k == k) ++e;
      f(k, std::span(products.data() + first, e - first));
    }
  }
};

/// A univariate truncated Taylor series: coefficient k is f^(k)(s0)/k!.
template <int K>
using Taylor = Jet<1, K>;

// --- primal value: the one thing generic code may branch on -------------------------------------
inline double primal(double x) { return x; }
template <int NV, int K>
double primal(const Jet<NV, K>& x) {
  return x.value();
}

inline bool is_finite(double x) { return std::isfinite(x); }
template <int NV, int K>
bool is_finite(const Jet<NV, K>& x) {
  for (double c : x.coefficients())
    if (!std::isfinite(c)) return false;
  return true;
}

// --- elementary functions (each: the univariate series it composes with) ------------------------
#define SSIMARCH_JET_UNARY(name)                               \
  template <int NV, int K>                                     \
  Jet<NV, K> name(const Jet<NV, K>& a) {                       \
    return Jet<NV, K>::apply(a, internal::name<K>(a.value())); \
  }
SSIMARCH_JET_UNARY(cbrt)   // binomial series with r = 1/3 (odd-symmetric)
SSIMARCH_JET_UNARY(tan)    // y' = 1 + y^2
SSIMARCH_JET_UNARY(asin)   // y' = (1 - x^2)^(-1/2)
SSIMARCH_JET_UNARY(acos)   // y' = -(1 - x^2)^(-1/2)
SSIMARCH_JET_UNARY(atan)   // y' = 1/(1 + x^2)
SSIMARCH_JET_UNARY(sinh)   // sinh(a0+h) = sinh a0 cosh h + cosh a0 sinh h
SSIMARCH_JET_UNARY(cosh)   // cosh(a0+h) = cosh a0 cosh h + sinh a0 sinh h
SSIMARCH_JET_UNARY(tanh)   // y' = 1 - y^2
SSIMARCH_JET_UNARY(abs)    // sign(a0) * a; not differentiable at 0 (derivatives NaN there)
#undef SSIMARCH_JET_UNARY

// By the graded recurrences (Jet::sin_cos, exp_of, power_of): one product's work each.
template <int NV, int K>
Jet<NV, K> sin(const Jet<NV, K>& a) {
  return Jet<NV, K>::sin_cos(a).first;
}
template <int NV, int K>
Jet<NV, K> cos(const Jet<NV, K>& a) {
  return Jet<NV, K>::sin_cos(a).second;
}
template <int NV, int K>
Jet<NV, K> exp(const Jet<NV, K>& a) {
  return Jet<NV, K>::exp_of(a);
}
template <int NV, int K>
Jet<NV, K> log(const Jet<NV, K>& a) {
  return Jet<NV, K>::power_of(a, 0.0, true);
}
template <int NV, int K>
Jet<NV, K> sqrt(const Jet<NV, K>& a) {
  return Jet<NV, K>::power_of(a, 0.5, false);
}

/// a^r for real r: binomial series a0^r (1 + h/a0)^r; needs a0 > 0 unless r is an integer.
template <int NV, int K>
Jet<NV, K> pow(const Jet<NV, K>& a, double r) {
  double ri = std::round(r);
  if (ri == r && std::fabs(r) <= 64) return pow(a, static_cast<int>(ri));
  return Jet<NV, K>::power_of(a, r, false);
}

/// a^n for integer n by repeated squaring, exact also at a0 = 0 for n >= 0.
template <int NV, int K>
Jet<NV, K> pow(const Jet<NV, K>& a, int n) {
  if (n < 0) return reciprocal(pow(a, -n));
  Jet<NV, K> result(1.0), base = a;
  while (n > 0) {
    if (n & 1) result = result * base;
    n >>= 1;
    if (n > 0) base = base * base;
  }
  return result;
}

/// a^b with both jets: exp(b log a) (a0 > 0).
template <int NV, int K>
Jet<NV, K> pow(const Jet<NV, K>& a, const Jet<NV, K>& b) {
  // A constant integer exponent keeps a0 <= 0 legal.
  bool constant_b = true;
  for (int i = 1; i < Jet<NV, K>::kSize; ++i)
    if (b[i] != 0.0) constant_b = false;
  if (constant_b) return pow(a, b.value());
  return exp(b * log(a));
}
template <int NV, int K>
Jet<NV, K> pow(double a, const Jet<NV, K>& b) {
  return exp(b * std::log(a));
}

/// atan2(y, x) = theta0 + atan((x0 y - y0 x) / (x0 x + y0 y)): the angle measured from the
/// expansion point's own direction, so the argument of atan starts at 0 and never wraps.
template <int NV, int K>
Jet<NV, K> atan2(const Jet<NV, K>& y, const Jet<NV, K>& x) {
  double x0 = x.value(), y0 = y.value();
  Jet<NV, K> num = x0 * y - y0 * x;
  Jet<NV, K> den = x0 * x + y0 * y;
  Jet<NV, K> r = atan(num / den);
  r[0] = std::atan2(y0, x0);
  return r;
}

// --- composition -------------------------------------------------------------------------------

/// f(x_1(t), ..., x_NV(t)): substitute jets of the inner variables (in M variables, any point)
/// into the Taylor polynomial of f taken at (x_1(t0), ..., x_NV(t0)). The inner jets' values
/// must equal f's expansion point; only their non-constant parts enter.
template <int NV, int M, int K>
Jet<M, K> compose(const Jet<NV, K>& f, const std::array<Jet<M, K>, NV>& x) {
  const auto& layout = internal::JetLayout<NV, K>::get();
  // powers[v][p] = (x_v - x_v0)^p
  std::array<std::array<Jet<M, K>, K + 1>, NV> powers;
  for (int v = 0; v < NV; ++v) {
    Jet<M, K> h = x[static_cast<std::size_t>(v)];
    h[0] = 0.0;
    powers[static_cast<std::size_t>(v)][0] = Jet<M, K>(1.0);
    for (int p = 1; p <= K; ++p)
      powers[static_cast<std::size_t>(v)][static_cast<std::size_t>(p)] =
          powers[static_cast<std::size_t>(v)][static_cast<std::size_t>(p - 1)] * h;
  }
  Jet<M, K> r;
  for (int i = 0; i < Jet<NV, K>::kSize; ++i) {
    double c = f[i];
    if (c == 0.0) continue;
    Jet<M, K> term(c);
    for (int v = 0; v < NV; ++v) {
      int e = layout.exponents[static_cast<std::size_t>(i)][static_cast<std::size_t>(v)];
      if (e > 0) term = term * powers[static_cast<std::size_t>(v)][static_cast<std::size_t>(e)];
    }
    r += term;
  }
  return r;
}

}  // namespace ssimarch
