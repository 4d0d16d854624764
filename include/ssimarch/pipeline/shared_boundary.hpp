// Two faces of one solid meet only along the edges and at the vertices they share: the faces of a
// manifold solid's boundary intersect each other in nothing else (ISO 10303-42 §5.4: a
// closed_shell is a connected face set whose faces meet only at their common edges and vertices,
// and a manifold_solid_brep's shells bound its volume). So the intersection of such a pair is
// read from the model's topology instead of traced: the exact edge curves the faces share, and
// their shared vertices that lie on no shared edge as isolated points. This is both the answer a
// CAD user expects (issue 28 item 3: the shared edges of adjacent faces are curves on both
// boundaries) and the only cheap one: two adjacent faces are tangent along their edge where the
// model is smooth (the halves of a cylinder, a fillet), where a march runs for seconds and can
// certify nothing (issue 28: 59 such pairs of one assembly took 140 s).
#pragma once

#include <optional>

#include "ssimarch/march/resolved_options.hpp"
#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/trace/result.hpp"

namespace ssimarch {

/// The intersection of the problem's surfaces when they are faces of one solid (both regions
/// given, FaceRegion::solid equal and not empty; `first` is the problem's first surface's region):
/// one curve per shared edge, sampled as a closed form's conics are (chords within the resolved
/// deviation and at most ResolvedTraceOptions::chord long), its points the edge's exact points with
/// the unknowns of their nearest points on the surfaces, its length by Gauss-Legendre on the edge;
/// each end a boundary end at its vertex; a curve along which the normals agree within
/// kSharedEdgeTangentSine is one of tangential contact. start_search: method kSharedBoundary,
/// certified (the guarantee is the solid's validity, docs/cad.md "Faces of one solid"). Nothing
/// when the faces are not of one solid.
std::optional<TraceResult> shared_boundary(const Problem& problem, const FaceRegion* first, const FaceRegion* second,
                                           const ResolvedTraceOptions& options);

/// sin(theta) of the surface normals at or below which a shared edge is one of tangential contact
/// (the faces join smoothly there): the angular precision of tangent-continuous joins in CAD
/// models, which approximate G1 to 1e-6..1e-10 rad; kSuspectSingularRankRatio's value.
inline constexpr double kSharedEdgeTangentSine = 1e-4;

}  // namespace ssimarch
