// The thesis' ruled surface F(u,v) = C(u) + v D(u), v in [-1/2, 1/2], as an exact rational
// B-spline for OpenCASCADE (cases.jsonl torus_ruled_knot: degree 10 x 1, 4 C0 segments).
#pragma once

#include <Geom_Surface.hxx>

namespace peers {

/// C(u) = ((4 + cos 4u) cos u, (4 + cos 4u) sin u, sin 4u), D(u) = ((cos 4u + sin 4u) cos u,
/// (cos 4u + sin 4u) sin u, sin 4u - cos 4u): trigonometric polynomials of degree 5, so with
/// t = tan(s/2) on each quarter turn u = k pi/2 + s the homogeneous point (1 + t^2)^5 (F, 1) is a
/// polynomial of degree 10 in t in [0, 1], written in Bernstein form by collocation.
Handle(Geom_Surface) knot_ruled_surface();

}  // namespace peers
