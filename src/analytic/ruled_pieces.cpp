// The curves of a ruled section inside a region: docs/math/closed_form_quadrics.md, "Along the
// rulings" (clipping and sampling as for conics, "Clipping and sampling").
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "ssimarch/analytic/ruled_section.hpp"

#include "ssimarch/problem/closed_form_tolerances.hpp"

#include "chord_sampling.hpp"

namespace ssimarch {

namespace {

constexpr int kStartPieces = 16, kBoundaryBisections = 80;
// Samples of one loop beyond which the closed form gives up (the caller traces): a loop that runs
// far outside the region (rulings nearly along an asymptotic direction of Q, |t| ~ |b / a|) would
// need ~extent / max_chord samples to clip.
constexpr std::size_t kMaxSamples = 100000;
constexpr int kCoarseSamples = 256;
// Pieces of phi between which arc_length's chord sums are extrapolated: from 16 (a piece of a loop
// then turns by at most ~pi / 8, where the h^2 series converges fast) to 2^16 (arc lengths of
// curves that no finer sampling of an analytic loop would change; the rule stops far earlier).
constexpr std::size_t kMinLengthPieces = 16, kMaxLengthPieces = 65536;
// The coarse samples sit at phi = period (k + kNodeOffset) / kCoarseSamples: off phi = 0 and pi
// (an arc's turning points, where the derivative is a difference quotient) at every level of
// halving (0.3 times a power of 2 is never an integer).
constexpr double kNodeOffset = 0.3;

bool inside(const Vec3& p, const std::vector<Slab>& region) {
  if (!p.allFinite()) return false;
  for (const Slab& s : region)
    if (!s.contains(p)) return false;
  return true;
}

Vec3 at(const RuledCurves& rc, const RuledLoop& loop, double phi) {
  const Vec3T<double> p = rc.point(loop, phi);
  return {p.x, p.y, p.z};
}

// Arc length over [lo, hi] from chords of exact points: the chord sums S_n on n equal pieces of
// phi, extrapolated by Romberg's scheme (the curve is analytic in phi, so S_n = L - c1 h^2 - c2 h^4
// - ...: each chord is the arc less odd powers of h about its midpoint), n doubled until two
// extrapolations agree to kClosedFormLengthTolerance. Not |d point / d phi|: on a narrow loop
// (surfaces 1e-9 from touching: Delta ~ 1e-9 of its terms everywhere) the derivative carries the
// cancellation of sqrt(Delta), a relative error that grows to 1e-3 towards the loop's turning
// points, while the points' own error lies along the curve there (along the ruling) and cancels
// in a chord sum. Gauss-Legendre on the derivative gave a loop 1.5e-4 short. Doubling stops at
// kMaxLengthPieces (the noise floor of ~1e-16 relative per point is then reached long before).
double arc_length(const RuledCurves& rc, const RuledLoop& loop, double lo, double hi) {
  std::vector<Vec3> p{at(rc, loop, lo), at(rc, loop, hi)};
  std::vector<double> previous;  // the last Romberg row
  double best = (p[1] - p[0]).norm();
  for (std::size_t n = 2; n <= kMaxLengthPieces; n *= 2) {
    std::vector<Vec3> refined(n + 1);
    for (std::size_t i = 0; i <= n; ++i)
      refined[i] = i % 2 == 0 ? p[i / 2] : at(rc, loop, lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n));
    p = std::move(refined);
    double chords = 0;
    for (std::size_t i = 0; i < n; ++i) chords += (p[i + 1] - p[i]).norm();
    std::vector<double> row{chords};
    double factor = 4;
    for (std::size_t j = 0; j < previous.size(); ++j, factor *= 4)
      row.push_back(row[j] + (row[j] - previous[j]) / (factor - 1));
    const double converged_to = previous.empty() ? INFINITY : std::fabs(row.back() - previous.back());
    best = row.back();
    if (n >= kMinLengthPieces && converged_to <= kClosedFormLengthTolerance * std::fabs(best)) return best;
    previous = std::move(row);
  }
  return best;
}

// The length of a whole loop from |d point / d phi| at kCoarseSamples uniform nodes: the
// trapezoidal rule, exact to within 4 pi M / (exp(alpha N) - 1) for a periodic integrand analytic
// and bounded by M in the strip |Im phi| < alpha (Trefethen & Weideman, "The exponentially
// convergent trapezoidal rule", SIAM Review 56(3), 2014, Thm 3.2; rescaled to the period). The
// rule on every second node (N / 2) has the square root of that bound, so their difference
// measures the coarser one's error; the finer is taken when that difference is within
// kClosedFormLengthTolerance (its own error is smaller still by exp(-alpha N / 2)). None when it
// is not (a loop whose integrand has a singularity close to the real axis: Gauss-Legendre then).
std::optional<double> periodic_length(const std::vector<double>& speed, double period) {
  double all = 0, even = 0;
  for (std::size_t k = 0; k < speed.size(); ++k) (k % 2 == 0 ? even : all) += speed[k];
  all += even;
  const double fine = all * period / static_cast<double>(speed.size());
  const double coarse = even * period / static_cast<double>(speed.size() / 2);
  if (!std::isfinite(fine) || !(std::fabs(fine - coarse) <= kClosedFormLengthTolerance * fine)) return std::nullopt;
  return fine;
}

// The parameters in [0, period) where `loop` passes a crossing point (theta = tau, a double root
// of Delta, where both sheets meet): an arc passes theta twice (cos phi = (mid - tau) / half), a
// circle once per turn.
std::vector<double> crossing_parameters(const RuledLoop& loop, const std::vector<double>& crossings) {
  std::vector<double> out;
  const double two_pi = 2 * M_PI;
  for (double tau : crossings) {
    if (loop.arc) {
      const double u = tau < loop.lo ? tau + two_pi : tau;
      if (!(u > loop.lo && u < loop.hi)) continue;
      const double phi = std::acos(std::clamp((0.5 * (loop.lo + loop.hi) - u) / (0.5 * (loop.hi - loop.lo)), -1.0, 1.0));
      out.push_back(phi);
      out.push_back(two_pi - phi);
    } else {
      const double phi = tau - loop.lo - two_pi * std::floor((tau - loop.lo) / two_pi);
      for (int k = 0; k < loop.turns; ++k) out.push_back(phi + two_pi * k);
    }
  }
  return out;
}

// Adds the crossing parameters (taken modulo the period) inside (lo, hi) to the sorted samples,
// so that the crossing points are output points of the curve, as the tracer's are.
void add_crossings(std::vector<double>* params, const std::vector<double>& crossing, double period, double lo, double hi) {
  const double tiny = 1e-12 * period;
  for (double c : crossing)
    for (int k = -1; k <= 2; ++k) {
      const double phi = c + k * period;
      if (!(phi > lo + tiny && phi < hi - tiny)) continue;
      const auto it = std::lower_bound(params->begin(), params->end(), phi);
      if ((it != params->end() && *it - phi <= tiny) || (it != params->begin() && phi - *(it - 1) <= tiny)) continue;
      params->insert(it, phi);
    }
}

// The curve through the samples of [lo, hi] (given when the caller has them already: a whole
// loop) and the crossing points in it; `length`: its length when the caller has it.
std::optional<TracedCurve> make_curve(const RuledCurves& rc, const RuledLoop& loop, double lo, double hi, bool closed,
                                      double deviation, double max_chord, const std::vector<double>& crossing,
                                      std::optional<std::vector<double>> params = std::nullopt,
                                      std::optional<double> length = std::nullopt) {
  TracedCurve curve;
  curve.closed = closed;
  if (!params)
    params = internal::sample_chord_parameters([&](double t) { return at(rc, loop, t); }, lo, hi, deviation, max_chord, kStartPieces, kMaxSamples);
  if (!params) return std::nullopt;
  add_crossings(&*params, crossing, loop.period(), lo, hi);
  curve.points.reserve(params->size());
  for (double phi : *params) {
    CurvePoint p;
    const auto [point, d] = rc.point_and_derivative(loop, phi);
    p.p = point;
    p.x = p.p;
    p.t = d.norm() > 0 ? Vec3(d.normalized()) : Vec3::Zero();
    curve.points.push_back(std::move(p));
  }
  if (closed) curve.points.back() = curve.points.front();
  curve.length = length ? *length : arc_length(rc, loop, lo, hi);
  curve.start_end = curve.end_end = closed ? Termination::kClosedLoop : Termination::kLeftDomain;
  if (!closed) curve.start_message = curve.end_message = "closed form: the curve leaves the region (box or trim)";
  return curve;
}

// The parameter between a (inside) and b (outside) where the loop leaves the region.
double boundary(const RuledCurves& rc, const RuledLoop& loop, const std::vector<Slab>& region, double a, double b) {
  for (int i = 0; i < kBoundaryBisections; ++i) {
    const double m = 0.5 * (a + b);
    if (!(m != a && m != b)) break;
    (inside(at(rc, loop, m), region) ? a : b) = m;
  }
  return a;
}

}  // namespace

