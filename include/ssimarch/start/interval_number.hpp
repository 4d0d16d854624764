// A closed interval of reals with outward rounding: every operation returns an interval that
// contains the exact image of its arguments (Moore, Kearfott & Cloud, Introduction to Interval
// Analysis, 2009, ch. 2-5). It has the operations of the expression programs' number types
// (expr/program.hpp), so the surfaces' templated point/value functions evaluate on it unchanged.
//
// Why our own type and not Boost.Interval: Boost's transcendental functions are only rigorous
// with a correctly rounded libm behind its rounding-mode policies, which glibc does not promise,
// and its mixed double/interval operators do not match the evaluators' `double op T` use. Here
// each bound computed in round-to-nearest is pushed one ulp outward (exact for + - * / and sqrt,
// whose rounding error is at most half an ulp), and the results of libm functions four ulps
// outward (glibc documents at most a few ulps for these functions).
//
// An operation outside its domain (log of a negative interval, division by an interval holding
// 0) gives the entire real line: a valid enclosure, never a wrong one.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

namespace ssimarch {

class IntervalNumber {
 public:
  IntervalNumber() = default;
  IntervalNumber(double x) : lo_(x), hi_(x) {}  // NOLINT: a double is the point interval
  IntervalNumber(double lo, double hi) : lo_(lo), hi_(hi) {
    if (std::isnan(lo_) || std::isnan(hi_)) *this = entire();
  }

  static IntervalNumber entire() {
    IntervalNumber r;
    r.lo_ = -std::numeric_limits<double>::infinity();
    r.hi_ = std::numeric_limits<double>::infinity();
    return r;
  }
  /// [lo, hi] pushed `ulps` units outward (the result of a computation rounded to nearest).
  static IntervalNumber outward(double lo, double hi, int ulps = 1) {
    if (std::isnan(lo) || std::isnan(hi)) return entire();
    for (int i = 0; i < ulps; ++i) {
      lo = next_down(lo);
      hi = next_up(hi);
    }
    IntervalNumber r;
    r.lo_ = lo;
    r.hi_ = hi;
    return r;
  }
  /// The next double above x (x itself for +inf): std::nextafter(x, +inf) without the libm call
  /// and its errno handling, which dominated interval products (docs/benchmarks.md, profiles).
  static double next_up(double x) {
    if (!(x < std::numeric_limits<double>::infinity())) return x;
    if (x == 0.0) return std::numeric_limits<double>::denorm_min();
    const auto bits = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
  }
  static double next_down(double x) { return -next_up(-x); }

  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double mid() const {
    if (std::isinf(lo_) || std::isinf(hi_))
      return std::isinf(lo_) && std::isinf(hi_) ? 0.0 : (std::isinf(lo_) ? hi_ : lo_);
    return 0.5 * lo_ + 0.5 * hi_;
  }
  double width() const { return hi_ - lo_; }
  double magnitude() const { return std::max(std::abs(lo_), std::abs(hi_)); }
  bool contains(double x) const { return lo_ <= x && x <= hi_; }
  bool contains_zero() const { return lo_ <= 0.0 && 0.0 <= hi_; }
  /// Whether this lies in the interior of b.
  bool interior_of(const IntervalNumber& b) const { return b.lo_ < lo_ && hi_ < b.hi_; }

