// The surfaces' forms on the jets of SSIMARCH_SURFACE_JET_TYPES_3 (surface.hpp), compiled once
// here instead of in every translation unit that evaluates them; the list is split over three files
// so that a parallel build compiles them side by side.
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

#define SSIMARCH_SURFACE_FORMS_INSTANTIATE(...) SSIMARCH_SURFACE_FORMS(template, __VA_ARGS__)
SSIMARCH_SURFACE_JET_TYPES_3(SSIMARCH_SURFACE_FORMS_INSTANTIATE);

}  // namespace ssimarch
