#include "ssimarch/march/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "march_steps.hpp"
#include "ssimarch/march/tracer.hpp"

namespace ssimarch {

namespace {

// One segment's circular-arc data: its length estimate, turning angle and osculating plane.
struct Segment {
  double h = 0, phi = 0;
  Vec3 b = Vec3::Zero();  // unit binormal t_a x t_b (zero where the tangents are parallel)
};

// Below this turning angle (radians) the binormal t_a x t_b is rounding noise: the segment's
// curvature is 0 to that precision and it gives no osculating plane.
constexpr double kNoPlaneTurn = 1e-12;

// What the circle's estimate may be off by where no shortfall is added: its own correction at
// the largest turning angle `turn` that the window saw.
double unresolved_error(double h, double turn) { return h * turn * turn / 24; }

// The shortfall of segment i from the three segments centred at j (segments indexed modulo m;
// i is j or one of its neighbours); empty where the window does not resolve the curve. *turn:
// the window's largest turning angle.
std::optional<double> window_shortfall(const std::vector<Segment>& g, std::size_t i, std::size_t j, double* turn) {
  const std::size_t m = g.size();
  const std::size_t w[3] = {(j + m - 1) % m, j, (j + 1) % m};
  *turn = std::max({g[w[0]].phi, g[w[1]].phi, g[w[2]].phi, g[i].phi});
  const double h = g[i].h;
  if (*turn > kShortfallMaxTurn) return std::nullopt;
  // Signs relative to the best-defined osculating plane of the window: through an inflection
  // (the lemniscate's node) the binormal flips and the signed curvature passes through 0.
  const Vec3 ref = g[*std::max_element(w, w + 3, [&](std::size_t a, std::size_t b) { return g[a].phi < g[b].phi; })].b;
  auto kappa = [&](std::size_t k) { return (g[k].b.dot(ref) < 0 ? -1.0 : 1.0) * g[k].phi / g[k].h; };
  const double d1 = (g[w[0]].h + g[w[1]].h) / 2, d2 = (g[w[1]].h + g[w[2]].h) / 2;
  const double s1 = (kappa(w[1]) - kappa(w[0])) / d1, s2 = (kappa(w[2]) - kappa(w[1])) / d2;
  const double k2 = 2 * (s2 - s1) / (d1 + d2);         // kappa'' at the middle segment
  double k1 = (s1 * d2 + s2 * d1) / (d1 + d2);         // kappa' there (nonuniform central difference)
  if (i != j) k1 += k2 * (i == w[0] ? -d1 : d2);       // carried to an end segment
  double tau = 0;                                      // the osculating plane's turning rate
  if (g[w[0]].phi > kNoPlaneTurn && g[w[2]].phi > kNoPlaneTurn) {
    const Vec3 b0 = g[w[0]].b.dot(ref) < 0 ? Vec3(-g[w[0]].b) : g[w[0]].b;
    const Vec3 b2 = g[w[2]].b.dot(ref) < 0 ? Vec3(-g[w[2]].b) : g[w[2]].b;
    tau = internal::angle_between(b0, b2) / (d1 + d2);
  }
  const double k = kappa(i);
  const double shortfall = std::pow(h, 5) / 1440 * (k1 * k1 - 2 * k * k2 + 3 * k * k * tau * tau);
  // Consistency: on a smooth curve resolved by the window the curvature changes across the
  // segment by less than a few times its largest value there, and the shortfall stays below
  // the circle's own correction at the window's largest turning angle, h Phi^2 / 24. Beyond it
  // the samples are noise (tangents at a node, steps of very different lengths): nothing added.
  if (!(std::fabs(shortfall) <= unresolved_error(h, *turn))) return std::nullopt;
  return shortfall;
}

// Segment i's shortfall from the window centred at j (j = i inside; the nearest interior window
// at an open curve's ends) and what may remain wrong: the next term of the expansion, smaller by
// about (h kappa)^2 <= turn^2 (at an open end the whole shortfall), or, where the windows beside
// it give another value (steps of very different lengths, the curvature changing faster than the
// differences follow), the difference.
SegmentLength segment_shortfall(const std::vector<Segment>& g, std::size_t i, std::size_t j, bool closed) {
  const std::size_t m = g.size();
  const double h = g[i].h;
  double turn = 0;
  const std::optional<double> s = window_shortfall(g, i, j, &turn);
  if (!s) return {h, 0.0, unresolved_error(h, turn)};
  // An open curve's end segment takes its neighbour's window, kappa' carried by one difference:
  // an extrapolation, which may miss all of it.
  double error = i == j ? std::fabs(*s) * std::min(1.0, turn * turn) : std::fabs(*s);
  for (const std::size_t k : {(j + m - 1) % m, (j + 1) % m}) {
    const bool window = closed ? m > 3 : (k >= 1 && k + 2 <= m && (k + 1 >= i && k <= i + 1) && k != j);
    double other_turn = 0;
    if (window)
      if (const std::optional<double> t = window_shortfall(g, i, k, &other_turn))
        error = std::max(error, std::fabs(*t - *s));
  }
  return {h, *s, error};
}

}  // namespace

std::vector<SegmentLength> segment_length_estimates(const std::vector<CurvePoint>& points, bool closed) {
  std::size_t n = points.size();
  // A closed curve's list may repeat its first point at the end: the closing segment is then
  // the last listed one, not one back to the start.
  if (closed && n > 1 && points.back().p == points.front().p) --n;
  const std::size_t m = closed ? n : (n > 0 ? n - 1 : 0);  // segments
  std::vector<Segment> g(m);
  std::vector<SegmentLength> out(m);
  bool differences = m >= 3;
  for (std::size_t i = 0; i < m; ++i) {
    const CurvePoint &a = points[i], &b = points[(i + 1) % n];
    g[i].h = arc_length_estimate(a.p, a.t, b.p, b.t);
    g[i].phi = internal::angle_between(a.t, b.t);
    if (g[i].phi > kNoPlaneTurn) g[i].b = a.t.cross(b.t).normalized();
    if (!(g[i].h > 0)) differences = false;  // a repeated point: no differences to take
    out[i] = {g[i].h, 0.0, unresolved_error(g[i].h, g[i].phi)};
  }
  if (differences)
    for (std::size_t i = 0; i < m; ++i)
      out[i] = segment_shortfall(g, i, closed ? i : std::clamp<std::size_t>(i, 1, m - 2), closed);
  return out;
}

std::vector<double> recorded_segment_lengths(const TracedCurve& c) {
  const std::size_t n = c.points.size();
  if (n < 2) return {};
  if (c.segment_lengths.size() + 1 == n) return c.segment_lengths;
  const std::vector<SegmentLength> s = segment_length_estimates(c.points, c.closed);
  std::vector<double> out(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i)
    out[i] = i < s.size() ? s[i].estimate + s[i].shortfall
                          : arc_length_estimate(c.points[i].p, c.points[i].t, c.points[i + 1].p, c.points[i + 1].t);
  return out;
}

std::vector<double> arc_length_shortfalls(const std::vector<CurvePoint>& points, bool closed) {
  std::vector<double> out;
  for (const SegmentLength& s : segment_length_estimates(points, closed)) out.push_back(s.shortfall);
  return out;
}

double arc_length_shortfall(const std::vector<CurvePoint>& points, bool closed) {
  double sum = 0;
  for (double s : arc_length_shortfalls(points, closed)) sum += s;
  return sum;
}

}  // namespace ssimarch
