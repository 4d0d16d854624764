#include "ssimarch/start/interval_number.hpp"

#include <array>

namespace ssimarch {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kLibmUlps = 4;  // outward push of libm results (see the header)

// The hull of libm's f at the two ends of a monotone increasing (or decreasing) function.
template <class F>
IntervalNumber monotone(const IntervalNumber& a, F f, bool increasing = true) {
  const double x = f(a.lo()), y = f(a.hi());
  return increasing ? IntervalNumber::outward(x, y, kLibmUlps) : IntervalNumber::outward(y, x, kLibmUlps);
}

// a clipped to [lo, hi]; *empty when a misses it.
IntervalNumber clip(const IntervalNumber& a, double lo, double hi, bool* empty) {
  return intersect(a, IntervalNumber(lo, hi), empty);
}

// Whether [a, b] (with slack for the rounding of a and b) holds an integer k with k = parity mod 2.
bool holds_integer_of_parity(double a, double b, int parity) {
  const double slack = 1e-12 * (1.0 + std::max(std::abs(a), std::abs(b)));
  const double first = std::ceil(a - slack);
  for (double k = first; k <= b + slack && k < first + 3; k += 1.0)
    if (static_cast<long long>(std::fmod(std::abs(k), 2.0)) == parity) return true;
  return false;
}

// cos on [lo, hi] with |hi - lo| < 2 pi: the end values, and +-1 where a multiple of pi lies inside.
IntervalNumber cos_range(double lo, double hi) {
  const double a = std::cos(lo), b = std::cos(hi);
  double rlo = std::min(a, b), rhi = std::max(a, b);
  const double s = lo / std::numbers::pi, t = hi / std::numbers::pi;
  IntervalNumber r = IntervalNumber::outward(rlo, rhi, kLibmUlps);
  rlo = r.lo();
  rhi = r.hi();
  if (holds_integer_of_parity(s, t, 0)) rhi = 1.0;
  if (holds_integer_of_parity(s, t, 1)) rlo = -1.0;
  return {std::max(rlo, -1.0), std::min(rhi, 1.0)};
}

}  // namespace

IntervalNumber hull(const IntervalNumber& a, const IntervalNumber& b) {
  return {std::min(a.lo(), b.lo()), std::max(a.hi(), b.hi())};
}

IntervalNumber intersect(const IntervalNumber& a, const IntervalNumber& b, bool* empty) {
  const double lo = std::max(a.lo(), b.lo()), hi = std::min(a.hi(), b.hi());
  *empty = lo > hi;
  return *empty ? a : IntervalNumber(lo, hi);
}

IntervalNumber sqrt(const IntervalNumber& a) {
  bool empty = false;
  IntervalNumber c = clip(a, 0.0, kInf, &empty);
  if (empty) return IntervalNumber::entire();
  IntervalNumber r = monotone(c, [](double x) { return std::sqrt(x); });
  return {std::max(r.lo(), 0.0), r.hi()};
}

IntervalNumber cbrt(const IntervalNumber& a) {
  return monotone(a, [](double x) { return std::cbrt(x); });
}

IntervalNumber exp(const IntervalNumber& a) {
  IntervalNumber r = monotone(a, [](double x) { return std::exp(x); });
  return {std::max(r.lo(), 0.0), r.hi()};
}

IntervalNumber log(const IntervalNumber& a) {
  bool empty = false;
  IntervalNumber c = clip(a, 0.0, kInf, &empty);
  if (empty) return IntervalNumber::entire();
  return monotone(c, [](double x) { return std::log(x); });
}

IntervalNumber cos(const IntervalNumber& a) {
  if (!(a.width() < 2 * std::numbers::pi)) return {-1.0, 1.0};
  return cos_range(a.lo(), a.hi());
}

IntervalNumber sin(const IntervalNumber& a) {
  if (!(a.width() < 2 * std::numbers::pi)) return {-1.0, 1.0};
  // sin x = cos(x - pi/2); the shift's rounding is covered by the slack of the extremum test and
  // the end values are taken from sin itself.
  const double x = std::sin(a.lo()), y = std::sin(a.hi());
  IntervalNumber r = IntervalNumber::outward(std::min(x, y), std::max(x, y), kLibmUlps);
  double rlo = r.lo(), rhi = r.hi();
  const double s = a.lo() / std::numbers::pi - 0.5, t = a.hi() / std::numbers::pi - 0.5;
  if (holds_integer_of_parity(s, t, 0)) rhi = 1.0;
  if (holds_integer_of_parity(s, t, 1)) rlo = -1.0;
  return {std::max(rlo, -1.0), std::min(rhi, 1.0)};
}

