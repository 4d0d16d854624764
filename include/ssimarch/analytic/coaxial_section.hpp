// Two surfaces of revolution about one axis meet in circles of that axis (docs/math/
// closed_form_quadrics.md, "Coaxial surfaces of revolution"); two spheres are coaxial about the
// line of their centres.
#pragma once

#include <optional>
#include <vector>

#include "ssimarch/analytic/conic.hpp"
#include "ssimarch/analytic/quadric_form.hpp"

namespace ssimarch {

/// The circles (and points on the axis) common to a and b when they share an axis; nullopt when
/// they do not (or they coincide). `scale`: the model's length scale, for the shape tests;
/// `gap_tolerance` (model units, contact_gap_tolerance): the surfaces touch at a point of the
/// axis when both poles nearest a root are within it of the root and of each other, and along a
/// circle when two roots' circles are within it of each other's surface.
std::optional<std::vector<Conic>> coaxial_section(RevolutionForm a, RevolutionForm b, double scale, double gap_tolerance);

}  // namespace ssimarch
