#include "ssimarch/surface/trims.hpp"

namespace ssimarch {

namespace {
// The slab of an axial range [h0, h1] measured from `origin` along the unit axis e2.
Slab axial_slab(const Frame& f, const Interval& range) {
  const double o = f.e2.dot(f.origin);
  return Slab{f.e2, Interval{o + range.lo, o + range.hi}};
}
}  // namespace

std::vector<Slab> implicit_trims(const Surface& surface) {
  if (const auto* c = surface.get_if<Cylinder>()) return {axial_slab(c->frame(), c->range())};
  if (const auto* k = surface.get_if<Cone>()) return {axial_slab(k->frame(), k->domain().v)};
  return {};
}

}  // namespace ssimarch
