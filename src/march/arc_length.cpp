#include "ssimarch/march/arc_length.hpp"

#include <algorithm>
#include <cmath>

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

// The shortfall of segment i from the three segments centred at j (j = i inside; the nearest
// interior window at an open curve's ends), segments indexed modulo m.
double segment_shortfall(const std::vector<Segment>& g, std::size_t i, std::size_t j) {
  const std::size_t m = g.size();
  const std::size_t w[3] = {(j + m - 1) % m, j, (j + 1) % m};
  for (std::size_t k : w)
    if (g[k].phi > kShortfallMaxTurn) return 0;
  if (g[i].phi > kShortfallMaxTurn) return 0;
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
  const double k = kappa(i), h = g[i].h;
  const double shortfall = std::pow(h, 5) / 1440 * (k1 * k1 - 2 * k * k2 + 3 * k * k * tau * tau);
  // Consistency: on a smooth curve resolved by the window the curvature changes across the
  // segment by less than a few times its largest value there, and the shortfall stays below
  // the circle's own correction at the window's largest turning angle, h Phi^2 / 24. Beyond it
  // the samples are noise (tangents at a node, steps of very different lengths): nothing added.
  const double turn = std::max({g[w[0]].phi, g[w[1]].phi, g[w[2]].phi, g[i].phi});
  return std::fabs(shortfall) <= h * turn * turn / 24 ? shortfall : 0.0;
}

}  // namespace

std::vector<double> arc_length_shortfalls(const std::vector<CurvePoint>& points, bool closed) {
  std::size_t n = points.size();
  // A closed curve's list may repeat its first point at the end: the closing segment is then
  // the last listed one, not one back to the start.
  if (closed && n > 1 && points.back().p == points.front().p) --n;
  const std::size_t m = closed ? n : (n > 0 ? n - 1 : 0);  // segments
  std::vector<double> out(m, 0.0);
  if (n < 2 || m < 3) return out;
  std::vector<Segment> g(m);
  for (std::size_t i = 0; i < m; ++i) {
    const CurvePoint &a = points[i], &b = points[(i + 1) % n];
    g[i].h = arc_length_estimate(a.p, a.t, b.p, b.t);
    g[i].phi = internal::angle_between(a.t, b.t);
    if (g[i].phi > kNoPlaneTurn) g[i].b = a.t.cross(b.t).normalized();
    if (!(g[i].h > 0)) return out;  // a repeated point: no differences to take
  }
  for (std::size_t i = 0; i < m; ++i)
    out[i] = segment_shortfall(g, i, closed ? i : std::clamp<std::size_t>(i, 1, m - 2));
  return out;
}

double arc_length_shortfall(const std::vector<CurvePoint>& points, bool closed) {
  double sum = 0;
  for (double s : arc_length_shortfalls(points, closed)) sum += s;
  return sum;
}

}  // namespace ssimarch
