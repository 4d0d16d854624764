// ssimarch.Surface (docs/python.md, "Surfaces"): a surface of the scene format built from Python,
// evaluated on numpy arrays by C++ loops on the library's thread pool with the GIL released
// (array_loops.hpp). The description is parsed by io/surface_json.hpp, so a Surface accepts and
// rejects exactly what a scene file does (except that an implicit surface may come without its
// box: evaluation needs none); the values are the library's (surface/derivatives.hpp; derivatives
// by Taylor jets, core/jet.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "array_loops.hpp"
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
/// Highest derivative order of Surface.derivatives and Surface.implicit_derivatives (jets of order
/// 1, 2 or 4 are instantiated).
constexpr int kMaxDerivativeOrder = 4;

// An implicit surface given without a box: evaluation reads no box, but ExprImplicit is built with
// one, so it gets this cube, which nothing reads: `Surface.box` is None (PySurface::box_given) and
// a trace first puts the other surface's box into the description (conversions.cpp).
bool lacks_box(const nlohmann::json& d) { return d.is_object() && d.contains("implicit") && !d.contains("box"); }
const nlohmann::json kUnreadBox = {{-1, 1}, {-1, 1}, {-1, 1}};

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
  const bool box_given = !lacks_box(description);
  nlohmann::json parsed = description;
  if (!box_given) parsed["box"] = kUnreadBox;
  Surface surface = surface_from_json(parsed, c, "surface");
  return PySurface{std::move(description), std::move(c), std::move(surface), box_given};
}

void require_parametric(const PySurface& s, const char* what) {
  if (!s.surface.is_parametric())
    throw InputError(what, "a " + std::string(s.surface.type_name()) +
                               " surface has no parametric form (use value/implicit_derivatives/normal on points (..., 3))");
}
void require_implicit(const PySurface& s, const char* what) {
  if (!s.surface.is_implicit())
    throw InputError(what, "a " + std::string(s.surface.type_name()) +
                               " surface has no implicit form (use point/derivatives/normal on parameters u, v)");
}
void require_order(int order) {
  if (order < 0 || order > kMaxDerivativeOrder)
    throw InputError("order", "must be an integer in [0, " + std::to_string(kMaxDerivativeOrder) + "], got " +
                                  std::to_string(order));
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

// {key(k): all[..., k, ...]} as contiguous arrays: the columns of one evaluation pass.
template <class Keys>
py::dict columns(const Array& all, const Keys& keys, bool vectors) {
  py::dict d;
  const py::object contiguous = py::module_::import("numpy").attr("ascontiguousarray");
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    py::object slice = vectors ? all[py::make_tuple(py::ellipsis(), i, py::slice(0, 3, 1))]
                               : all[py::make_tuple(py::ellipsis(), i)];
    d[keys[k]] = contiguous(slice);
  }
  return d;
}

// Every partial derivative d^(i+j)F/du^i dv^j with i + j <= order, by one jet of order K >= order.
template <int K>
py::dict derivatives_by_jet(const PySurface& s, const py::object& u, const py::object& v, int order,
                            unsigned threads) {
  std::vector<std::array<int, 2>> orders;
  std::vector<py::tuple> keys;
  for (int total = 0; total <= order; ++total)
    for (int i = total; i >= 0; --i) {
      orders.push_back({i, total - i});
      keys.push_back(py::make_tuple(i, total - i));
    }
  const auto m = static_cast<py::ssize_t>(orders.size());
  const Array all = python::map_parameters(u, v, {m, 3}, threads, [&](double uu, double vv, double* out) {
    const auto F = parametric_jet<K>(s.surface, uu, vv);
    for (std::size_t k = 0; k < orders.size(); ++k) put(out + 3 * k, partial<K>(F, orders[k][0], orders[k][1]));
  });
  return columns(all, keys, true);
}

