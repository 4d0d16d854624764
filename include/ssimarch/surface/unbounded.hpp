// Surfaces unbounded in a parameter direction (issue 29): a plane, cylinder, cone or paraboloid
// whose extent the user did not give stands, like OpenCASCADE's Geom surfaces, for the whole
// unbounded surface. Work needs a finite domain, so a Problem clips such a surface to the other
// surface of the pair: the copy's domain covers every parameter whose point lies in the other
// surface's box (Surface::box(), which holds the other surface), with a margin, so the whole
// intersection lies inside it and no curve is cut by a default. When both surfaces are unbounded
// the region is a stated box (unbounded_pair_region), and a curve that leaves it ends on that
// domain edge, as its `ends` say.
#pragma once

#include "ssimarch/surface/domain.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Margin added on each side of a clipped interval, relative to the diagonal of the region
/// (dimensionless): the region is a box that holds the other surface, so the intersection lies
/// inside the projection already; the margin keeps it off the new domain edge by far more than
/// any step, so a closed curve is traced as closed.
inline constexpr double kUnboundedClipMargin = 0.05;

/// Half-side of the box two unbounded surfaces are clipped to, relative to the larger diagonal of
/// their nominal boxes (dimensionless): their intersection is bounded unless it is a line or
/// parallel lines, and a bounded one lies within a few sizes of the surfaces' radii and centres.
inline constexpr double kUnboundedPairBox = 10;

/// Whether s has an unbounded parameter direction (ParamDomain::unbounded_u / unbounded_v).
bool has_unbounded_direction(const Surface& s);

/// A copy of s whose unbounded directions cover `region` (every point of s in the region has its
/// parameters in the copy's domain), widened by kUnboundedClipMargin; bounded directions and
/// every other surface are returned as they are.
Surface clipped_to(const Surface& s, const Box& region);

/// The box two unbounded surfaces are clipped to: centred between the centres of their nominal
/// boxes, of half-side kUnboundedPairBox times the larger diagonal of those boxes.
Box unbounded_pair_region(const Surface& a, const Surface& b);

}  // namespace ssimarch
