// ssimarch.Surface (docs/python.md, "Surfaces"): a surface of the scene format built from Python,
// evaluated on numpy arrays by one C++ loop per call with the GIL released. The description is
// parsed by io/surface_json.hpp, so a Surface accepts and rejects exactly what a scene file does;
// the values are the library's (surface/derivatives.hpp; derivatives by Taylor jets, core/jet.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/io/surface_json.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace py = pybind11;

namespace ssimarch {
namespace {

using python::PySurface;
using Array = py::array_t<double>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Highest derivative order of Surface.derivatives (jets of order 1, 2 or 4 are instantiated).
constexpr int kMaxDerivativeOrder = 4;

PySurface make_surface(const py::object& spec, const py::object& constants) {
  nlohmann::json description = nlohmann::json::parse(python::json_text(spec));
  Constants c;
  if (!constants.is_none()) {
    for (const auto& [k, v] : constants.cast<py::dict>()) {
      const std::string name = py::str(k).cast<std::string>();
      if (py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v) || !py::hasattr(v, "__float__"))
        throw InputError("constants." + name, "expected a number");
      c[name] = v.cast<double>();
    }
  }
  Surface surface = surface_from_json(description, c, "surface");
  return PySurface{std::move(description), std::move(c), std::move(surface)};
}

// (u, v) broadcast against each other, as C-ordered float64 arrays of one shape.
std::pair<Array, Array> parameters(const py::object& u, const py::object& v) {
  const Array a = python::as_double_array(u, "u"), b = python::as_double_array(v, "v");
  py::tuple ab;
  try {
    ab = py::module_::import("numpy").attr("broadcast_arrays")(a, b);
  } catch (const py::error_already_set&) {
    throw InputError("u, v", "shapes " + python::shape_text(a) + " and " + python::shape_text(b) + " do not broadcast");
  }
  return {python::as_double_array(ab[0], "u"), python::as_double_array(ab[1], "v")};
}

void require_parametric(const PySurface& s, const char* what) {
  if (!s.surface.is_parametric())
    throw InputError(what, "a " + std::string(s.surface.type_name()) +
                               " surface has no parametric form (use value/gradient/normal on points (..., 3))");
}
void require_implicit(const PySurface& s, const char* what) {
  if (!s.surface.is_implicit())
    throw InputError(what, "a " + std::string(s.surface.type_name()) +
                               " surface has no implicit form (use point/derivatives/normal on parameters u, v)");
}

void put(double* out, const Vec3& p) {
  out[0] = p.x();
  out[1] = p.y();
  out[2] = p.z();
}
void put(double* out, const std::optional<Vec3>& p) {
  if (p) put(out, *p);
  else out[0] = out[1] = out[2] = kNaN;
}

// out[i * width ...] = f(u[i], v[i], out + i * width) for every parameter pair, the GIL released.
template <class F>
Array map_parameters(const py::object& u, const py::object& v, std::vector<py::ssize_t> tail, F f) {
  auto [a, b] = parameters(u, v);
  Array out = python::new_array(python::shape_with(a, tail));
  const double* pu = a.data();
  const double* pv = b.data();
  double* po = out.mutable_data();
  py::ssize_t width = 1;
  for (py::ssize_t t : tail) width *= t;
  const py::ssize_t n = a.size();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) f(pu[i], pv[i], po + i * width);
  }
  return out;
}

template <class F>
Array map_points(const py::object& points, std::vector<py::ssize_t> tail, F f) {
  const Array p = python::as_points(points, "points");
  Array out = python::new_array(python::shape_with(p, tail, 1));
  const double* pp = p.data();
  double* po = out.mutable_data();
  py::ssize_t width = 1;
  for (py::ssize_t t : tail) width *= t;
  const py::ssize_t n = p.size() / 3;
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) f(Vec3(pp[3 * i], pp[3 * i + 1], pp[3 * i + 2]), po + i * width);
  }
  return out;
}

