// Intervals on a line or a circle (internal to porosity: the union of particles). A particle meets
// a vertical line in a chord and a horizontal circle in arcs; the part of one particle covered by
// earlier ones is the length of its intervals inside the merge of theirs (particle_union.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

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

}  // namespace ssimarch::internal
