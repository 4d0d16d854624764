// docs/math/closed_form_quadrics.md, "Clipping and sampling".
#include "ssimarch/analytic/conic_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "chord_sampling.hpp"
#include "ssimarch/core/gauss_legendre.hpp"

namespace ssimarch {

namespace {

// Real roots of q2 t^2 + q1 t + q0 (q2 may be 0).
std::vector<double> roots2(double q2, double q1, double q0) {
  if (q2 == 0) return q1 == 0 ? std::vector<double>{} : std::vector<double>{-q0 / q1};
  const double disc = q1 * q1 - 4 * q2 * q0;
  if (disc < 0) return {};
  const double s = -0.5 * (q1 + std::copysign(std::sqrt(disc), q1));
  if (s == 0) return {0.0};
  return {s / q2, q0 / s};
}

// Parameters where n . point(t) equals `level`.
std::vector<double> crossings(const Conic& c, const Vec3& n, double level) {
  const double m = level - n.dot(c.center);
  const double n0 = n.dot(c.e0), n1 = n.dot(c.e1);
  switch (c.type) {
    case ConicType::kCircle:
    case ConicType::kEllipse: {  // A cos t + B sin t = m
      const double A = c.a * n0, B = c.b * n1, R = std::hypot(A, B);
      if (R == 0 || std::fabs(m) > R) return {};
      const double phi = std::atan2(B, A), w = std::acos(m / R);
      return {phi + w, phi - w};
    }
    case ConicType::kHyperbola: {  // A cosh t + B sinh t = m; w = e^t: (A+B) w^2 - 2 m w + (A-B) = 0
      const double A = c.a * n0, B = c.b * n1;
      std::vector<double> t;
      for (double w : roots2(A + B, -2 * m, A - B))
        if (w > 0) t.push_back(std::log(w));
      return t;
    }
    case ConicType::kParabola: return roots2(n0 / (4 * c.a), n1, -m);
    case ConicType::kLine: return n0 == 0 ? std::vector<double>{} : std::vector<double>{m / n0};
    case ConicType::kPoint: return {};
  }
  return {};
}

bool inside(const Vec3& p, const std::vector<Slab>& slabs, double slack) {
  for (const Slab& s : slabs) {
    const double x = s.normal.dot(p);
    if (x < s.range.lo - slack || x > s.range.hi + slack) return false;
  }
  return true;
}

Conic with_range(Conic c, double lo, double hi) {
  c.range = {lo, hi};
  return c;
}

// Consecutive inside intervals that share an end (the conic touched a face) become one.
std::vector<Interval> merged(std::vector<Interval> in) {
  std::vector<Interval> out;
  for (const Interval& r : in) {
    if (!out.empty() && out.back().hi == r.lo) out.back().hi = r.hi;
    else out.push_back(r);
  }
  return out;
}

}  // namespace

bool is_whole(const Conic& piece) {
  return piece.periodic() && piece.range.hi - piece.range.lo >= (2 * std::numbers::pi);
}

std::vector<Slab> box_slabs(const std::array<Interval, 3>& box) {
  return {{Vec3::UnitX(), box[0]}, {Vec3::UnitY(), box[1]}, {Vec3::UnitZ(), box[2]}};
}

std::vector<Conic> clip_to_slabs(const Conic& c, const std::vector<Slab>& slabs) {
  double extent = 0;
  for (const Slab& s : slabs) extent = std::max(extent, s.range.width());
  const double slack = 1e-12 * extent;
  if (c.type == ConicType::kPoint) return inside(c.center, slabs, slack) ? std::vector<Conic>{c} : std::vector<Conic>{};
  std::vector<double> t;
  for (const Slab& slab : slabs)
    for (double level : {slab.range.lo, slab.range.hi})
      for (double s : crossings(c, slab.normal, level))
        t.push_back(c.periodic() ? s - (2 * std::numbers::pi) * std::floor(s / (2 * std::numbers::pi)) : s);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  if (c.periodic()) {
    if (t.empty())
      return inside(c.point(0), slabs, slack) ? std::vector<Conic>{with_range(c, 0, (2 * std::numbers::pi))}
                                              : std::vector<Conic>{};
    t.push_back(t.front() + (2 * std::numbers::pi));
  }
  std::vector<Interval> keep;
  for (std::size_t k = 0; k + 1 < t.size(); ++k)
    if (t[k + 1] > t[k] && inside(c.point(0.5 * (t[k] + t[k + 1])), slabs, slack)) keep.push_back({t[k], t[k + 1]});
  keep = merged(keep);
  // Around a periodic conic the last piece may continue into the first.
  if (c.periodic() && keep.size() > 1 && keep.back().hi == keep.front().lo + (2 * std::numbers::pi)) {
    keep.front().lo = keep.back().lo - (2 * std::numbers::pi);
    keep.pop_back();
  }
  std::vector<Conic> out;
  for (const Interval& r : keep) out.push_back(with_range(c, r.lo, r.hi));
  return out;
}

double conic_length(const Conic& c) {
  // 8-point Gauss-Legendre on each of n equal sub-intervals, n doubled until two agree.
  const auto& x = kGaussLegendre8Nodes;
  const auto& w = kGaussLegendre8Weights;
  auto rule = [&](int n) {
    const double h = (c.range.hi - c.range.lo) / n;
    double sum = 0;
    for (int j = 0; j < n; ++j) {
      const double mid = c.range.lo + (j + 0.5) * h;
      for (int k = 0; k < 4; ++k)
        sum += w[k] * (c.derivative(mid + 0.5 * h * x[k]).norm() + c.derivative(mid - 0.5 * h * x[k]).norm());
    }
    return 0.5 * h * sum;
  };
  double prev = rule(4);
  for (int n = 8; n <= 4096; n *= 2) {
    const double next = rule(n);
    if (std::fabs(next - prev) <= 1e-14 * std::fabs(next)) return next;
    prev = next;
  }
  return prev;
}

TracedCurve sample_conic(const Conic& c, double deviation, double max_chord) {
  TracedCurve curve;
  curve.closed = is_whole(c);
  auto add = [&](double t) {
    CurvePoint p;
    p.p = c.point(t);
    p.x = p.p;
    const Vec3 d = c.derivative(t);
    p.t = d.norm() > 0 ? Vec3(d.normalized()) : Vec3::Zero();
    curve.points.push_back(std::move(p));
  };
  // Start from 8 pieces; no bound on the count (a conic's curvature is bounded in its range).
  const auto params = internal::sample_chord_parameters([&](double t) { return Vec3(c.point(t)); }, c.range.lo, c.range.hi,
                                                        deviation, max_chord, 8, std::numeric_limits<std::size_t>::max());
  for (double t : *params) add(t);
  if (curve.closed) curve.points.back() = curve.points.front();
  curve.length = conic_length(c);
  curve.start_end = curve.end_end = curve.closed ? Termination::kClosedLoop : Termination::kLeftDomain;
  if (!curve.closed) curve.start_message = curve.end_message = "closed form: the conic leaves the region (box or trim)";
  return curve;
}

}  // namespace ssimarch
