// Cutting traced curves to CAD faces (pipeline/face_region.hpp): the pieces of each curve inside
// both surfaces' regions, each ending exactly on the boundary it crosses (docs/cad.md,
// "Trimming loops").
#pragma once

#include <array>

#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

/// Replaces run->result.curves by their pieces inside the regions (regions[k] belongs to the
/// Problem's surface k; null: no trim on that side). A crossing of the boundary between two
/// points of a curve is solved on the curve to |signed distance| <= 1e-13 x max(1, model size)
/// (Illinois regula falsi along the unknown that changes most, each trial point corrected onto
/// both surfaces); the new end is marked Termination::kLeftDomain with the region's name. A
/// curve with no crossing is kept or dropped whole by the side of its first point. Singular and
/// isolated points outside a region are dropped, the curve indices of the rest renumbered;
/// conics are kept per piece with their parameter range cut. Runs before the network, the
/// geometry and the B-splines are built.
void clip_to_regions(const std::array<const FaceRegion*, 2>& regions, IntersectionRun* run);

}  // namespace ssimarch