IntervalNumber tan(const IntervalNumber& a) {
  if (!(a.width() < std::numbers::pi)) return IntervalNumber::entire();
  const double s = a.lo() / std::numbers::pi - 0.5, t = a.hi() / std::numbers::pi - 0.5;
  if (holds_integer_of_parity(s, t, 0) || holds_integer_of_parity(s, t, 1)) return IntervalNumber::entire();
  return monotone(a, [](double x) { return std::tan(x); });
}

IntervalNumber asin(const IntervalNumber& a) {
  bool empty = false;
  IntervalNumber c = clip(a, -1.0, 1.0, &empty);
  if (empty) return IntervalNumber::entire();
  return monotone(c, [](double x) { return std::asin(x); });
}

IntervalNumber acos(const IntervalNumber& a) {
  bool empty = false;
  IntervalNumber c = clip(a, -1.0, 1.0, &empty);
  if (empty) return IntervalNumber::entire();
  return monotone(
      c, [](double x) { return std::acos(x); }, false);
}

IntervalNumber atan(const IntervalNumber& a) {
  return monotone(a, [](double x) { return std::atan(x); });
}
IntervalNumber sinh(const IntervalNumber& a) {
  return monotone(a, [](double x) { return std::sinh(x); });
}
IntervalNumber tanh(const IntervalNumber& a) {
  return monotone(a, [](double x) { return std::tanh(x); });
}

IntervalNumber cosh(const IntervalNumber& a) {
  IntervalNumber m = abs(a);
  IntervalNumber r = monotone(m, [](double x) { return std::cosh(x); });
  return {std::max(r.lo(), 1.0), r.hi()};
}

IntervalNumber abs(const IntervalNumber& a) {
  if (a.lo() >= 0) return a;
  if (a.hi() <= 0) return -a;
  return {0.0, std::max(-a.lo(), a.hi())};
}

IntervalNumber atan2(const IntervalNumber& y, const IntervalNumber& x) {
  // Off the branch cut (x <= 0, y = 0) atan2 is monotone in each argument over the box, so its
  // range is spanned by the corners.
  if (!(y.lo() > 0 || y.hi() < 0 || x.lo() > 0)) return IntervalNumber::outward(-std::numbers::pi, std::numbers::pi);
  const std::array<double, 4> c{std::atan2(y.lo(), x.lo()), std::atan2(y.lo(), x.hi()), std::atan2(y.hi(), x.lo()),
                                std::atan2(y.hi(), x.hi())};
  return IntervalNumber::outward(*std::min_element(c.begin(), c.end()), *std::max_element(c.begin(), c.end()),
                                 kLibmUlps);
}

namespace {

constexpr int kProductPowers = 8;  // x^n by n - 1 products up to this n, by libm's pow beyond

// x^n (2 <= n <= kProductPowers) by repeated products, and the outward push that covers them:
// each product is rounded to nearest (relative error <= 2^-53, and one ulp of the result is at
// least 2^-53 of it), so n - 1 products are within n - 1 ulps; one more for the slack of the
// relative bound. Cheaper than pow, which dominated the profiles of polynomial surfaces.
double product_power(double x, int n) {
  double r = x;
  for (int i = 1; i < n; ++i) r *= x;
  return r;
}

template <class F>
IntervalNumber monotone_power(const IntervalNumber& a, int n, F f) {
  if (n > kProductPowers) return monotone(a, f);
  return IntervalNumber::outward(product_power(a.lo(), n), product_power(a.hi(), n), n);
}

}  // namespace

IntervalNumber pow(const IntervalNumber& a, int n) {
  if (n == 0) return IntervalNumber(1.0);
  if (n < 0) return 1.0 / pow(a, -n);
  if (n == 1) return a;
  auto f = [n](double x) { return std::pow(x, n); };
  if (n % 2 == 1) return monotone_power(a, n, f);
  IntervalNumber r = monotone_power(abs(a), n, f);
  return {std::max(r.lo(), 0.0), r.hi()};
}

IntervalNumber pow(const IntervalNumber& a, double r) {
  if (r == std::round(r) && std::abs(r) < 1 << 20) return pow(a, static_cast<int>(r));
  bool empty = false;
  IntervalNumber c = clip(a, 0.0, kInf, &empty);  // a real power is defined for x >= 0 only
  if (empty) return IntervalNumber::entire();
  if (r < 0 && c.lo() == 0.0) return IntervalNumber::entire();
  IntervalNumber p = monotone(
      c, [r](double x) { return std::pow(x, r); }, r > 0);
  return {std::max(p.lo(), 0.0), p.hi()};
}

IntervalNumber pow(const IntervalNumber& a, const IntervalNumber& b) {
  if (b.lo() == b.hi()) return pow(a, b.lo());
  return exp(b * log(a));
}

}  // namespace ssimarch
