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
/// they do not (or they coincide). `scale`: the model's length scale, for the degeneracy tests.
std::optional<std::vector<Conic>> coaxial_section(RevolutionForm a, RevolutionForm b, double scale);

}  // namespace ssimarch
