// The parts of the Python module defined in their own translation units.
#pragma once

#include <pybind11/pybind11.h>

namespace ssimarch {

/// Defines radial, axial and bulk in the submodule ssimarch.porosity (porosity_bindings.cpp).
void bind_porosity(pybind11::module_& m);

}  // namespace ssimarch
