// The surfaces' forms on the interval types of SSIMARCH_INTERVAL_TYPES_1 (start/interval_forms.hpp),
// compiled once here; three files so that a parallel build compiles them side by side.
#include "ssimarch/start/interval_forms.hpp"

namespace ssimarch {

#define SSIMARCH_SURFACE_FORMS_INSTANTIATE(...) SSIMARCH_SURFACE_FORMS(template, __VA_ARGS__)
SSIMARCH_INTERVAL_TYPES_1(SSIMARCH_SURFACE_FORMS_INSTANTIATE);

}  // namespace ssimarch
