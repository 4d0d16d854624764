#include "ssimarch/surface/unbounded.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ssimarch {

namespace {

std::array<Vec3, 8> corners(const Box& b) {
  std::array<Vec3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[static_cast<std::size_t>(k)] = Vec3(k & 1 ? b.x.hi : b.x.lo, k & 2 ? b.y.hi : b.y.lo, k & 4 ? b.z.hi : b.z.lo);
  return c;
}

double diagonal(const Box& b) { return Vec3(b.x.width(), b.y.width(), b.z.width()).norm(); }

// The interval of the frame coordinate `axis` (0: e0, 1: e1, 2: e2) over the region's corners,
// widened by the margin: a linear coordinate, so its extremes over the box are at corners.
Interval coordinate_range(const Frame& f, int axis, const Box& region) {
  const Vec3& e = axis == 0 ? f.e0 : axis == 1 ? f.e1 : f.e2;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& c : corners(region)) {
    const double t = (c - f.origin).dot(e);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  const double pad = kUnboundedClipMargin * diagonal(region);
  return {lo - pad, hi + pad};
}

// A plane's or paraboloid's rectangle with its unbounded directions covering the region (both are
// graphs over their frame's (e0, e1) plane, so u and v are the frame coordinates).
ParamDomain clipped_rectangle(const Frame& f, ParamDomain d, const Box& region) {
  if (d.unbounded_u) d.u = coordinate_range(f, 0, region);
  if (d.unbounded_v) d.v = coordinate_range(f, 1, region);
  d.unbounded_u = d.unbounded_v = false;
  return d;
}

template <class S>
S rebuilt(const S& s, const Box& region);

template <>
Plane rebuilt(const Plane& s, const Box& region) {
  return Plane(s.frame().origin, s.frame().e2, clipped_rectangle(s.frame(), s.domain(), region), s.frame().e0);
}

template <>
Paraboloid rebuilt(const Paraboloid& s, const Box& region) {
  return Paraboloid(s.frame().origin, s.frame().e2, s.focal_u(), s.focal_v(),
                    clipped_rectangle(s.frame(), s.domain(), region), s.frame().e0);
}

template <>
Cylinder rebuilt(const Cylinder& s, const Box& region) {
  const Interval range = s.domain().unbounded_v ? coordinate_range(s.frame(), 2, region) : s.range();
  return Cylinder(s.frame().origin, s.frame().e2, s.radius(), range, s.frame().e0);
}

template <>
Cone rebuilt(const Cone& s, const Box& region) {
  // Both nappes where the region reaches past the apex (v is the signed axial distance from it).
  const Interval range = s.domain().unbounded_v ? coordinate_range(s.frame(), 2, region) : s.range();
  return Cone(s.frame().origin, s.frame().e2, s.half_angle(), range, s.frame().e0);
}

}  // namespace

bool has_unbounded_direction(const Surface& s) {
  if (!s.is_parametric()) return false;
  const ParamDomain& d = s.domain();
  return d.unbounded_u || d.unbounded_v;
}

Surface clipped_to(const Surface& s, const Box& region) {
  if (!has_unbounded_direction(s)) return s;
  if (const auto* p = s.get_if<Plane>()) return Surface(rebuilt(*p, region));
  if (const auto* p = s.get_if<Paraboloid>()) return Surface(rebuilt(*p, region));
  if (const auto* p = s.get_if<Cylinder>()) return Surface(rebuilt(*p, region));
  if (const auto* p = s.get_if<Cone>()) return Surface(rebuilt(*p, region));
  return s;
}

Box unbounded_pair_region(const Surface& a, const Surface& b) {
  const Box &ba = a.box(), &bb = b.box();
  auto centre = [](const Box& x) {
    return Vec3(0.5 * (x.x.lo + x.x.hi), 0.5 * (x.y.lo + x.y.hi), 0.5 * (x.z.lo + x.z.hi));
  };
  const Vec3 c = 0.5 * (centre(ba) + centre(bb));
  const double half = kUnboundedPairBox * std::max(diagonal(ba), diagonal(bb));
  return Box{{c.x() - half, c.x() + half}, {c.y() - half, c.y() + half}, {c.z() - half, c.z() + half}};
}

}  // namespace ssimarch
