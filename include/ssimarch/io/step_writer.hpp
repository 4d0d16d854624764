// The certified B-splines of a trace job (pipeline/trace_job.hpp, option "bspline") as a STEP
// AP242 exchange file (ISO 10303-21 clear text; ISO 10303-42 geometry): each 3D curve a
// B_SPLINE_CURVE_WITH_KNOTS in a GEOMETRIC_CURVE_SET of a wireframe shape representation, and
// each p-curve a 2D B_SPLINE_CURVE_WITH_KNOTS in a DEFINITIONAL_REPRESENTATION of a parametric
// context named after its curve and surface. Surfaces are not written.
#pragma once

#include <ostream>
#include <vector>

#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

/// Throws InputError when no run has B-splines (trace with the option "bspline").
void write_step(std::ostream& out, const std::vector<IntersectionRun>& runs);

}  // namespace ssimarch