  friend IntervalNumber operator-(const IntervalNumber& a) { return {-a.hi_, -a.lo_}; }
  friend IntervalNumber operator+(const IntervalNumber& a, const IntervalNumber& b) {
    return outward(a.lo_ + b.lo_, a.hi_ + b.hi_);
  }
  friend IntervalNumber operator-(const IntervalNumber& a, const IntervalNumber& b) {
    return outward(a.lo_ - b.hi_, a.hi_ - b.lo_);
  }
  /// Inline: the products dominate every interval evaluation (docs/benchmarks.md, profiles). The
  /// hull of the four end products; a point factor 0 gives 0 (also against an infinite end), and
  /// 0 * inf anywhere else gives the entire line (a valid enclosure).
  friend IntervalNumber operator*(const IntervalNumber& a, const IntervalNumber& b) {
    if ((a.lo_ == 0 && a.hi_ == 0) || (b.lo_ == 0 && b.hi_ == 0)) return IntervalNumber(0.0);
    const double p0 = a.lo_ * b.lo_, p1 = a.lo_ * b.hi_, p2 = a.hi_ * b.lo_, p3 = a.hi_ * b.hi_;
    if (std::isnan(p0) || std::isnan(p1) || std::isnan(p2) || std::isnan(p3)) return entire();
    return outward(std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3)));
  }
  /// Inline like the product; a divisor that may vanish gives the entire line.
  friend IntervalNumber operator/(const IntervalNumber& a, const IntervalNumber& b) {
    if (b.contains_zero()) return entire();
    const double p0 = a.lo_ / b.lo_, p1 = a.lo_ / b.hi_, p2 = a.hi_ / b.lo_, p3 = a.hi_ / b.hi_;
    if (std::isnan(p0) || std::isnan(p1) || std::isnan(p2) || std::isnan(p3)) return entire();
    return outward(std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3)));
  }
  friend IntervalNumber operator+(const IntervalNumber& a, double b) { return a + IntervalNumber(b); }
  friend IntervalNumber operator+(double a, const IntervalNumber& b) { return IntervalNumber(a) + b; }
  friend IntervalNumber operator-(const IntervalNumber& a, double b) { return a - IntervalNumber(b); }
  friend IntervalNumber operator-(double a, const IntervalNumber& b) { return IntervalNumber(a) - b; }
  friend IntervalNumber operator*(const IntervalNumber& a, double b) { return a * IntervalNumber(b); }
  friend IntervalNumber operator*(double a, const IntervalNumber& b) { return IntervalNumber(a) * b; }
  friend IntervalNumber operator/(const IntervalNumber& a, double b) { return a / IntervalNumber(b); }
  friend IntervalNumber operator/(double a, const IntervalNumber& b) { return IntervalNumber(a) / b; }
  IntervalNumber& operator+=(const IntervalNumber& b) { return *this = *this + b; }
  IntervalNumber& operator-=(const IntervalNumber& b) { return *this = *this - b; }
  IntervalNumber& operator*=(const IntervalNumber& b) { return *this = *this * b; }

  friend std::ostream& operator<<(std::ostream& os, const IntervalNumber& a) {
    return os << "[" << a.lo_ << ", " << a.hi_ << "]";
  }

 private:
  double lo_ = 0.0, hi_ = 0.0;
};

/// The hull of a and b.
IntervalNumber hull(const IntervalNumber& a, const IntervalNumber& b);
/// a intersected with b; *empty is set when they are disjoint (the result is then meaningless).
IntervalNumber intersect(const IntervalNumber& a, const IntervalNumber& b, bool* empty);

/// Generic code may branch on the midpoint only (core/jet.hpp, "primal value"); surfaces that
/// do (capsules) are not evaluated on intervals (evaluates_on_intervals,
/// start/certified_start_points.hpp); B-splines cut the box at their knot lines instead
/// (surface/piece_enclosure.hpp).
inline double primal(const IntervalNumber& x) { return x.mid(); }

IntervalNumber sqrt(const IntervalNumber& a);
IntervalNumber cbrt(const IntervalNumber& a);
IntervalNumber exp(const IntervalNumber& a);
IntervalNumber log(const IntervalNumber& a);
IntervalNumber sin(const IntervalNumber& a);
IntervalNumber cos(const IntervalNumber& a);
IntervalNumber tan(const IntervalNumber& a);
IntervalNumber asin(const IntervalNumber& a);
IntervalNumber acos(const IntervalNumber& a);
IntervalNumber atan(const IntervalNumber& a);
IntervalNumber sinh(const IntervalNumber& a);
IntervalNumber cosh(const IntervalNumber& a);
IntervalNumber tanh(const IntervalNumber& a);
IntervalNumber abs(const IntervalNumber& a);
IntervalNumber atan2(const IntervalNumber& y, const IntervalNumber& x);
IntervalNumber pow(const IntervalNumber& a, int n);
IntervalNumber pow(const IntervalNumber& a, double r);
IntervalNumber pow(const IntervalNumber& a, const IntervalNumber& b);

}  // namespace ssimarch