py::dict derivatives(const PySurface& s, const py::object& u, const py::object& v, int order, unsigned threads) {
  require_parametric(s, "derivatives");
  require_order(order);
  if (order <= 1) return derivatives_by_jet<1>(s, u, v, order, threads);
  if (order == 2) return derivatives_by_jet<2>(s, u, v, order, threads);
  return derivatives_by_jet<kMaxDerivativeOrder>(s, u, v, order, threads);
}

// Every partial derivative d^(i+j+k)f/dx^i dy^j dz^k with i + j + k <= order, by one jet of order K.
template <int K>
py::dict implicit_derivatives_by_jet(const PySurface& s, const py::object& points, int order, unsigned threads) {
  std::vector<std::array<int, 3>> orders;
  std::vector<py::tuple> keys;
  for (int total = 0; total <= order; ++total)
    for (int i = total; i >= 0; --i)
      for (int j = total - i; j >= 0; --j) {
        orders.push_back({i, j, total - i - j});
        keys.push_back(py::make_tuple(i, j, total - i - j));
      }
  const auto m = static_cast<py::ssize_t>(orders.size());
  const Array all = python::map_points(points, {m}, threads, [&](const Vec3& p, double* out) {
    const Jet<3, K> f = implicit_jet<K>(s.surface, p);
    for (std::size_t k = 0; k < orders.size(); ++k) out[k] = f.derivative(orders[k]);
  });
  return columns(all, keys, false);
}

py::dict implicit_derivatives(const PySurface& s, const py::object& points, int order, unsigned threads) {
  require_implicit(s, "implicit_derivatives");
  require_order(order);
  if (order <= 1) return implicit_derivatives_by_jet<1>(s, points, order, threads);
  if (order == 2) return implicit_derivatives_by_jet<2>(s, points, order, threads);
  return implicit_derivatives_by_jet<kMaxDerivativeOrder>(s, points, order, threads);
}

