// The parts of the Python module defined in their own translation units, and the conversions
// they share.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/pipeline/scene.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Defines radial, axial, bins, map, bulk and pack in the submodule ssimarch.porosity
/// (porosity_bindings.cpp).
void bind_porosity(pybind11::module_& m);
/// Defines the class Surface (surface_bindings.cpp); the constructors Sphere(...) etc. are
/// python/ssimarch/surfaces.py.
void bind_surface(pybind11::module_& m);
/// Defines curve_geometry and geometry_methods (geometry_bindings.cpp).
void bind_curve_geometry(pybind11::module_& m);

namespace python {

/// A surface built from Python: its scene-format description, the constants its expressions
/// use, and the library's surface parsed from them (io/surface_json.hpp). An implicit surface
/// may come without its box (box_given false): it evaluates, and a trace against another surface
/// uses that surface's box (scene_of).
struct PySurface {
  nlohmann::json spec;
  Constants constants;
  Surface surface;
  bool box_given = true;
};

/// JSON text of a Python object (a dict of a scene or a surface) through the json module; numpy
/// arrays and numbers become lists and numbers, Surface objects their description.
std::string json_text(const pybind11::object& obj);
/// A Python object from JSON, through the json module (the values the CLI writes).
pybind11::object python_of(const nlohmann::json& j);

/// The scene of `trace` and `curve_geometry`: a path, a JSON text, a dict, or two Surface objects
/// (the scene with surfaces "a", "b" and the one intersection "a-b"; an implicit surface without
/// a box gets the other's box: the curve lies on the other surface, inside its box). InputError
/// naming the surface where a box is needed and none can be derived.
Scene scene_of(const pybind11::object& scene, const pybind11::object& other, const char* function);

/// A float64 array of the same values, C order (float32, Fortran order, views, lists accepted).
pybind11::array_t<double> as_double_array(const pybind11::object& obj, const char* name);
/// An array of points: shape (..., 3) (a single point (3,) included); InputError naming `name` otherwise.
pybind11::array_t<double> as_points(const pybind11::object& obj, const char* name);
/// A new float64 array of this shape.
pybind11::array_t<double> new_array(std::vector<pybind11::ssize_t> shape);
/// The shape of `a` followed by `tail`.
std::vector<pybind11::ssize_t> shape_with(const pybind11::array& a, std::vector<pybind11::ssize_t> tail, int drop = 0);
/// "(2, 3)" for messages.
std::string shape_text(const pybind11::array& a);

}  // namespace python
}  // namespace ssimarch
