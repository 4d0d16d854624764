// Conversions shared by the module's translation units (bindings.hpp): JSON, scenes, numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/surface/frame.hpp"

namespace py = pybind11;

namespace ssimarch::python {

namespace {

// json.dumps(default=...): Surface objects become their description, numpy arrays and scalars lists
// and numbers; anything else is json's TypeError.
py::object jsonable(const py::object& o) {
  if (py::isinstance<PySurface>(o)) return python_of(o.cast<const PySurface&>().spec);
  if (py::hasattr(o, "tolist")) return o.attr("tolist")();
  throw py::type_error("Object of type " + py::str(py::type::of(o).attr("__name__")).cast<std::string>() +
                       " is not JSON serializable");
}

// The constants of two surfaces, one map; a name defined twice must have one value.
Constants merged_constants(const PySurface& a, const PySurface& b) {
  Constants c = a.constants;
  for (const auto& [k, v] : b.constants) {
    auto [it, added] = c.emplace(k, v);
    if (!added && it->second != v)
      throw InputError("constants." + k, "the two surfaces give it different values (" + std::to_string(it->second) +
                                             " and " + std::to_string(v) + ")");
  }
  return c;
}

nlohmann::json interval_json(const Interval& i) { return {i.lo, i.hi}; }

std::string missing_box(const PySurface& s) {
  return "the implicit surface " + s.spec["implicit"].dump() +
         " has no box, the region where intersections are searched: give one, box=((x0, x1), (y0, y1), (z0, z1))";
}

/// Dimensionless, relative to the largest side: the margin added around the box an implicit surface
/// takes from the other surface of trace(a, b), so that a flat one (a planar patch's control-point
/// box) still has three sides (ExprImplicit rejects an empty interval). Enlarging it changes no
/// trace: two implicit forms are traced in the intersection of their boxes (problem/problem.cpp).
constexpr double kDerivedBoxMargin = 0.05;

// The description of `s` for the scene of trace(a, b): with the box of `other` when it has none.
// The intersection lies on `other`, which lies in its box (primitives, patches and boxed implicit
// surfaces: an enclosure; a parametric expression's sampled box is not one, but with a parametric
// surface the implicit one's box is never read: the pair is traced in the parametric's domain).
nlohmann::json traced_description(const PySurface& s, const PySurface& other, const std::string& name,
                                  const std::string& other_name) {
  if (s.box_given) return s.spec;
  if (!other.box_given)
    throw InputError(name + ".box", missing_box(s) + " (" + other_name + " has none either, to derive it from)");
  const Box b = inflate(other.surface.box(), kDerivedBoxMargin);
  nlohmann::json spec = s.spec;
  spec["box"] = {interval_json(b.x), interval_json(b.y), interval_json(b.z)};
  return spec;
}

Scene scene_of_surfaces(const PySurface& a, const PySurface& b) {
  nlohmann::json scene{{"surfaces", {{"a", traced_description(a, b, "a", "b")}, {"b", traced_description(b, a, "b", "a")}}},
                       {"intersections", nlohmann::json::array({{{"name", "a-b"}, {"surfaces", {"a", "b"}}}})}};
  const Constants c = merged_constants(a, b);
  if (!c.empty()) scene["constants"] = c;
  return parse_scene(scene.dump(), "<surfaces>");
}

std::string type_name(const py::handle& o) { return py::str(py::type::of(o).attr("__name__")).cast<std::string>(); }

}  // namespace

std::string json_text(const py::object& obj) {
  return py::module_::import("json").attr("dumps")(obj, py::arg("default") = py::cpp_function(&jsonable)).cast<std::string>();
}

py::object python_of(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

Scene scene_of(const py::object& scene, const py::object& other, const char* function) {
  const std::string fn(function);
  if (py::isinstance<PySurface>(scene)) {
    if (!py::isinstance<PySurface>(other))
      throw py::type_error(fn + ": a Surface needs a second Surface to intersect with (got " + type_name(other) + ")");
    return scene_of_surfaces(scene.cast<const PySurface&>(), other.cast<const PySurface&>());
  }
  if (!other.is_none())
    throw py::type_error(fn + ": a second positional argument is only for two Surface objects (got " +
                         type_name(scene) + " and " + type_name(other) + ")");
  if (py::isinstance<py::dict>(scene)) {
    // A scene's surfaces may be in several intersections: no one other surface to take a box from.
    const py::dict d = scene.cast<py::dict>();
    if (d.contains("surfaces") && py::isinstance<py::dict>(d["surfaces"]))
      for (const auto& [name, s] : d["surfaces"].cast<py::dict>())
        if (py::isinstance<PySurface>(s) && !s.cast<const PySurface&>().box_given)
          throw InputError("surfaces." + py::str(name).cast<std::string>() + ".box",
                           missing_box(s.cast<const PySurface&>()) + " (a scene needs it; trace(a, b) of two "
                           "Surface objects takes the other's box)");
    return parse_scene(json_text(scene), "<dict>");
  }
  if (py::isinstance<py::str>(scene)) {
    const std::string s = scene.cast<std::string>();
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && s[first] == '{') return parse_scene(s, "<string>");
    return load_scene(s);
  }
  if (py::hasattr(scene, "__fspath__")) return load_scene(py::str(scene.attr("__fspath__")()).cast<std::string>());
  throw py::type_error(fn + ": scene must be a path, a JSON string, a dict or two Surface objects (got " +
                       type_name(scene) + ")");
}

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array_t<double> as_double_array(const py::object& obj, const char* name) {
  // Not array_t::ensure: it would silently accept text ("1.5") and None.
  if (py::isinstance<py::str>(obj) || obj.is_none())
    throw InputError(name, "expected numbers (an array or a number), got " + type_name(obj));
  py::array a = py::module_::import("numpy").attr("asarray")(obj);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw InputError(name, "expected a numeric array, got dtype " + py::str(a.dtype()).cast<std::string>());
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

py::array_t<double> as_points(const py::object& obj, const char* name) {
  py::array_t<double> a = as_double_array(obj, name);
  if (a.ndim() < 1 || a.shape(a.ndim() - 1) != 3)
    throw InputError(name, "expected points as an array of shape (..., 3), got shape " + shape_text(a));
  return a;
}

py::array_t<double> new_array(std::vector<py::ssize_t> shape) { return py::array_t<double>(shape); }

std::vector<py::ssize_t> shape_with(const py::array& a, std::vector<py::ssize_t> tail, int drop) {
  std::vector<py::ssize_t> s(a.shape(), a.shape() + a.ndim() - drop);
  s.insert(s.end(), tail.begin(), tail.end());
  return s;
}

}  // namespace ssimarch::python
