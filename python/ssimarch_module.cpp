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
#include <thread>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/singular_json.hpp"
#include "ssimarch/io/step_intersect.hpp"
#include "ssimarch/io/step_section.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "ssimarch/step/units.hpp"
#include "ssimarch/io/topology_json.hpp"
#include "ssimarch/io/trace_writers.hpp"
#include "ssimarch/pipeline/option_table.hpp"
#include "ssimarch/pipeline/trace_job.hpp"
#include "bindings.hpp"
#include "interrupt.hpp"

namespace py = pybind11;

namespace ssimarch {
namespace {

using python::python_of;

using Array = py::array_t<double>;

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

// The curve network of one run (network/curve_network.hpp), as the JSON's "topology".
struct PyTopology {
  std::shared_ptr<const TraceJob> job;
  const IntersectionRun* run;
  py::object part(const char* key) const { return python_of(curve_network_to_json(run->network)[key]); }
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
    // A bool is a yes/no option's value (as JSON true/false in a scene), never a number.
    const bool yes_no = spec->choices == std::vector<std::string>{"true", "false"};
    if (py::isinstance<py::bool_>(v) && yes_no) value = std::string(v.cast<bool>() ? "true" : "false");
    else if (py::isinstance<py::bool_>(v)) throw InputError(key, "expects " + spec->rule + " (got a bool)");
    else if (py::isinstance<py::str>(v)) value = v.cast<std::string>();
    else if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) value = v.cast<double>();
    else throw InputError(key, "expects a number or a name (" + spec->rule + ")");
    request.overrides.push_back({spec, std::move(value), key});
  }
  return request;
}

// trace()'s docstring: what it takes, then every keyword option from the option table with its
// admissible values, unit, default and meaning.
std::string trace_docstring() {
  std::string doc =
      "Traces a scene (a path, a JSON string or a dict; docs/scene-format.md), or the intersection of two Surface "
      "objects (trace(a, b): the scene of surfaces 'a', 'b' and the intersection 'a-b'). `only`: a name or names "
      "of intersections to trace. Keyword arguments override trace options of every intersection (keys of "
      "ssimarch.trace_options()), validated as the CLI's flags. Raises InputError; Ctrl-C raises "
      "KeyboardInterrupt when the trace returns.\n\nKeyword options:\n";
  for (const TraceOptionSpec& o : trace_option_table()) {
    doc += "  " + std::string(o.key) + ": " + std::string(o.help) + " (" + o.rule;
    if (!o.unit.empty()) doc += "; " + std::string(o.unit);
    doc += "; default " + std::string(o.default_text) + ")\n";
  }
  return doc;
}

PyTrace trace(const py::object& scene, const py::object& other, const py::object& only, const py::kwargs& overrides) {
  auto job = std::make_shared<TraceJob>();
  job->scene = python::scene_of(scene, other, "trace");
  const TraceRequest request = request_of(only, overrides);
  job->result = python::run_interruptible([&] { return trace_scene(job->scene, request); });
  return PyTrace{std::move(job)};
}

// ---- STEP models (issue 28: `ssimarch faces`, `section` and `intersect` from Python) -----------

// A face that could not be read is left out, as the CLI leaves it out, and said as a RuntimeWarning
// (the CLI's stderr line); warnings.simplefilter("error", RuntimeWarning) makes it an exception.
void warn_not_read(const std::vector<std::string>& not_read, const char* function) {
  for (const std::string& w : not_read) {
    const std::string m = std::string(function) + ": not read, left out: " + w;
    if (PyErr_WarnEx(PyExc_RuntimeWarning, m.c_str(), 2) != 0) throw py::error_already_set();
  }
}

PyTrace trace_generated(const nlohmann::json& scene_json, const std::string& source, const py::kwargs& overrides) {
  auto job = std::make_shared<TraceJob>();
  const TraceRequest request = request_of(py::none(), overrides);  // the options checked even with no pair
  if (scene_json["intersections"].empty()) return PyTrace{std::move(job)};
  job->scene = parse_scene(scene_json.dump(), source);
  job->result = python::run_interruptible([&] { return trace_scene(job->scene, request); });
  return PyTrace{std::move(job)};
}

// unit= of read_step, section and intersect: a unit's name, or None for the file's own.
std::optional<StepLengthUnit> unit_argument(const py::object& unit) {
  if (unit.is_none()) return std::nullopt;
  if (!py::isinstance<py::str>(unit)) throw InputError("unit", "must be a unit's name such as 'mm' or 'in', or None");
  return named_length_unit(unit.cast<std::string>(), "unit");
}

py::dict unit_dict(const StepLengthUnit& u) {
  return py::dict(py::arg("name") = u.name, py::arg("metres") = u.metres, py::arg("several") = u.several);
}

