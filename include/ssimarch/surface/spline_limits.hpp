#pragma once
// The largest polynomial degree of a Bezier patch or a B-spline surface that ssimarch accepts
// (issue 29 item 4: no unbounded work). The certified search bounds a patch by its control net
// subdivided into pieces whose cost grows like the degree's square per direction and whose
// bounds converge more slowly as the degree grows: a random Bezier patch against a plane took
// 0.1 s at degree 10, 1.1 s at 25 and 7 s at 60. CAD kernels write at most degree 25
// (OpenCASCADE's Geom_BSplineSurface::MaxDegree(), the STEP files and IGES files we read), so the
// bound turns no real model away.

namespace ssimarch {

/// Largest degree along u or v of a `bezier` or `bspline` surface (default 25); a larger one is
/// refused as invalid input naming the key.
inline constexpr int kMaxSplineDegree = 25;

}  // namespace ssimarch
