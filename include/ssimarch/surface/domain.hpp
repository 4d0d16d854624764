// Parameter domains and axis-aligned boxes of surfaces.
#pragma once

namespace ssimarch {

/// Closed interval [lo, hi].
struct Interval {
  double lo = 0, hi = 0;
  double width() const { return hi - lo; }
  bool contains(double x) const { return lo <= x && x <= hi; }
};

/// Rectangle of a parametric form, u in [u.lo, u.hi], v in [v.lo, v.hi]. A periodic direction
/// wraps: F(u.lo, v) = F(u.hi, v) and the parameter may be reduced modulo u.width().
struct ParamDomain {
  Interval u, v;
  bool periodic_u = false, periodic_v = false;
};

/// Axis-aligned box in model space.
struct Box {
  Interval x, y, z;
};

}  // namespace ssimarch
