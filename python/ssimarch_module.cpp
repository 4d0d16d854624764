// The Python module ssimarch._ssimarch (docs/python.md): thin bindings over the library's entry
// points. A trace goes through load_scene/parse_scene (io/scene.hpp), the option table
// (pipeline/option_table.hpp) and trace_scene (pipeline/trace_job.hpp); its JSON is io/trace_writers'.
// Porosity is in porosity_bindings.cpp. Nothing is computed here: the bindings only convert between
// Python/numpy and the library's types.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/singular_json.hpp"
#include "ssimarch/io/trace_writers.hpp"
#include "ssimarch/pipeline/option_table.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace ssimarch {
namespace {

using Array = py::array_t<double>;

// A Python object from JSON, through the standard json module (the same values the CLI writes).
py::object python_of(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

// N x k array from a per-row writer.
template <class Row>
Array rows(std::size_t n, std::size_t k, Row row) {
  Array a({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(k)});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) row(i, &m(static_cast<py::ssize_t>(i), 0));
  return a;
}

// A whole job's results; the runs refer to the scene's surfaces, so both live together.
struct TraceJob {
  Scene scene;
  TraceJobResult result;
};

// One curve of one run, the job kept alive by the shared pointer.
struct PyCurve {
  std::shared_ptr<const TraceJob> job;
  const IntersectionRun* run;
  std::size_t index;
  const TracedCurve& curve() const { return run->result.curves[index]; }
};

struct PyIntersection {
  std::shared_ptr<const TraceJob> job;
  const IntersectionRun* run;
};

struct PyTrace {
  std::shared_ptr<const TraceJob> job;
};

nlohmann::json run_json(const IntersectionRun& run) { return to_json(run); }

// The differential geometry columns of a curve traced with the "geometry" option, else None.
py::object geometry_columns(const PyCurve& c) {
  if (c.run->geometry.empty()) return py::none();
  const std::vector<CurveGeometry>& g = c.run->geometry[c.index];
  py::dict d;
  auto vec = [&](Vec3 CurveGeometry::*f) {
    return rows(g.size(), 3, [&](std::size_t i, double* r) {
      for (int k = 0; k < 3; ++k) r[k] = (g[i].*f)[k];
    });
  };
  auto scalar = [&](double CurveGeometry::*f) {
    Array a(static_cast<py::ssize_t>(g.size()));
    auto m = a.mutable_unchecked<1>();
    for (std::size_t i = 0; i < g.size(); ++i) m(static_cast<py::ssize_t>(i)) = g[i].*f;
    return a;
  };
  d["t"] = vec(&CurveGeometry::t);
  d["n"] = vec(&CurveGeometry::n);
  d["b"] = vec(&CurveGeometry::b);
  d["kappa"] = scalar(&CurveGeometry::kappa);
  d["tau"] = scalar(&CurveGeometry::tau);
  d["kappa_prime"] = scalar(&CurveGeometry::kappa_prime);
  d["theta"] = scalar(&CurveGeometry::theta);
  py::list status;
  for (const auto& x : g) status.append(std::string(to_string(x.status)));
  d["status"] = status;
  return d;
}

// The scene of ssimarch.trace: an os.PathLike, a dict, a JSON text (starts with '{') or a path.
Scene scene_of(const py::object& scene) {
  if (py::isinstance<py::dict>(scene)) {
    const std::string text = py::module_::import("json").attr("dumps")(scene).cast<std::string>();
    return parse_scene(text, "<dict>");
  }
  if (py::isinstance<py::str>(scene)) {
    const std::string s = scene.cast<std::string>();
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && s[first] == '{') return parse_scene(s, "<string>");
    return load_scene(s);
  }
  if (py::hasattr(scene, "__fspath__")) return load_scene(py::str(scene.attr("__fspath__")()).cast<std::string>());
  throw py::type_error("trace: scene must be a path, a JSON string or a dict (got " +
                       py::str(py::type::of(scene).attr("__name__")).cast<std::string>() + ")");
}

