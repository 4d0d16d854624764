#include "ssimarch/pipeline/parameter_loops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace ssimarch {

namespace {

// Samples per boundary curve: the parity test needs the loops' topology in (u, v), not their
// shape to the tolerance (points near the boundary are decided in 3D by face_clip), and 64 keeps
// a full circle's chords within 0.1 % of its radius.
constexpr int kSamplesPerCurve = 64;
// Relative nudge of the ray's abscissa (of the loops' extent along it): far below the 3D band
// inside which face_clip decides a point's side in 3D instead.
constexpr double kAbscissaNudge = 1e-9;

// x moved by whole periods to lie within half a period of `near` (periodic directions only).
double nearest_image(double x, double near, double period) {
  if (!(period > 0)) return x;
  return x - period * std::round((x - near) / period);
}

}  // namespace

std::optional<ParameterLoops> ParameterLoops::build(const FaceRegion& region, const Surface& surface) {
  if (!surface.is_parametric() || region.boundary_curves() == 0) return std::nullopt;
  const ParamDomain& d = surface.domain();
  const double period[2] = {d.periodic_u ? d.u.width() : 0.0, d.periodic_v ? d.v.width() : 0.0};
  ParameterLoops out;
  // Each curve unwrapped by continuity, its start put at the image nearest the previous curve's
  // end (a loop's curves are chained) or, for the first, the first curve's start.
  Vec2 previous_end = Vec2::Zero();
  std::optional<Vec2> first;
  for (int i = 0; i < region.boundary_curves(); ++i) {
    const auto [lo, hi] = region.boundary_range(i);
    Vec2 prev = Vec2::Zero();
    Vec3 prev_p = Vec3::Zero();
    for (int k = 0; k <= kSamplesPerCurve; ++k) {
      const Vec3 p = region.boundary_point(i, lo + (hi - lo) * k / kSamplesPerCurve);
      if (k > 0) {
        const Vec3 mid = region.boundary_point(i, lo + (hi - lo) * (k - 0.5) / kSamplesPerCurve);
        out.resolution_ = std::max(out.resolution_, (mid - 0.5 * (p + prev_p)).norm());
      }
      prev_p = p;
      std::optional<Vec2> uv = k == 0 ? closest_parameters(surface, p) : refine_closest_parameters(surface, p, prev);
      if (!uv || !uv->allFinite()) return std::nullopt;
      out.edge_gap_ = std::max(out.edge_gap_, (p - point(surface, (*uv)[0], (*uv)[1])).norm());
      Vec2 w = *uv;
      const Vec2 anchor = k > 0 ? prev : (first ? previous_end : w);
      for (int c = 0; c < 2; ++c) w[c] = nearest_image(w[c], anchor[c], period[c]);
      if (!first) first = w;
      if (k > 0) out.segments_.push_back({prev, w});
      prev = w;
    }
    previous_end = prev;
  }
  // The ray runs along a parameter the face does not go round: a bounded one, else a periodic one
  // whose loops span less than a period.
  auto extent = [&](int c) {
    double a = std::numeric_limits<double>::infinity(), b = -a;
    for (const Segment& s : out.segments_) a = std::min({a, s.a[c], s.b[c]}), b = std::max({b, s.a[c], s.b[c]});
    return std::pair{a, b};
  };
  for (int ray : {1, 0}) {
    const auto [a, b] = extent(ray);
    if (period[ray] > 0 && !(b - a < period[ray] * (1 - 1e-9))) continue;
    out.ray_ = ray;
    out.period_ray_ = period[ray];
    out.period_abscissa_ = period[1 - ray];
    out.ray_lo_ = a;
    out.ray_hi_ = b;
    const auto [c0, c1] = extent(1 - ray);
    out.abscissa_extent_ = std::max(c1 - c0, 0.0);
    return out;
  }
  return std::nullopt;
}

bool ParameterLoops::contains(const Vec2& uv) const {
  const int r = ray_, s = 1 - ray_;
  double o = uv[r];
  if (period_ray_ > 0) {  // into the turn that holds the loops
    o = ray_lo_ + std::fmod(std::fmod(o - ray_lo_, period_ray_) + period_ray_, period_ray_);
    if (o > ray_hi_) return false;
  }
  // The ray's abscissa is nudged off the samples: a point level with a vertex of the loops (a
  // curve starting on the plane's domain edge at the loop's extreme vertex) met the vertex's two
  // edges at abscissae one rounding apart, and counted one of them.
  const double x0 = uv[s] + kAbscissaNudge * abscissa_extent_;
  int crossings = 0;
  for (const Segment& seg : segments_) {
    const double a0 = std::min(seg.a[s], seg.b[s]), a1 = std::max(seg.a[s], seg.b[s]);
    double x = x0;
    if (period_abscissa_ > 0)
      x = a0 + std::fmod(std::fmod(x - a0, period_abscissa_) + period_abscissa_, period_abscissa_);
    if (!(x >= a0 && x < a1)) continue;  // half-open: a vertex counts once
    const double t = (x - seg.a[s]) / (seg.b[s] - seg.a[s]);
    if (seg.a[r] + t * (seg.b[r] - seg.a[r]) > o) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace ssimarch