// Every partial derivative d^(i+j)F/du^i dv^j with i + j <= order, by one jet of order K >= order.
template <int K>
py::dict derivatives_by_jet(const PySurface& s, const py::object& u, const py::object& v, int order) {
  std::vector<std::pair<int, int>> orders;
  for (int total = 0; total <= order; ++total)
    for (int i = total; i >= 0; --i) orders.emplace_back(i, total - i);
  const auto m = static_cast<py::ssize_t>(orders.size());
  Array all = map_parameters(u, v, {m, 3}, [&](double uu, double vv, double* out) {
    const auto F = parametric_jet<K>(s.surface, uu, vv);
    for (std::size_t k = 0; k < orders.size(); ++k) put(out + 3 * k, partial<K>(F, orders[k].first, orders[k].second));
  });
  py::dict d;
  for (py::ssize_t k = 0; k < m; ++k) {
    py::object slice = all[py::make_tuple(py::ellipsis(), k, py::slice(0, 3, 1))];
    d[py::make_tuple(orders[static_cast<std::size_t>(k)].first, orders[static_cast<std::size_t>(k)].second)] =
        py::module_::import("numpy").attr("ascontiguousarray")(slice);
  }
  return d;
}

py::dict derivatives(const PySurface& s, const py::object& u, const py::object& v, int order) {
  require_parametric(s, "derivatives");
  if (order < 0 || order > kMaxDerivativeOrder)
    throw InputError("order", "must be an integer in [0, " + std::to_string(kMaxDerivativeOrder) + "], got " +
                                  std::to_string(order));
  if (order <= 1) return derivatives_by_jet<1>(s, u, v, order);
  if (order == 2) return derivatives_by_jet<2>(s, u, v, order);
  return derivatives_by_jet<kMaxDerivativeOrder>(s, u, v, order);
}

py::dict curvature_columns(Array all) {
  py::dict d;
  const char* names[] = {"gaussian", "mean", "k1", "k2"};
  for (int k = 0; k < 4; ++k)
    d[names[k]] = py::module_::import("numpy").attr("ascontiguousarray")(all[py::make_tuple(py::ellipsis(), k)]);
  return d;
}

void put_curvatures(double* out, const std::optional<Curvatures>& c) {
  if (!c) {
    out[0] = out[1] = out[2] = out[3] = kNaN;
    return;
  }
  out[0] = c->gaussian;
  out[1] = c->mean;
  out[2] = c->k1;
  out[3] = c->k2;
}

py::tuple interval(const Interval& i) { return py::make_tuple(i.lo, i.hi); }

void bind_evaluation(py::class_<PySurface>& c) {
  c.def("point", [](const PySurface& s, const py::object& u, const py::object& v) {
        require_parametric(s, "point");
        return map_parameters(u, v, {3}, [&](double a, double b, double* out) { put(out, point(s.surface, a, b)); });
      }, py::arg("u"), py::arg("v"),
      "F(u, v) of the parametric form: u, v arrays (or numbers) of one shape S (broadcast); returns S + (3,).");
  c.def("derivatives", &derivatives, py::arg("u"), py::arg("v"), py::arg("order") = 1,
        "Every partial derivative of F up to `order` (0..4), exact (Taylor jets): a dict {(i, j): array S + (3,)} "
        "of d^(i+j)F / du^i dv^j, (0, 0) being F itself.");
  c.def("normal", [](const PySurface& s, const py::object& u, const py::object& v) {
        require_parametric(s, "normal");
        return map_parameters(u, v, {3}, [&](double a, double b, double* out) { put(out, unit_normal(s.surface, a, b)); });
      }, py::arg("u"), py::arg("v"),
      "Unit normal Fu x Fv / |Fu x Fv| at parameters (S + (3,)); NaN at degenerate points (poles, apices).");
  c.def("normal", [](const PySurface& s, const py::object& points) {
        require_implicit(s, "normal");
        return map_points(points, {3}, [&](const Vec3& p, double* out) { put(out, unit_normal(s.surface, p)); });
      }, py::arg("points"),
      "Unit normal grad f / |grad f| at points of shape S + (3,); NaN where grad f vanishes.");
  c.def("curvatures", [](const PySurface& s, const py::object& u, const py::object& v) {
        require_parametric(s, "curvatures");
        return curvature_columns(map_parameters(u, v, {4}, [&](double a, double b, double* out) {
          const auto ff = fundamental_forms(s.surface, a, b);
          put_curvatures(out, ff ? std::optional<Curvatures>(curvatures(*ff)) : std::nullopt);
        }));
      }, py::arg("u"), py::arg("v"),
      "Gaussian, mean and principal curvatures k1 >= k2 of the parametric form (signs: docs/python.md): dict of "
      "arrays of shape S; NaN at degenerate points.");
  c.def("curvatures", [](const PySurface& s, const py::object& points) {
        require_implicit(s, "curvatures");
        return curvature_columns(map_points(points, {4}, [&](const Vec3& p, double* out) {
          put_curvatures(out, implicit_curvatures(s.surface, p));
        }));
      }, py::arg("points"), "The same for the implicit form at points on the surface (S + (3,)).");
  c.def("value", [](const PySurface& s, const py::object& points) {
        require_implicit(s, "value");
        return map_points(points, {}, [&](const Vec3& p, double* out) {
          *out = s.surface.value<double>(Vec3T<double>(p.x(), p.y(), p.z()));
        });
      }, py::arg("points"), "f(p) of the implicit form, zero on the surface, at points of shape S + (3,): shape S.");
  c.def("gradient", [](const PySurface& s, const py::object& points) {
        require_implicit(s, "gradient");
        return map_points(points, {3}, [&](const Vec3& p, double* out) { put(out, gradient(s.surface, p)); });
      }, py::arg("points"), "grad f at points of shape S + (3,): shape S + (3,).");
  c.def("hessian", [](const PySurface& s, const py::object& points) {
        require_implicit(s, "hessian");
        return map_points(points, {3, 3}, [&](const Vec3& p, double* out) {
          const Eigen::Matrix3d h = hessian(s.surface, p);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) out[3 * i + j] = h(i, j);
        });
      }, py::arg("points"), "The Hessian of f at points of shape S + (3,): shape S + (3, 3).");
}

}  // namespace