// Keyword overrides through the option table: the key names the option in messages.
TraceRequest request_of(const py::object& only, const py::kwargs& overrides) {
  TraceRequest request;
  request.only_where = "only";
  if (!only.is_none()) {
    if (py::isinstance<py::str>(only)) request.only.push_back(only.cast<std::string>());
    else request.only = only.cast<std::vector<std::string>>();
  }
  for (const auto& [k, v] : overrides) {
    const std::string key = py::str(k).cast<std::string>();
    const TraceOptionSpec* spec = find_trace_option(key);
    if (!spec) throw InputError(key, "unknown option (known options: " + trace_option_keys() + ")");
    OptionValue value;
    if (py::isinstance<py::bool_>(v)) throw InputError(key, "expects " + spec->rule + " (got a bool)");
    if (py::isinstance<py::str>(v)) value = v.cast<std::string>();
    else if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) value = v.cast<double>();
    else throw InputError(key, "expects a number or a name (" + spec->rule + ")");
    request.overrides.push_back({spec, std::move(value), key});
  }
  return request;
}

PyTrace trace(const py::object& scene, const py::object& only, const py::kwargs& overrides) {
  auto job = std::make_shared<TraceJob>();
  job->scene = scene_of(scene);
  const TraceRequest request = request_of(only, overrides);
  {
    py::gil_scoped_release release;
    job->result = trace_scene(job->scene, request);
  }
  return PyTrace{std::move(job)};
}

// ---- trace results ----------------------------------------------------------------------------

void bind_curve(py::module_& m) {
  py::class_<PyCurve>(m, "Curve", "One traced curve of an intersection.")
      .def_property_readonly(
          "xyz", [](const PyCurve& c) {
            const auto& pts = c.curve().points;
            return rows(pts.size(), 3, [&](std::size_t i, double* r) {
              for (int k = 0; k < 3; ++k) r[k] = pts[i].p[k];
            });
          }, "The 3D points, an N×3 float64 array.")
      .def_property_readonly(
          "params", [](const PyCurve& c) {
            const auto& pts = c.curve().points;
            const std::size_t k = pts.empty() ? c.run->problem.unknown_names().size() : static_cast<std::size_t>(pts[0].x.size());
            return rows(pts.size(), k, [&](std::size_t i, double* r) {
              for (std::size_t j = 0; j < k; ++j) r[j] = pts[i].x[static_cast<Eigen::Index>(j)];
            });
          }, "The unknowns at each point (N×k; names in Intersection.unknowns).")
      .def_property_readonly("closed", [](const PyCurve& c) { return c.curve().closed; }, "True for a closed loop.")
      .def_property_readonly("length", [](const PyCurve& c) { return c.curve().length; }, "Arc length, model units.")
      .def_property_readonly(
          "ends", [](const PyCurve& c) {
            return python_of(run_json(*c.run)["curves"][c.index]["ends"]);
          }, "{'start': {'reason', 'message'}, 'end': {...}} as in the JSON.")
      .def_property_readonly("geometry", &geometry_columns,
                             "With the 'geometry' option: dict of columns t, n, b (N×3), kappa, tau, kappa_prime, "
                             "theta (N; NaN where undetermined) and status; else None.")
      .def("__len__", [](const PyCurve& c) { return c.curve().points.size(); })
      .def("__repr__", [](const PyCurve& c) {
        return "<ssimarch.Curve " + std::string(c.curve().closed ? "closed" : "open") + ", " +
               std::to_string(c.curve().points.size()) + " points, length " + std::to_string(c.curve().length) + ">";
      });
}

