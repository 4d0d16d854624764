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
///
/// An unbounded direction (a plane, cylinder, cone or paraboloid whose extent the user did not
/// give, surface/unbounded.hpp) keeps a nominal interval here for whatever needs one (a picture,
/// `ssimarch eval`); a Problem replaces it by one that covers the other surface of the pair, so an
/// intersection is never cut by a default (issue 29).
struct ParamDomain {
  Interval u, v;
  bool periodic_u = false, periodic_v = false;
  bool unbounded_u = false, unbounded_v = false;
};

/// Axis-aligned box in model space.
struct Box {
  Interval x, y, z;
};

}  // namespace ssimarch
