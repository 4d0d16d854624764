// Intervals on a line or a circle (internal to porosity: the union of particles). A particle meets
// a vertical line in a chord and a horizontal circle in arcs; the part of one particle covered by
// earlier ones is the length of its intervals inside the merge of theirs (particle_union.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch::internal {

struct Span {
  double lo = 0.0, hi = 0.0;
};

/// Length of `own` inside the union of `others` (sorted in place by lower end). Own spans are
/// disjoint; other spans may overlap each other.
inline double covered_length(const std::vector<Span>& own, std::vector<Span>& others) {
  if (own.empty() || others.empty()) return 0.0;
  std::sort(others.begin(), others.end(), [](const Span& a, const Span& b) { return a.lo < b.lo; });
  double total = 0.0;
  for (const Span& o : own) {
    // Sweep the others clipped to o, adding the length of their union.
    double reach = o.lo;
    for (const Span& s : others) {
      if (s.lo >= o.hi) break;
      const double lo = std::max(s.lo, reach), hi = std::min(s.hi, o.hi);
      if (hi > lo) {
        total += hi - lo;
        reach = hi;
      }
    }
  }
  return total;
}

/// Appends the arc [begin, begin + length] of the circle (length in (0, 2 pi]) as spans within
/// [-pi, pi], split where it passes theta = pi.
inline void add_arc(std::vector<Span>& out, double begin, double length) {
  constexpr double pi = std::numbers::pi;
  if (!(length > 0)) return;
  if (length >= 2 * pi) {
    out.push_back({-pi, pi});
    return;
  }
  const double b = std::remainder(begin, 2 * pi), e = b + length;
  if (e <= pi) {
    out.push_back({b, e});
  } else {
    out.push_back({b, pi});
    out.push_back({-pi, e - 2 * pi});
  }
}

/// Angular window [lo, hi] (hi - lo <= 2 pi) of the circles about the z axis that holds every
/// point of the box [box_lo, box_hi] (its corners' angles, or the whole circle when the box holds
/// the axis).
inline std::pair<double, double> angular_window(const Vec3& box_lo, const Vec3& box_hi) {
  constexpr double pi = std::numbers::pi;
  const double x0 = box_lo.x(), x1 = box_hi.x(), y0 = box_lo.y(), y1 = box_hi.y();
  if (x0 <= 0 && x1 >= 0 && y0 <= 0 && y1 >= 0) return {-pi, pi};
  const double phi = std::atan2((y0 + y1) / 2, (x0 + x1) / 2);
  double lo = 0, hi = 0;
  for (double x : {x0, x1})
    for (double y : {y0, y1}) {
      const double d = std::remainder(std::atan2(y, x) - phi, 2 * pi);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  return {phi + lo, phi + hi};
}

/// Sorted breakpoints inside [lo, hi], the ends included and duplicates dropped; with `periodic`
/// the values are angles, each shifted by a multiple of 2 pi into [lo, lo + 2 pi).
inline void breakpoints_in(std::vector<double>& out, const std::vector<double>& values, double lo, double hi,
                           bool periodic) {
  constexpr double two_pi = 2 * std::numbers::pi;
  out.assign({lo, hi});
  for (double t : values) {
    if (periodic) t = lo + std::fmod(std::fmod(t - lo, two_pi) + two_pi, two_pi);
    if (t > lo && t < hi) out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

inline std::vector<double> breakpoints_in(const std::vector<double>& values, double lo, double hi, bool periodic) {
  std::vector<double> out;
  breakpoints_in(out, values, lo, hi, periodic);
  return out;
}

}  // namespace ssimarch::internal