// The model's length unit and its faces as `ssimarch faces` lists them, each with its placed box
// (None, and the reason in "error", where its surface cannot be read).
py::dict read_step(const std::string& path, const py::object& unit_name) {
  const StepModel model = StepModel::read(path, {}, unit_argument(unit_name));
  if (!model.converted_to()) step_length_unit(model.file());  // a malformed unit named, as `ssimarch faces` does
  const StepLengthUnit& unit = model.length_unit();
  py::list faces;
  for (const StepFace& f : model.faces()) {
    py::dict d;
    d["face"] = f.index;
    d["entity"] = f.entity;
    d["line"] = f.line;
    d["surface_type"] = f.surface_type;
    d["instance"] = f.instance;
    d["box"] = py::none();
    d["error"] = py::none();
    try {
      const Box b = model.surface(f.entity, f.placement).box();
      d["box"] = py::make_tuple(py::make_tuple(b.x.lo, b.y.lo, b.z.lo), py::make_tuple(b.x.hi, b.y.hi, b.z.hi));
    } catch (const InputError& e) {
      d["error"] = std::string(e.what());
    }
    faces.append(d);
  }
  py::dict out;
  out["unit"] = unit_dict(unit);
  out["converted_from"] = model.converted_to() ? py::object(unit_dict(model.file_length_unit())) : py::none();
  out["faces"] = faces;
  return out;
}

// "X,Y,Z,NX,NY,NZ" of one plane given as six numbers, for the CLI's parser and messages.
SectionPlane plane_of(const py::handle& p, const std::string& where) {
  std::vector<double> v;
  try {
    v = p.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw InputError(where, "expected six numbers X, Y, Z, NX, NY, NZ (a point and the normal)");
  }
  std::ostringstream text;
  text.precision(17);
  for (std::size_t i = 0; i < v.size(); ++i) text << (i ? "," : "") << v[i];
  return parse_section_plane(text.str(), where);
}

PyTrace section(const std::string& model_path, const py::object& planes, const std::string& faces,
                const py::object& unit, const py::kwargs& overrides) {
  std::vector<SectionPlane> list;
  const py::sequence seq = planes.cast<py::sequence>();
  const bool one = seq.size() == 6 && !py::isinstance<py::sequence>(seq[0]);
  if (one) list.push_back(plane_of(planes, "planes"));
  for (std::size_t k = 0; !one && k < seq.size(); ++k)
    list.push_back(plane_of(seq[k], "planes[" + std::to_string(k) + "]"));
  if (list.empty()) throw InputError("planes", "at least one plane X, Y, Z, NX, NY, NZ is required");
  const StepModel model = StepModel::read(model_path, {}, unit_argument(unit));
  const SectionScene s =
      step_section_scene(std::filesystem::absolute(model_path), model, step_face_list(faces, model, "faces", 1), list);
  warn_not_read(s.not_read, "section");
  return trace_generated(s.scene, model_path, overrides);
}

PyTrace intersect(const std::string& a_path, const py::object& b_path, const std::string& a_faces,
                  const std::string& b_faces, const py::object& unit_name, const py::kwargs& overrides) {
  const std::string b = b_path.is_none() ? a_path : b_path.cast<std::string>();
  std::error_code unreadable;  // a missing file is reported by its reader below
  const bool same = b == a_path || std::filesystem::equivalent(a_path, b, unreadable);
  const std::optional<StepLengthUnit> unit = unit_argument(unit_name);
  const StepModel ma = StepModel::read(a_path, {}, unit);
  const std::unique_ptr<StepModel> mb = same ? nullptr : std::make_unique<StepModel>(StepModel::read(b, {}, unit));
  const StepModel& b_model = same ? ma : *mb;
  const StepFaceSet sa{std::filesystem::absolute(a_path), &ma, step_face_list(a_faces, ma, "a_faces", 1)};
  const StepFaceSet sb{std::filesystem::absolute(b), &b_model, step_face_list(b_faces, b_model, "b_faces", 1)};
  // solid_topology=False traces faces of one solid; they are otherwise left out here when apart.
  const bool topology = requested_options(request_of(py::none(), overrides).overrides).solid_topology;
  const IntersectScene s = step_intersect_scene(sa, sb, same, topology);
  warn_not_read(s.not_read, "intersect");
  return trace_generated(s.scene, a_path, overrides);
}

