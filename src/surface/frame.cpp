#include "ssimarch/surface/frame.hpp"

#include <algorithm>
#include <cmath>

#include "ssimarch/core/error.hpp"

namespace ssimarch {

Frame Frame::from_axis(const Vec3& origin, const Vec3& axis, const std::optional<Vec3>& reference,
                       const std::string& what) {
  // Below this |sin| between reference and axis the reference gives no usable e0.
  constexpr double kMinReferenceSine = 1e-9;
  if (!origin.allFinite()) throw InputError(what, "the position has a non-finite coordinate");
  if (!axis.allFinite()) throw InputError(what, "the axis has a non-finite coordinate");
  const double n = axis.norm();
  if (!(n > 0) || !std::isfinite(n)) throw InputError(what, "the axis must be a non-zero vector");
  Frame f;
  f.origin = origin;
  f.e2 = axis / n;
  Vec3 ref;
  if (reference) {
    if (!reference->allFinite()) throw InputError(what, "the reference direction has a non-finite coordinate");
    const double rn = reference->norm();
    ref = *reference - f.e2 * f.e2.dot(*reference);
    if (!(rn > 0) || !(ref.norm() > kMinReferenceSine * rn))
      throw InputError(what, "the reference direction must be non-zero and not parallel to the axis");
  } else {
    int i = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(f.e2[k]) < std::fabs(f.e2[i])) i = k;
    ref = Vec3::Unit(i) - f.e2 * f.e2[i];
  }
  f.e0 = ref.normalized();
  f.e1 = f.e2.cross(f.e0);
  return f;
}

Box box_union(const Box& a, const Box& b) {
  auto u = [](const Interval& p, const Interval& q) { return Interval{std::min(p.lo, q.lo), std::max(p.hi, q.hi)}; };
  return {u(a.x, b.x), u(a.y, b.y), u(a.z, b.z)};
}

Box inflate(const Box& b, double relative, double absolute) {
  const double side = std::max({b.x.width(), b.y.width(), b.z.width()});
  const double m = std::max(relative * side, absolute);
  return {{b.x.lo - m, b.x.hi + m}, {b.y.lo - m, b.y.hi + m}, {b.z.lo - m, b.z.hi + m}};
}

}  // namespace ssimarch