void bind_surface(py::module_& m) {
  py::class_<PySurface> c(m, "Surface",
                          "A surface of the scene format (docs/scene-format.md), evaluated on numpy arrays. Build one "
                          "with Sphere(...), Plane(...), ..., ParametricSurface(...), ImplicitSurface(...), "
                          "Bezier(...), BSpline(...) or Surface(description_dict).");
  c.def(py::init(&make_surface), py::arg("description"), py::arg("constants") = py::none(),
        "From a scene-format description such as {'sphere': {'center': [0, 0, 0], 'radius': 'R'}}; `constants` "
        "are the names its expressions may use. Raises InputError with the scene reader's message.");
  c.def_property_readonly("description", [](const PySurface& s) { return python::python_of(s.spec); },
                          "The scene-format description (a dict): put it under a scene's \"surfaces\".");
  c.def_property_readonly("constants", [](const PySurface& s) { return s.constants; },
                          "The constants its expressions use (a dict).");
  c.def_property_readonly("type", [](const PySurface& s) { return std::string(s.surface.type_name()); },
                          "The type key: 'sphere', 'parametric', 'bspline', ...");
  c.def_property_readonly("is_parametric", [](const PySurface& s) { return s.surface.is_parametric(); },
                          "Whether it has a parametric form F(u, v).");
  c.def_property_readonly("is_implicit", [](const PySurface& s) { return s.surface.is_implicit(); },
                          "Whether it has an implicit form f(x, y, z) = 0.");
  c.def_property_readonly("domain", [](const PySurface& s) -> py::object {
        if (!s.surface.is_parametric()) return py::none();
        const ParamDomain& d = s.surface.domain();
        return py::make_tuple(interval(d.u), interval(d.v));
      }, "((u_lo, u_hi), (v_lo, v_hi)) of the parametric form, else None.");
  c.def_property_readonly("periodic", [](const PySurface& s) -> py::object {
        if (!s.surface.is_parametric()) return py::none();
        return py::make_tuple(s.surface.domain().periodic_u, s.surface.domain().periodic_v);
      }, "(periodic in u, periodic in v) of the parametric form, else None.");
  c.def_property_readonly("box", [](const PySurface& s) {
        const Box& b = s.surface.box();
        return py::make_tuple(interval(b.x), interval(b.y), interval(b.z));
      }, "The region of interest ((x_lo, x_hi), (y_lo, y_hi), (z_lo, z_hi)) (docs/scene-format.md, Box).");
  c.def("__repr__", [](const PySurface& s) { return "<ssimarch.Surface " + s.spec.dump() + ">"; });
  bind_evaluation(c);
}

}  // namespace ssimarch