void bind_step(py::module_& m) {
  m.def("read_step", &read_step, py::arg("path"), py::kw_only(), py::arg("unit") = py::none(),
        "The length unit ({'name', 'metres', 'several'}: as the file declares it, coordinates kept in it; or the "
        "unit named by unit= ('mm', 'cm', 'm', 'um', 'nm', 'km', 'in', 'ft'), every length converted to it, the "
        "file's own then in 'converted_from') and "
        "the faces of a STEP model as `ssimarch faces` numbers them (list of dicts face, entity, line, "
        "surface_type, instance (the part's path in the assembly), box ((x0, y0, z0), (x1, y1, z1)) placed, or "
        "None with the reason in error). Raises InputError naming file:line for a malformed file (docs/cad.md).");
  m.def("section", &section, py::arg("model"), py::arg("planes"), py::kw_only(), py::arg("faces") = "all",
        py::arg("unit") = py::none(),
        "The curves where planes cut a STEP model, as `ssimarch section` (docs/cad.md, \"Sections\"): planes is "
        "one (X, Y, Z, NX, NY, NZ) or a list of them; faces 'all', '3,7' or 'part:NAME'; unit converts the "
        "model's lengths (as read_step; the planes and the curves are then in it). One intersection "
        "faceI-planeK per face whose box a plane reaches, each face trimmed to its loops. Keyword options as "
        "for trace. Unreadable faces are left out with a RuntimeWarning. Returns a Trace.");
  m.def("intersect", &intersect, py::arg("a"), py::arg("b") = py::none(), py::kw_only(), py::arg("a_faces") = "all",
        py::arg("b_faces") = "all", py::arg("unit") = py::none(),
        "The curves where the faces of one STEP part or model meet another's, as `ssimarch intersect` (docs/cad.md, "
        "\"Part against part\"): b None is a's file; face sets 'all', '3,7' or 'part:NAME'; unit reads both "
        "models converted to one length unit (as read_step); pairs whose boxes are "
        "apart are not traced. One intersection faceI-faceJ (one model) or aI-bJ (two) per pair. Keyword options "
        "as for trace. Unreadable faces are left out with a RuntimeWarning. Returns a Trace.");
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

void bind_topology(py::module_& m) {
  py::class_<PyTopology>(m, "Topology",
                         "The curve network of an intersection (docs/topology.md): the curves cut at their singular "
                         "points and open ends into edges; the JSON's \"topology\".")
      .def_property_readonly("complete", [](const PyTopology& t) { return t.run->network.complete(); },
                             "True when no curve end failed (failures is empty).")
      .def_property_readonly("vertices", [](const PyTopology& t) { return t.part("vertices"); },
                             "Singular points and open curve ends: list of dicts id, kind ('singular_point', "
                             "'isolated_point', 'boundary_end', 'interior_end'), type (the singular point's type, '' for ends), xyz, params.")
      .def_property_readonly("edges", [](const PyTopology& t) { return t.part("edges"); },
                             "Pieces of curves between vertices: list of dicts id, vertices ([from, to]; None on a "
                             "closed loop without vertex), curve (index into Intersection.curves), point_range "
                             "([first, last] point indices of that curve), length.")
      .def_property_readonly("branches", [](const PyTopology& t) { return t.part("branches"); },
                             "One per traced curve: list of dicts curve, edges (ids in the curve's order), closed, "
                             "length, rotation_index (closed branches; else None), rotation_plane, rotation_note.")
      .def_property_readonly("components", [](const PyTopology& t) { return t.part("components"); },
                             "Connected components: list of dicts branches, vertices (sorted indices).")
      .def_property_readonly("failures", [](const PyTopology& t) { return t.part("failures"); },
                             "Curve ends that did not end on the domain edge, a closure or a vertex: list of dicts "
                             "curve, end ('start' or 'end'), reason, message.")
      .def("to_json", [](const PyTopology& t) { return curve_network_to_json(t.run->network).dump(1); },
           "The JSON's \"topology\" object of this intersection.");
}

void bind_intersection(py::module_& m) {
  bind_topology(m);
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
        return python_of(singular_points_to_json(x.run->result.singular_points)); },
        "As the JSON's singular_points: list of dicts xyz, params, type, ak, multiplicity, milnor, curves and "
        "half_branches, each with tangent, param_tangent, continuation and expansion {coefficient, exponent (the "
        "leading term), normal, terms [{exponent, coefficient}]}: the Puiseux expansion W = sum coefficient "
        "X^exponent of the half-branch over the common tangent plane, X = (P - P0) . tangent, W = (P - P0) . normal, "
        "the same for every pair kind (docs/python.md).")
      .def_property_readonly("isolated_points", [](const PyIntersection& x) {
        return python_of(singular_points_to_json(x.run->result.isolated_points)); }, "As the JSON's isolated_points.")
      .def_property_readonly("stats", [](const PyIntersection& x) { return python_of(stats_to_json(x.run->result.stats)); },
                             "Statistics (dict), as the JSON's stats.")
      .def_property_readonly("start_points", [](const PyIntersection& x) { return python_of(run_json(*x.run)["start_points"]); },
                             "How the start points were found (dict), as the JSON's start_points.")
      .def_property_readonly("topology", [](const PyIntersection& x) { return PyTopology{x.job, x.run}; },
                             "The curve network (Topology): vertices, edges, branches, components, failures.")
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

  // The keywords' documentation is the option table's (the one the scene keys, the CLI's flags
  // and docs/scene-format.md come from): pybind11 keeps the pointer, so the text lives as long.
  static const std::string trace_doc = trace_docstring();
  m.def("trace", &trace, py::arg("scene"), py::arg("other") = py::none(), py::kw_only(), py::arg("only") = py::none(),
        trace_doc.c_str());
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
  ssimarch::python::main_thread() = std::this_thread::get_id();  // imports run on the main thread
  ssimarch::bind_trace(m);
  ssimarch::bind_step(m);
  ssimarch::bind_surface(m);
  ssimarch::bind_curve_geometry(m);
  py::module_ porosity = m.def_submodule("porosity", "Porosity profiles of packed beds (docs/porosity.md).");
  ssimarch::bind_porosity(porosity);
}
