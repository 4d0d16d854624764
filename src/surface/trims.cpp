#include "ssimarch/surface/trims.hpp"

namespace ssimarch {

namespace {
// The slab of an axial range [h0, h1] measured from `origin` along the unit axis e2.
Slab axial_slab(const Frame& f, const Interval& range) {
  const double o = f.e2.dot(f.origin);
  return Slab{f.e2, Interval{o + range.lo, o + range.hi}};
}

// The slabs of a graph over the frame's (e0, e1) plane whose parameters are the coordinates
// along e0 and e1 (a plane, a paraboloid): u in [u0, u1] and v in [v0, v1] are two slabs.
std::vector<Slab> rectangle_slabs(const Frame& f, const ParamDomain& d) {
  const double o0 = f.e0.dot(f.origin), o1 = f.e1.dot(f.origin);
  return {Slab{f.e0, Interval{o0 + d.u.lo, o0 + d.u.hi}}, Slab{f.e1, Interval{o1 + d.v.lo, o1 + d.v.hi}}};
}
}  // namespace

std::vector<Slab> implicit_trims(const Surface& surface) {
  if (const auto* c = surface.get_if<Cylinder>()) return {axial_slab(c->frame(), c->range())};
  if (const auto* k = surface.get_if<Cone>()) return {axial_slab(k->frame(), k->domain().v)};
  if (const auto* p = surface.get_if<Plane>()) return rectangle_slabs(p->frame(), p->domain());
  if (const auto* p = surface.get_if<Paraboloid>()) return rectangle_slabs(p->frame(), p->domain());
  return {};
}

}  // namespace ssimarch
