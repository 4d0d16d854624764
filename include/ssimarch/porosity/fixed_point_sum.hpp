// Order-independent sums of doubles. Each term is rounded once to a multiple of a fixed quantum
// 2^q (q chosen from the size of the total, e.g. 96 binary digits below the profile's norm) and
// added as a 128-bit integer; integer addition is associative, so the total has the same bits
// whatever the order of the terms and however they are split over chunks, threads or MPI ranks
// (docs/scaling.md, "Determinism"). The rounding of one term is at most 2^(q-1): with q = e - 96
// for a total of size 2^e, a hundred million terms lose less than 1e-20 relative.
#pragma once

#include <cmath>
#include <cstdint>

namespace ssimarch {

class FixedPointSum {
 public:
  /// Binary digits kept below the magnitude of `scale` (the largest total expected; terms up to
  /// 2^30 times `scale` still fit in the 127-bit integer).
  static constexpr int kDigitsBelowScale = 96;

  FixedPointSum() = default;
  /// Quantum 2^(ilogb(scale) - kDigitsBelowScale); scale > 0 and finite.
  explicit FixedPointSum(double scale)
      : exponent_(std::ilogb(scale) - kDigitsBelowScale), factor_(std::ldexp(1.0, -exponent_)) {}

  void add(double v) {
    if (v == 0) return;
    // Scaling by a power of two is exact (a product by factor_ when 2^-exponent is a normal double,
    // else ldexp: both correctly rounded, so the same bits); nearbyint rounds once.
    const double x = std::nearbyint(std::isnormal(factor_) ? v * factor_ : std::ldexp(v, -exponent_));
    total_ += to_int(x);
  }
  FixedPointSum& operator+=(const FixedPointSum& o) {
    total_ += o.total_;
    return *this;
  }
  double value() const { return std::ldexp(static_cast<double>(total_), exponent_); }

  /// The integer as two 64-bit words (low first), for message passing; `set_words` restores it.
  void words(std::uint64_t out[2]) const {
    const auto u = static_cast<UInt>(total_);
    out[0] = static_cast<std::uint64_t>(u);
    out[1] = static_cast<std::uint64_t>(u >> 64);
  }
  void set_words(const std::uint64_t in[2]) {
    total_ = static_cast<Int>((static_cast<UInt>(in[1]) << 64) | static_cast<UInt>(in[0]));
  }
  int exponent() const { return exponent_; }

 private:
  __extension__ typedef __int128 Int;  // GCC/Clang: 128-bit two's complement; wrap-around via UInt
  __extension__ typedef unsigned __int128 UInt;
  // An integral double |x| <= 2^126 as a 128-bit integer, exactly: through 64-bit conversions
  // (one instruction each) instead of the library's double -> __int128 call. Below 2^63 directly;
  // else x = hi 2^64 + mid 2^32 + lo with every part exact (multiples of ulp(x), under 2^53).
  static Int to_int(double x) {
    if (std::abs(x) < 0x1p63) return static_cast<Int>(static_cast<long long>(x));
    const double hi = std::trunc(x * 0x1p-64), rest = x - hi * 0x1p64;
    const double mid = std::trunc(rest * 0x1p-32), lo = rest - mid * 0x1p32;
    return static_cast<Int>(static_cast<long long>(hi)) * (Int{1} << 64) +
           static_cast<Int>(static_cast<long long>(mid)) * (Int{1} << 32) + static_cast<Int>(static_cast<long long>(lo));
  }

  int exponent_ = 0;
  double factor_ = 1.0;
  Int total_ = 0;
};

/// Adds two totals given as word pairs (low first), as 128-bit two's complement integers: the
/// reduction operator of a message-passing sum.
inline void add_fixed_point_words(const std::uint64_t a[2], std::uint64_t b[2]) {
  const std::uint64_t lo = a[0] + b[0];
  b[1] = a[1] + b[1] + (lo < a[0] ? 1 : 0);
  b[0] = lo;
}

}  // namespace ssimarch
