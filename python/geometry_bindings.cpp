// ssimarch.curve_geometry (docs/python.md): `ssimarch curve-geometry` at many points in one call,
// through geometry_at_point (pipeline/point_geometry.hpp), every method of the CLI; numpy columns
// out. No geometry is computed here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/pipeline/point_geometry.hpp"

namespace py = pybind11;

namespace ssimarch {
namespace {

using Array = py::array_t<double>;

const IntersectionSpec& intersection_of(const Scene& scene, const py::object& name) {
  if (name.is_none()) {
    if (scene.intersections.size() == 1) return scene.intersections[0];
    throw InputError("intersection", "the scene has " + std::to_string(scene.intersections.size()) +
                                         " intersections (" + scene.intersection_names() + "): name one");
  }
  const std::string n = name.cast<std::string>();
  if (const IntersectionSpec* spec = scene.intersection(n)) return *spec;
  const std::string known = scene.intersection_names();
  throw InputError("intersection", "the scene has no intersection \"" + n + "\" (it has: " +
                                       (known.empty() ? std::string("none") : known) + ")");
}

GeometryMethod method_of(const IntersectionSpec& spec, const py::object& name) {
  GeometryMethod method = spec.options.geometry.value_or(GeometryMethod::kExact);
  if (name.is_none()) return method;
  const std::string n = name.cast<std::string>();
  if (!parse(n, &method)) throw InputError("method", "unknown method \"" + n + "\" (known: " + method_names() + ")");
  return method;
}

std::optional<Vec3> toward_of(const py::object& toward) {
  if (toward.is_none()) return std::nullopt;
  const Array t = python::as_points(toward, "toward");
  if (t.size() != 3) throw InputError("toward", "expected one vector (3,), got shape " + python::shape_text(t));
  return Vec3(t.data()[0], t.data()[1], t.data()[2]);
}

// Column k of an (n, width) block of rows, reshaped to S + tail.
struct Columns {
  std::vector<py::ssize_t> shape;  // S
  py::dict out;
  Array add(const char* name, std::vector<py::ssize_t> tail) {
    std::vector<py::ssize_t> s = shape;
    s.insert(s.end(), tail.begin(), tail.end());
    Array a = python::new_array(s);
    out[name] = a;
    return a;
  }
};

void put3(double* p, const Vec3& v) {
  p[0] = v.x();
  p[1] = v.y();
  p[2] = v.z();
}

py::dict columns_of(const std::vector<PointGeometry>& rs, const std::vector<py::ssize_t>& shape, std::size_t unknowns) {
  Columns c{shape, {}};
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double* point = c.add("point", {3}).mutable_data();
  double* params = c.add("params", {static_cast<py::ssize_t>(unknowns)}).mutable_data();
  double* distance = c.add("distance", {}).mutable_data();
  double* t = c.add("t", {3}).mutable_data();
  double* n = c.add("n", {3}).mutable_data();
  double* b = c.add("b", {3}).mutable_data();
  double* kappa = c.add("kappa", {}).mutable_data();
  double* tau = c.add("tau", {}).mutable_data();
  double* kappa_prime = c.add("kappa_prime", {}).mutable_data();
  double* theta = c.add("theta", {}).mutable_data();
  py::array_t<bool> on_curve(shape);
  py::array_t<long> samples(shape);
  py::list status;
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const PointGeometry& r = rs[i];
    const CurveGeometry& g = r.geometry;
    on_curve.mutable_data()[i] = r.x.has_value();
    samples.mutable_data()[i] = r.sampled ? static_cast<long>(r.samples) : 0;
    for (std::size_t k = 0; k < unknowns; ++k)
      params[i * unknowns + k] = r.x ? (*r.x)[static_cast<Eigen::Index>(k)] : nan;
    put3(point + 3 * i, r.x ? r.point : Vec3::Constant(nan));
    distance[i] = r.x ? r.distance : nan;
    put3(t + 3 * i, g.t);
    put3(n + 3 * i, g.n);
    put3(b + 3 * i, g.b);
    kappa[i] = g.kappa;
    tau[i] = g.tau;
    kappa_prime[i] = g.kappa_prime;
    theta[i] = g.theta;
    status.append(r.x ? std::string(to_string(g.status)) : std::string("not-on-curve"));
  }
  c.out["on_curve"] = on_curve;
  c.out["samples"] = samples;
  c.out["status"] = py::module_::import("numpy").attr("array")(status, py::arg("dtype") = "U").attr("reshape")(py::tuple(py::cast(shape)));
  return c.out;
}

py::dict curve_geometry(const py::object& scene, const py::object& other, const py::object& at,
                        const py::object& intersection, const py::object& method, double step, const py::object& toward) {
  const Scene s = python::scene_of(scene, other, "curve_geometry");
  const IntersectionSpec& spec = intersection_of(s, intersection);
  PointGeometryQuery query;
  query.at = Vec3::Zero();  // set per point below
  query.method = method_of(spec, method);
  if (!(step > 0) || !std::isfinite(step)) throw InputError("step", "must be a positive length, got " + std::to_string(step));
  query.step = step;
  query.toward = toward_of(toward);
  const Array points = python::as_points(at, "at");
  const std::vector<py::ssize_t> shape = python::shape_with(points, {}, 1);
  const Problem problem = s.problem(spec);
  const std::size_t n = static_cast<std::size_t>(points.size() / 3);
  const double* p = points.data();
  const std::vector<PointGeometry> rs = python::run_interruptible([&] {
    std::vector<PointGeometry> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      throw_if_interrupted();
      PointGeometryQuery q = query;
      q.at = Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
      out.push_back(geometry_at_point(problem, q));
    }
    return out;
  });
  return columns_of(rs, shape, problem.unknown_names().size());
}

}  // namespace

void bind_curve_geometry(py::module_& m) {
  m.def("curve_geometry", &curve_geometry, py::arg("scene"), py::arg("other") = py::none(), py::kw_only(),
        py::arg("at"), py::arg("intersection") = py::none(), py::arg("method") = py::none(), py::arg("step") = 0.01,
        py::arg("toward") = py::none(),
        "The differential geometry of an intersection curve at the curve points nearest to the points `at` "
        "(shape S + (3,)), as `ssimarch curve-geometry` (docs/geometry.md): scene as for trace (or two Surface "
        "objects); `intersection` names it (default: the only one); `method` one of geometry_methods() (default: "
        "the intersection's geometry option, else 'exact'); `step` the chord of the estimate methods; `toward` "
        "orients t. Returns a dict of numpy columns of shape S (+ (3,) or (k,)): point, params, distance, t, n, b, "
        "kappa, tau, kappa_prime, theta (NaN where undetermined), status, on_curve, samples.");
  m.def("geometry_methods", [] {
    // method_names() is the library's list ("exact, ye-maekawa, ..."), the one the CLI prints.
    std::vector<std::string> names;
    const std::string all = method_names();
    for (std::size_t start = 0; start < all.size();) {
      const std::size_t comma = all.find(", ", start);
      names.push_back(all.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      start = comma == std::string::npos ? all.size() : comma + 2;
    }
    return names;
  }, "The names of the curve geometry methods (docs/geometry.md).");
}

}  // namespace ssimarch