void bind_intersection(py::module_& m) {
  py::class_<PyIntersection>(m, "Intersection", "One traced intersection of a scene.")
      .def_property_readonly("name", [](const PyIntersection& x) { return x.run->spec.name; })
      .def_property_readonly("surfaces", [](const PyIntersection& x) {
        return py::make_tuple(x.run->spec.surfaces[0], x.run->spec.surfaces[1]); })
      .def_property_readonly("unknowns", [](const PyIntersection& x) { return x.run->problem.unknown_names(); },
                             "Names of the params columns.")
      .def_property_readonly(
          "curves", [](const PyIntersection& x) {
            py::list l;
            for (std::size_t i = 0; i < x.run->result.curves.size(); ++i) l.append(PyCurve{x.job, x.run, i});
            return l;
          }, "The traced curves (list of Curve).")
      .def_property_readonly("singular_points", [](const PyIntersection& x) {
        return python_of(singular_points_to_json(x.run->result.singular_points)); }, "As the JSON's singular_points.")
      .def_property_readonly("isolated_points", [](const PyIntersection& x) {
        return python_of(singular_points_to_json(x.run->result.isolated_points)); }, "As the JSON's isolated_points.")
      .def_property_readonly("stats", [](const PyIntersection& x) { return python_of(stats_to_json(x.run->result.stats)); },
                             "Statistics (dict), as the JSON's stats.")
      .def_property_readonly("start_points", [](const PyIntersection& x) { return python_of(run_json(*x.run)["start_points"]); },
                             "How the start points were found (dict), as the JSON's start_points.")
      .def_property_readonly("certified", [](const PyIntersection& x) { return x.run->result.start_search.certified; })
      .def_property_readonly("warnings", [](const PyIntersection& x) { return x.run->result.warnings; })
      .def("to_json", [](const PyIntersection& x) { return run_json(*x.run).dump(1); },
           "This intersection as the CLI writes it (one element of 'intersections').")
      .def("__repr__", [](const PyIntersection& x) {
        return "<ssimarch.Intersection " + x.run->spec.name + ", " + std::to_string(x.run->result.curves.size()) + " curve(s)>";
      });
}

void bind_trace(py::module_& m) {
  bind_curve(m);
  bind_intersection(m);
  py::class_<PyTrace>(m, "Trace", "The result of ssimarch.trace: every traced intersection.")
      .def_property_readonly(
          "intersections", [](const PyTrace& t) {
            py::list l;
            for (const auto& r : t.job->result.runs) l.append(PyIntersection{t.job, &r});
            return l;
          }, "The intersections in scene order (list of Intersection).")
      .def_property_readonly("complete", [](const PyTrace& t) { return t.job->result.complete(); },
                             "False when an intersection found no curve or a start point could not be put on it.")
      .def("__getitem__", [](const PyTrace& t, const std::string& name) {
        for (const auto& r : t.job->result.runs)
          if (r.spec.name == name) return PyIntersection{t.job, &r};
        throw py::key_error(name);
      })
      .def("__len__", [](const PyTrace& t) { return t.job->result.runs.size(); })
      .def("to_json", [](const PyTrace& t) {
        std::ostringstream out;
        write_json(out, t.job->result.runs);
        return out.str();
      }, "The CLI's JSON output (ssimarch trace SCENE), byte for byte.");

  m.def("trace", &trace, py::arg("scene"), py::kw_only(), py::arg("only") = py::none(),
        "Traces a scene (a path, a JSON string or a dict; docs/scene-format.md). `only`: a name or names of "
        "intersections to trace. Keyword arguments override trace options of every intersection (keys of "
        "ssimarch.trace_options()), validated as the CLI's flags. Raises InputError.");
  m.def("trace_options", [] {
    std::vector<std::string> keys;
    for (const auto& o : trace_option_table()) keys.emplace_back(o.key);
    return keys;
  }, "The keys of the trace options, in the order of docs/scene-format.md.");
}

}  // namespace
}  // namespace ssimarch

PYBIND11_MODULE(_ssimarch, m) {
  m.doc() = "ssimarch: surface-surface intersection curves and porosity profiles (docs/python.md)";
  py::register_exception<ssimarch::InputError>(m, "InputError", PyExc_ValueError);
  ssimarch::bind_trace(m);
  py::module_ porosity = m.def_submodule("porosity", "Porosity profiles of packed beds (docs/porosity.md).");
  ssimarch::bind_porosity(porosity);
}
