// The certified B-splines of a trace job (pipeline/trace_job.hpp, option "bspline") as a STEP
// AP242 exchange file (ISO 10303-21 clear text; ISO 10303-42 geometry): each 3D curve a
// B_SPLINE_CURVE_WITH_KNOTS in a GEOMETRIC_CURVE_SET of a wireframe shape representation, and
// each p-curve a 2D B_SPLINE_CURVE_WITH_KNOTS in a DEFINITIONAL_REPRESENTATION of a parametric
// context named after its curve and surface. Surfaces with a STEP form are written once each,
// with ssimarch's parameterisation (planes, cylinders, cones bounded to their domain by a
// RECTANGULAR_TRIMMED_SURFACE; spheres, tori; B-spline and Bezier patches as
// B_SPLINE_SURFACE_WITH_KNOTS, rational ones as the complex instance with
// RATIONAL_B_SPLINE_SURFACE, from the scene's control data), and each curve is then a SURFACE_CURVE or
// INTERSECTION_CURVE whose associated geometry is the PCURVE on each written parametric
// surface (the surface itself for an implicit one); step/reader.hpp reads them back.
#pragma once

#include <ostream>
#include <vector>

#include "ssimarch/pipeline/trace_job.hpp"

namespace ssimarch {

/// Throws InputError when no run has B-splines (trace with the option "bspline"). `scene` (the
/// runs' scene) gives the control data of spline surfaces; without it they are not written
/// and their p-curves are bare DEFINITIONAL_REPRESENTATIONs.
void write_step(std::ostream& out, const std::vector<IntersectionRun>& runs, const Scene* scene = nullptr);

}  // namespace ssimarch
