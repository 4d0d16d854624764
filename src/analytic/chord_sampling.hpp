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

/// Parameters from lo to hi (both included) and the curve's points there.
struct ChordSamples {
  std::vector<double> t;
  std::vector<Vec3> p;
};

/// Parameters from lo to hi (both included) whose chords are within `deviation` of the curve f and
/// at most `max_chord` long: [lo, hi] cut into `start_pieces` equal pieces (so that no symmetric
/// chord hides a bulge), each chord bisected until its midpoint is close enough, at most 40 times.
/// The points come with them: f is evaluated once per parameter tested (a rejected chord's
/// midpoint is the end of its first half). None when more than `max_samples` parameters would be
/// needed.
inline std::optional<ChordSamples> sample_chords(const std::function<Vec3(double)>& f, double lo, double hi, double deviation,
                                                 double max_chord, int start_pieces, std::size_t max_samples) {
  constexpr int kMaxDepth = 40;
  struct Pending {
    double t;  // end parameter
    int depth;
    bool known;  // p = f(t) already
    Vec3 p;
  };
  ChordSamples out{{lo}, {f(lo)}};
  std::vector<Pending> todo;  // the last processed first
  const double h = (hi - lo) / start_pieces;
  for (int j = start_pieces; j >= 1; --j) todo.push_back({j == start_pieces ? hi : lo + j * h, 0, false, Vec3::Zero()});
  double t0 = lo;
  Vec3 a = out.p.back();
  while (!todo.empty()) {
    Pending& e = todo.back();
    if (!e.known) e.p = f(e.t), e.known = true;
    const double t1 = e.t, tm = 0.5 * (t0 + t1);
    const int depth = e.depth;
    const Vec3 b = e.p, m = f(tm);
    const Vec3 chord = b - a;
    const double len = chord.norm();
    const double sag = len > 0 ? (m - a - (m - a).dot(chord) / (len * len) * chord).norm() : (m - a).norm();
    if (depth < kMaxDepth && (sag > deviation || len > max_chord)) {
      e.depth = depth + 1;
      todo.push_back({tm, depth + 1, true, m});
      continue;
    }
    todo.pop_back();
    out.t.push_back(t1);
    out.p.push_back(b);
    if (out.t.size() > max_samples) return std::nullopt;
    t0 = t1;
    a = b;
  }
  return out;
}

/// The parameters of sample_chords alone.
inline std::optional<std::vector<double>> sample_chord_parameters(const std::function<Vec3(double)>& f, double lo, double hi,
                                                                  double deviation, double max_chord, int start_pieces,
                                                                  std::size_t max_samples) {
  auto s = sample_chords(f, lo, hi, deviation, max_chord, start_pieces, max_samples);
  if (!s) return std::nullopt;
  return std::move(s->t);
}

}  // namespace ssimarch::internal
