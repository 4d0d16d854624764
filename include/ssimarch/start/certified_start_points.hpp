// Complete start points with a certificate (docs/topology.md): a point on every branch of
// H(x) = 0 inside the box of the unknowns, from three families of square systems solved for all
// their roots by interval branch and bound with the Krawczyk test (start/krawczyk.hpp):
//
//   boundary systems   x_i = lo_i or hi_i (the seam lo_i for a periodic x_i), H(x) = 0:
//                      n-1 equations in the other n-1 unknowns. Every branch that leaves the box
//                      (or crosses a seam) meets one of these faces in isolated points.
//   turning systems    H(x) = 0 and det(J_H without column k) = 0: n equations in n unknowns.
//                      The second equation says the tangent's x_k component vanishes (the tangent
//                      is the generalised cross product of J_H's rows, whose k-th component is
//                      that minor up to sign). A closed branch inside the open box has a
//                      maximum of x_k, so it is a root of the system of every k.
//   trim face systems  H(x) = 0 and n . point(x) = b for each face of a trim of a surface in
//                      implicit form (surface/trims.hpp): a piece of a branch inside the trims
//                      that ends on a trim face meets it in an isolated root.
//
// The result is certified when every box of every boundary and trim face system and of at
// least one turning system was decided. Roots the Krawczyk test cannot prove (singular Jacobian: tangential
// contacts, singular points of the curve) are shrunk to a small box, handed to Newton as
// candidate start points and reported as uncertain regions.
#pragma once

#include <string>
#include <vector>

#include "ssimarch/march/result.hpp"
#include "ssimarch/start/start_search.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/surface/surface.hpp"
#include "ssimarch/start/krawczyk.hpp"

namespace ssimarch {

/// Whether the surface's point/value evaluated on intervals encloses its true range and its
/// derivatives' (what the certified search needs): false for forms that branch on the midpoint
/// (capsules), B-splines too large to extract into Bezier pieces, and B-splines that are not C1
/// across a knot line or seam (surface/knot_line_continuity.hpp).
bool evaluates_on_intervals(const Surface& surface);
/// Why not (one phrase; empty when it does).
std::string interval_refusal(const Surface& surface);

/// The roots of the boundary system x_i = lo_i (upper: hi_i) and its undecided boxes, as boxes
/// of all n unknowns (x_i a point interval). Empty for the upper end of a periodic x_i.
RootSearchResult boundary_roots(const Problem& P, int i, bool upper, const RootSearchOptions& options);

/// The roots of the system of a trim's face (H = 0 and n . point(x) = b, b the lower bound of
/// problem_trims(P)[trim], upper: its upper bound) over the box of the unknowns, and its undecided
/// boxes. Empty when there is no such trim.
RootSearchResult trim_face_roots(const Problem& P, int trim, bool upper, const RootSearchOptions& options);

/// The roots of the turning system for unknown k (x_k's tangent component vanishes) and its
/// undecided boxes.
RootSearchResult turning_points(const Problem& P, int k, const RootSearchOptions& options);

/// The regions of the unknowns that can hold a singular point of the curve: the undecided boxes
/// (touching ones merged) of the turning system for the first unknown, searched with at most
/// max_boxes boxes. A singular point is a root of every turning system (J_H loses rank there)
/// whose Jacobian is singular, which the Krawczyk test never certifies, so every other box is
/// free of them (docs/math/tangential_contact.md §4). Requires both surfaces to evaluate on
/// intervals.
std::vector<std::vector<Interval>> singular_point_regions(const Problem& P, long max_boxes);

/// The boundary system of the face x_i = at: H = 0 in the n-1 unknowns other than x_i (in their
/// order). Captures `problem` by reference.
SquareSystem face_system(const Problem& problem, int i, double at);

/// Start points found by the certified search; fills *search (method "certified") and adds the
/// Newton work to *stats. Requires both surfaces to evaluate on intervals.
std::vector<VecX> certified_start_points(const Tracer& tracer, TraceStats* stats, StartPointSearch* search);

/// The automatic start points of trace_all: the certified search when both surfaces evaluate on
/// intervals and the options ask for it, sampling (find_start_points) otherwise; *search says
/// which and why.
std::vector<VecX> automatic_start_points(const Tracer& tracer, TraceStats* stats, StartPointSearch* search);

}  // namespace ssimarch