py::dict curvature_columns(const Array& all) {
  const std::array<const char*, 4> names = {"gaussian", "mean", "k1", "k2"};
  return columns(all, names, false);
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

void bind_parametric_evaluation(py::class_<PySurface>& c) {
  c.def("point", [](const PySurface& s, const py::object& u, const py::object& v, unsigned threads) {
        require_parametric(s, "point");
        return python::map_parameters(u, v, {3}, threads,
                                      [&](double a, double b, double* out) { put(out, point(s.surface, a, b)); });
      }, py::arg("u"), py::arg("v"), py::kw_only(), py::arg("threads") = 0u,
      "F(u, v) of the parametric form: u, v arrays (or numbers) of one shape S (broadcast); returns S + (3,). "
      "Every evaluation method takes `threads`: threads of the library's pool (0: every core, as the CLI's "
      "--threads); Ctrl-C raises KeyboardInterrupt.");
  c.def("derivatives", &derivatives, py::arg("u"), py::arg("v"), py::arg("order") = 1, py::kw_only(),
        py::arg("threads") = 0u,
        "Every partial derivative of F up to `order` (0..4), exact (Taylor jets): a dict {(i, j): array S + (3,)} "
        "of d^(i+j)F / du^i dv^j, (0, 0) being F itself.");
  c.def("normal", [](const PySurface& s, const py::object& u, const py::object& v, unsigned threads) {
        require_parametric(s, "normal");
        return python::map_parameters(u, v, {3}, threads,
                                      [&](double a, double b, double* out) { put(out, unit_normal(s.surface, a, b)); });
      }, py::arg("u"), py::arg("v"), py::kw_only(), py::arg("threads") = 0u,
      "Unit normal Fu x Fv / |Fu x Fv| at parameters (S + (3,)); NaN at degenerate points (poles, apices).");
  c.def("curvatures", [](const PySurface& s, const py::object& u, const py::object& v, unsigned threads) {
        require_parametric(s, "curvatures");
        return curvature_columns(python::map_parameters(u, v, {4}, threads, [&](double a, double b, double* out) {
          const auto ff = fundamental_forms(s.surface, a, b);
          put_curvatures(out, ff ? std::optional<Curvatures>(curvatures(*ff)) : std::nullopt);
        }));
      }, py::arg("u"), py::arg("v"), py::kw_only(), py::arg("threads") = 0u,
      "Gaussian, mean and principal curvatures k1 >= k2 of the parametric form (signs: docs/python.md): dict of "
      "arrays of shape S; NaN at degenerate points.");
}

void bind_implicit_evaluation(py::class_<PySurface>& c) {
  c.def("normal", [](const PySurface& s, const py::object& points, unsigned threads) {
        require_implicit(s, "normal");
        return python::map_points(points, {3}, threads,
                                  [&](const Vec3& p, double* out) { put(out, unit_normal(s.surface, p)); });
      }, py::arg("points"), py::kw_only(), py::arg("threads") = 0u,
      "Unit normal grad f / |grad f| at points of shape S + (3,); NaN where grad f vanishes.");
  c.def("curvatures", [](const PySurface& s, const py::object& points, unsigned threads) {
        require_implicit(s, "curvatures");
        return curvature_columns(python::map_points(points, {4}, threads, [&](const Vec3& p, double* out) {
          put_curvatures(out, implicit_curvatures(s.surface, p));
        }));
      }, py::arg("points"), py::kw_only(), py::arg("threads") = 0u,
      "The same for the implicit form at points on the surface (S + (3,)).");
  c.def("value", [](const PySurface& s, const py::object& points, unsigned threads) {
        require_implicit(s, "value");
        return python::map_points(points, {}, threads, [&](const Vec3& p, double* out) {
          *out = s.surface.value<double>(Vec3T<double>(p.x(), p.y(), p.z()));
        });
      }, py::arg("points"), py::kw_only(), py::arg("threads") = 0u,
      "f(p) of the implicit form, zero on the surface, at points of shape S + (3,): shape S.");
  c.def("implicit_derivatives", &implicit_derivatives, py::arg("points"), py::arg("order") = 1, py::kw_only(),
        py::arg("threads") = 0u,
        "Every partial derivative of f up to `order` (0..4) at points of shape S + (3,), exact (Taylor jets): a dict "
        "{(i, j, k): array S} of d^(i+j+k)f / dx^i dy^j dz^k, (0, 0, 0) being f itself.");
  c.def("gradient", [](const PySurface& s, const py::object& points, unsigned threads) {
        require_implicit(s, "gradient");
        return python::map_points(points, {3}, threads,
                                  [&](const Vec3& p, double* out) { put(out, gradient(s.surface, p)); });
      }, py::arg("points"), py::kw_only(), py::arg("threads") = 0u,
      "grad f at points of shape S + (3,): shape S + (3,).");
  c.def("hessian", [](const PySurface& s, const py::object& points, unsigned threads) {
        require_implicit(s, "hessian");
        return python::map_points(points, {3, 3}, threads, [&](const Vec3& p, double* out) {
          const Eigen::Matrix3d h = hessian(s.surface, p);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) out[3 * i + j] = h(i, j);
        });
      }, py::arg("points"), py::kw_only(), py::arg("threads") = 0u,
      "The Hessian of f at points of shape S + (3,): shape S + (3, 3).");
}

py::tuple interval(const Interval& i) { return py::make_tuple(i.lo, i.hi); }

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
  c.def_property_readonly("box", [](const PySurface& s) -> py::object {
        if (!s.box_given) return py::none();
        const Box& b = s.surface.box();
        return py::make_tuple(interval(b.x), interval(b.y), interval(b.z));
      }, "The region of interest ((x_lo, x_hi), (y_lo, y_hi), (z_lo, z_hi)) (docs/scene-format.md, Box); None for "
         "an implicit surface made without one (trace(a, b) then uses the other surface's box).");
  c.def("__repr__", [](const PySurface& s) { return "<ssimarch.Surface " + s.spec.dump() + ">"; });
  bind_parametric_evaluation(c);
  bind_implicit_evaluation(c);
}

}  // namespace ssimarch
