// Trims of an implicit form: the part of the zero set f = 0 that the surface is. A primitive
// with an axial range (cylinder, cone) is the piece of its infinite implicit surface between
// two planes normal to its axis; the implicit form carries that range as a slab, so a curve
// traced in implicit form ends on the same rim as in parametric form (issue 11 item 5). A
// plane's or a paraboloid's rectangle (its parameters are the coordinates along e0 and e1) is
// two such slabs, along e0 and e1: without them a plane patch paired in implicit form was the
// whole plane inside its (inflated) box, and curves ran past its edges.
#pragma once

#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// The region normal . p in range (normal a unit vector, range in model units).
struct Slab {
  Vec3 normal = Vec3::UnitZ();
  Interval range;
  bool contains(const Vec3& p, double eps = 0.0) const {
    const double s = normal.dot(p);
    return s >= range.lo - eps && s <= range.hi + eps;
  }
};

/// The slabs trimming a surface's implicit form: one per axial range (cylinder, cone), two per
/// parameter rectangle (plane, paraboloid), none for closed surfaces, implicit expressions
/// (their box is their region) and patches.
std::vector<Slab> implicit_trims(const Surface& surface);

}  // namespace ssimarch