std::optional<std::vector<TracedCurve>> ruled_curves_in(const RuledCurves& rc, const RuledSection& section,
                                                        const std::vector<Slab>& region, double deviation,
                                                        double max_chord) {
  std::vector<TracedCurve> out;
  auto add = [&](std::optional<TracedCurve> c) {
    if (c) out.push_back(std::move(*c));
    return c.has_value();
  };
  for (const RuledLoop& loop : section.loops) {
    const double L = loop.period();
    const std::vector<double> crossing = crossing_parameters(loop, section.crossings);
    // A coarse polyline first: a loop that runs far outside the region needs more samples than
    // the cap, which it need not spend to find out. Its uniform nodes, with the derivative, also
    // give a whole loop's length (periodic_length).
    double coarse = 0;
    std::vector<double> speed(kCoarseSamples);
    Vec3 first = Vec3::Zero(), last = Vec3::Zero();
    for (int k = 0; k < kCoarseSamples; ++k) {
      const auto [p, d] = rc.point_and_derivative(loop, L * (k + kNodeOffset) / kCoarseSamples);
      speed[static_cast<std::size_t>(k)] = d.norm();
      if (k == 0) first = p;
      else coarse += (p - last).norm();
      last = p;
    }
    coarse += (first - last).norm();
    if (!(coarse / max_chord < static_cast<double>(kMaxSamples))) return std::nullopt;
    auto sampled = internal::sample_chords([&](double p) { return at(rc, loop, p); }, 0, L, deviation, max_chord, kStartPieces,
                                           kMaxSamples);
    if (!sampled) return std::nullopt;
    const std::vector<double> whole = sampled->t;
    std::vector<double>& t = sampled->t;
    t.pop_back();  // t = L is t = 0 again
    const std::size_t n = t.size();
    std::vector<bool> in(n);
    std::size_t first_out = n;
    for (std::size_t i = 0; i < n; ++i) {
      in[i] = inside(sampled->p[i], region);
      if (!in[i] && first_out == n) first_out = i;
    }
    if (first_out == n) {
      if (!add(make_curve(rc, loop, 0, L, true, deviation, max_chord, crossing, whole, periodic_length(speed, L)))) return std::nullopt;
      continue;
    }
    // Walk once round from an outside sample: each entry to its exit is one open piece.
    double enter = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (first_out + k) % n, j = (i + 1) % n;
      const double ti = t[i] + (i < first_out ? L : 0.0);
      const double tj = t[j] + (j <= first_out ? L : 0.0);
      if (!in[i] && in[j]) enter = boundary(rc, loop, region, tj, ti);
      if (in[i] && !in[j]) {
        const double leave = boundary(rc, loop, region, ti, tj);
        if (leave > enter && !add(make_curve(rc, loop, enter, leave, false, deviation, max_chord, crossing))) return std::nullopt;
      }
    }
  }
  return out;
}

}  // namespace ssimarch
