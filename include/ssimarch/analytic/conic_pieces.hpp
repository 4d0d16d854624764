// The pieces of a conic inside an axis-aligned box, and a conic piece as a traced curve: exact
// points at a chordal deviation, exact tangents, arc length by Gauss-Legendre quadrature
// (docs/math/closed_form_quadrics.md, "Clipping and sampling").
#pragma once

#include <array>
#include <vector>

#include "ssimarch/analytic/conic.hpp"
#include "ssimarch/march/result.hpp"
#include "ssimarch/surface/trims.hpp"  // Slab: a box is three slabs, a cylinder's axial trim one

namespace ssimarch {

/// The three slabs of an axis-aligned box (x, y, z intervals).
std::vector<Slab> box_slabs(const std::array<Interval, 3>& box);

/// The parts of `conic` inside every slab, each with its parameter range; a circle or ellipse
/// wholly inside comes back once with range [0, 2 pi]. A point comes back when it is inside.
std::vector<Conic> clip_to_slabs(const Conic& conic, const std::vector<Slab>& slabs);

/// Whether the piece is a whole circle or ellipse (a closed curve).
bool is_whole(const Conic& piece);

/// The piece as a curve of points (x = the 3D point, for implicit-implicit unknowns): every chord
/// within `deviation` of the conic and at most `max_chord` long. A whole conic is closed (its
/// last point repeats the first); an open piece ends on the box (kLeftDomain at both ends).
TracedCurve sample_conic(const Conic& piece, double deviation, double max_chord);

/// The arc length of the piece over its parameter range (adaptive Gauss-Legendre to ~1e-14).
double conic_length(const Conic& piece);

}  // namespace ssimarch
