// Adaptive sampling of a closed-form curve by chords, shared by the conics (conic_pieces.cpp) and
// the curves along rulings (ruled_pieces.cpp), internal to analytic/.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch::internal {

/// Parameters from lo to hi (both included) whose chords are within `deviation` of the curve f and
/// at most `max_chord` long: [lo, hi] cut into `start_pieces` equal pieces (so that no symmetric
/// chord hides a bulge), each chord bisected until its midpoint is close enough, at most 40 times.
/// None when more than `max_samples` parameters would be needed.
inline std::optional<std::vector<double>> sample_chord_parameters(const std::function<Vec3(double)>& f, double lo, double hi,
                                                                  double deviation, double max_chord, int start_pieces,
                                                                  std::size_t max_samples) {
  constexpr int kMaxDepth = 40;
  std::vector<double> out{lo};
  std::vector<std::pair<double, int>> todo;  // (end parameter, depth), the last processed first
  const double h = (hi - lo) / start_pieces;
  for (int j = start_pieces; j >= 1; --j) todo.push_back({j == start_pieces ? hi : lo + j * h, 0});
  double t0 = lo;
  Vec3 a = f(lo);
  while (!todo.empty()) {
    const auto [t1, depth] = todo.back();
    const Vec3 b = f(t1), m = f(0.5 * (t0 + t1));
    const Vec3 chord = b - a;
    const double len = chord.norm();
    const double sag = len > 0 ? (m - a - (m - a).dot(chord) / (len * len) * chord).norm() : (m - a).norm();
    if (depth < kMaxDepth && (sag > deviation || len > max_chord)) {
      todo.back().second = depth + 1;
      todo.push_back({0.5 * (t0 + t1), depth + 1});
      continue;
    }
    todo.pop_back();
    out.push_back(t1);
    if (out.size() > max_samples) return std::nullopt;
    t0 = t1;
    a = b;
  }
  return out;
}

}  // namespace ssimarch::internal
