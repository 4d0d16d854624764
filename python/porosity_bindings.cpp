// ssimarch.porosity (docs/python.md): numpy particles in, numpy profiles out, through
// run_porosity_job (pipeline/porosity_job.hpp), and the packing generator through run_packing_job
// (pipeline/packing_job.hpp); no porosity logic here. Ctrl-C stops a profile between chunks
// (interrupt.hpp: the job's progress callback polls the stop flag).
#include <sstream>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/pipeline/packing_job.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"
#include "ssimarch/porosity/correlation.hpp"

namespace py = pybind11;

namespace ssimarch {
namespace {

using Array = py::array_t<double>;

// Particles from an N x 4 (x, y, z, d: spheres) or N x 8 (x, y, z, ux, uy, uz, d, l) array, the
// columns of the packing CSV (porosity/packing.hpp). float32 and Fortran order are converted.
std::vector<Particle> particles_of(const py::object& obj) {
  const auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!c) throw InputError("particles", "expected a numeric N×4 or N×8 array");
  if (c.ndim() != 2 || (c.shape(1) != 4 && c.shape(1) != 8)) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < c.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(c.shape(i));
    throw InputError("particles", "expected an N×4 array of spheres (x, y, z, d) or an N×8 array of "
                                  "spherocylinders (x, y, z, ux, uy, uz, d, l); got shape " + shape + (c.ndim() == 1 ? ",)" : ")"));
  }
  if (c.shape(0) == 0) throw InputError("particles", "no particles (the array has 0 rows)");
  auto m = c.unchecked<2>();
  std::vector<Particle> out(static_cast<std::size_t>(c.shape(0)));
  for (py::ssize_t i = 0; i < c.shape(0); ++i) {
    Particle& p = out[static_cast<std::size_t>(i)];
    p.centre = Vec3(m(i, 0), m(i, 1), m(i, 2));
    if (c.shape(1) == 4) {
      p.diameter = m(i, 3);
    } else {
      p.axis = Vec3(m(i, 3), m(i, 4), m(i, 5));
      p.diameter = m(i, 6);
      p.length = m(i, 7);
    }
    // The rules of the packing readers (issue 29: a negative diameter was reported as a slab height
    // range), each naming the row: a positive diameter, a length >= 0, a non-zero axis, made unit.
    const std::string row = "particles[" + std::to_string(i) + "]";
    const int d = c.shape(1) == 4 ? 3 : 6;
    if (!(p.diameter > 0))
      throw InputError(row + "[" + std::to_string(d) + "]",
                       "the diameter must be > 0, got " + std::to_string(p.diameter));
    if (c.shape(1) == 8) {
      if (!(p.length >= 0)) throw InputError(row + "[7]", "the length must be >= 0, got " + std::to_string(p.length));
      if (!(p.axis.norm() > 0)) throw InputError(row + "[3:6]", "the axis (ux, uy, uz) must not be zero");
      p.axis.normalize();
    }
  }
  return out;
}

// Clump ids of array particles (Packing::clumps): a 1-D array of integers, one per row. Floats are
// refused rather than truncated (2.5 is no particle id).
std::vector<long> clumps_of(const py::object& obj) {
  const py::array a = py::array::ensure(obj);
  if (!a || a.ndim() != 1)
    throw InputError("clumps", "expected a 1-D array of integer particle ids, one per row of `particles`");
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError("clumps",
                     std::string("expected integer particle ids, got dtype ") + py::str(a.dtype()).cast<std::string>());
  const auto ids = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  return std::vector<long>(ids.data(), ids.data() + ids.size());
}

PorosityJob porosity_job(const py::object& particles, double radius, const py::object& height_range, double tolerance,
                         unsigned threads, const std::string& overlaps, const py::object& clumps) {
  PorosityJob job;
  if (py::isinstance<py::str>(particles) || py::hasattr(particles, "__fspath__")) {
    job.packing_file = py::str(py::module_::import("os").attr("fspath")(particles)).cast<std::string>();
    if (!clumps.is_none())
      throw InputError("clumps",
                       "a packing file brings its own clump column (docs/porosity.md); clumps= is for "
                       "particles given as an array");
  } else {
    job.packing = particles_of(particles);
    if (!clumps.is_none()) job.clumps = clumps_of(clumps);
  }
  job.container_radius = radius;
  if (!height_range.is_none()) {
    const auto h = height_range.cast<std::pair<double, double>>();
    job.height_range = BedSlab{h.first, h.second};
  }
  job.options.tolerance = tolerance;
  job.options.threads = threads;
  job.options.overlaps = overlap_rule_named(overlaps);
  return job;
}

// Overlapping particles (docs/porosity.md): said as a RuntimeWarning, as the CLI says it on
// stderr (describe_overlaps), with how their common volume was counted (`overlaps=`). The CLI's
// --strict is Python's warning filter: warnings.simplefilter("error", RuntimeWarning) makes it an
// exception.
void warn_of_overlaps(const PorosityJobResult& r, OverlapRule rule) {
  const std::string m = describe_overlaps(r, rule, OverlapWording{0, "overlaps='sum'"});
  if (m.empty()) return;
  if (PyErr_WarnEx(PyExc_RuntimeWarning, m.c_str(), 2) != 0) throw py::error_already_set();
}

PorosityJobResult run_job(PorosityJob job) {
  job.progress = [](std::string_view, double) { throw_if_interrupted(); };
  PorosityJobResult r = python::run_interruptible([&] { return run_porosity_job(job); });
  warn_of_overlaps(r, job.options.overlaps);
  return r;
}

Array vector_array(const std::vector<double>& v) {
  Array a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

Array matrix_array(const std::vector<double>& v, std::size_t rows, std::size_t cols) {
  Array a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// N x 4 (x, y, z, d) for spheres, N x 8 (x, y, z, ux, uy, uz, d, l) for spherocylinders: the
// columns particles_of reads back.
Array particle_array(const std::vector<Particle>& ps, bool spherocylinders) {
  const py::ssize_t k = spherocylinders ? 8 : 4;
  Array a({static_cast<py::ssize_t>(ps.size()), k});
  auto m = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(ps.size()); ++i) {
    const Particle& p = ps[static_cast<std::size_t>(i)];
    for (int j = 0; j < 3; ++j) m(i, j) = p.centre[j];
    if (!spherocylinders) {
      m(i, 3) = p.diameter;
      continue;
    }
    for (int j = 0; j < 3; ++j) m(i, 3 + j) = p.axis[j];
    m(i, 6) = p.diameter;
    m(i, 7) = p.length;
  }
  return a;
}

// A keyword of one generator only: given to the other one, it is an error naming it.
template <class T>
T only_for(const py::object& value, const char* name, bool applies, const char* kind, T fallback) {
  if (value.is_none()) return fallback;
  if (!applies) throw InputError(name, std::string("applies to ") + kind + " only");
  return value.cast<T>();
}

PackingJob packing_job(const std::string& kind, double radius, long count, double diameter, const py::object& diameter_max,
                       const py::object& length, const py::object& height, const py::object& fraction,
                       std::uint64_t seed) {
  const bool spheres = kind == "spheres";
  if (!spheres && kind != "spherocylinders")
    throw InputError("kind", "expected \"spheres\" (drop and roll) or \"spherocylinders\" (RSA), got \"" + kind + "\"");
  if (count < 1) throw InputError("count", "must be >= 1, got " + std::to_string(count));
  if (spheres) {
    SphereBedOptions o;
    o.container_radius = radius;
    o.diameter = diameter;
    o.diameter_max = only_for(diameter_max, "diameter_max", true, "spheres", 0.0);
    only_for(length, "length", false, "spherocylinders", 0.0);
    only_for(height, "height", false, "spherocylinders", 0.0);
    only_for(fraction, "solid_fraction", false, "spherocylinders", 0.0);
    o.count = count;
    o.seed = seed;
    return o;
  }
  SpherocylinderRsaOptions o;
  only_for(diameter_max, "diameter_max", false, "spheres", 0.0);
  o.container_radius = radius;
  o.diameter = diameter;
  o.length = only_for(length, "length", true, "", o.length);
  o.height = only_for(height, "height", true, "", o.height);
  o.target_solid_fraction = only_for(fraction, "solid_fraction", true, "", o.target_solid_fraction);
  o.count = count;
  o.seed = seed;
  return o;
}

py::tuple pack(const std::string& kind, double radius, long count, double diameter, const py::object& diameter_max,
               const py::object& length, const py::object& height, const py::object& fraction, std::uint64_t seed) {
  const PackingJob job = packing_job(kind, radius, count, diameter, diameter_max, length, height, fraction, seed);
  const PackingJobResult r = python::run_interruptible([&] { return run_packing_job(job); });
  py::dict info;
  info["placed"] = r.report.placed;
  info["attempts"] = r.report.attempts;
  info["height"] = r.report.height;
  info["max_overlap"] = r.report.max_overlap;
  info["unstable"] = r.report.unstable;
  info["container_radius"] = r.bed.radius;
  info["height_range"] = py::make_tuple(r.bed.slab.z_min, r.bed.slab.z_max);
  info["bulk_porosity"] = r.bulk.porosity;
  return py::make_tuple(particle_array(r.particles, kind == "spherocylinders"), info);
}

// The packing generator and the de Klerk correlation, the companions of the profiles.
void bind_packing(py::module_& m) {
  m.def("pack", &pack, py::arg("kind"), py::arg("container_radius"), py::arg("count") = 1000, py::kw_only(),
        py::arg("diameter") = 1.0, py::arg("diameter_max") = py::none(), py::arg("length") = py::none(),
        py::arg("height") = py::none(), py::arg("solid_fraction") = py::none(), py::arg("seed") = 1u,
        "Generates a packing in a cylinder (`ssimarch packing`): kind 'spheres' (drop and roll on the floor z = 0; "
        "diameter_max > diameter: diameters uniform in [diameter, diameter_max]) or 'spherocylinders' (random "
        "sequential addition; length l, default 2; container height, default from solid_fraction, default 0.2). "
        "Deterministic for a seed. Returns (particles, info): an N×4 (spheres) or N×8 array as the functions above "
        "take, and a dict placed, attempts, height, max_overlap, unstable, container_radius, height_range, "
        "bulk_porosity.");
  m.def(
      "de_klerk",
      [](const py::object& x_wall, double eps_bulk) {
        const Array x = python::as_double_array(x_wall, "x_wall");
        Array out = python::new_array(python::shape_with(x, {}));
        for (py::ssize_t i = 0; i < x.size(); ++i) out.mutable_data()[i] = de_klerk_porosity(x.data()[i], eps_bulk);
        return out;
      },
      py::arg("x_wall"), py::arg("eps_bulk"),
      "The de Klerk (2003) correlation of the radial porosity of monodisperse sphere beds "
      "(porosity/correlation.hpp) at distances x_wall = (R - r) / d from the wall (an array), for comparison plots.");
}

}  // namespace

void bind_porosity(py::module_& m) {
  m.def(
      "radial",
      [](const py::object& particles, double radius, int points, const py::object& height, double tol, unsigned threads,
         const std::string& overlaps, const py::object& clumps) {
        PorosityJob job = porosity_job(particles, radius, height, tol, threads, overlaps, clumps);
        if (points == 0) throw InputError("radial_points", "needs at least one radius (got 0)");
        job.radial_points = points;
        const PorosityJobResult r = run_job(job);
        return py::make_tuple(vector_array(r.radial->x), vector_array(r.radial->porosity));
      },
      py::arg("particles"), py::arg("radius"), py::arg("points") = PorosityDefaults::kRadialPoints, py::kw_only(),
      py::arg("height_range") = py::none(), py::arg("tolerance") = PorosityDefaults::kTolerance,
      py::arg("threads") = 0u, py::arg("overlaps") = "union", py::arg("clumps") = py::none(),
      "Radial porosity eps(r) at `points` radii evenly on (0, radius]: returns (r, eps) as numpy arrays.");
  m.def(
      "axial",
      [](const py::object& particles, double radius, int slices, const py::object& height, double tol, unsigned threads,
         const std::string& overlaps, const py::object& clumps) {
        PorosityJob job = porosity_job(particles, radius, height, tol, threads, overlaps, clumps);
        if (slices == 0) throw InputError("axial_slices", "needs at least one slice (got 0)");
        job.axial_slices = slices;
        const PorosityJobResult r = run_job(job);
        return py::make_tuple(vector_array(r.axial->x), vector_array(r.axial->porosity));
      },
      py::arg("particles"), py::arg("radius"), py::arg("slices") = PorosityDefaults::kAxialSlices, py::kw_only(),
      py::arg("height_range") = py::none(), py::arg("tolerance") = PorosityDefaults::kTolerance,
      py::arg("threads") = 0u, py::arg("overlaps") = "union", py::arg("clumps") = py::none(),
      "Axial porosity eps(z) at the centres of `slices` equal slices of the height range: returns (z, eps).");
  m.def(
      "bulk",
      [](const py::object& particles, double radius, const py::object& height, double tol, unsigned threads,
         const std::string& overlaps, const py::object& clumps) {
        return run_job(porosity_job(particles, radius, height, tol, threads, overlaps, clumps)).bulk.porosity;
      },
      py::arg("particles"), py::arg("radius"), py::kw_only(), py::arg("height_range") = py::none(),
      py::arg("tolerance") = PorosityDefaults::kTolerance, py::arg("threads") = 0u, py::arg("overlaps") = "union",
      py::arg("clumps") = py::none(),
      "Bulk porosity of the container (radius, height range; default: the packing's vertical extent).");
  m.def(
      "bins",
      [](const py::object& particles, double radius, int bins, const py::object& height, double tol, unsigned threads,
         const std::string& overlaps, const py::object& clumps) {
        PorosityJob job = porosity_job(particles, radius, height, tol, threads, overlaps, clumps);
        if (bins == 0) throw InputError("bins", "needs at least one bin (got 0)");
        job.bins = bins;
        const PorosityJobResult r = run_job(job);
        return py::make_tuple(vector_array(r.bins->x), vector_array(r.bins->x_upper), vector_array(r.bins->porosity));
      },
      py::arg("particles"), py::arg("radius"), py::arg("bins") = 50, py::kw_only(),
      py::arg("height_range") = py::none(), py::arg("tolerance") = PorosityDefaults::kTolerance,
      py::arg("threads") = 0u, py::arg("overlaps") = "union", py::arg("clumps") = py::none(),
      "Porosity averaged over `bins` equal annular bins of [0, radius] (the CLI's --bins): returns (r_inner, "
      "r_outer, eps).");
  m.def(
      "map",
      [](const py::object& particles, double radius, int radii, int heights, const py::object& height, double tol,
         unsigned threads, const std::string& overlaps, const py::object& clumps) {
        PorosityJob job = porosity_job(particles, radius, height, tol, threads, overlaps, clumps);
        if (radii == 0 || heights == 0)
          throw InputError("map", "needs at least one radius and one height (got " + std::to_string(radii) + " x " +
                                      std::to_string(heights) + ")");
        job.map_radii = radii;
        job.map_heights = heights;
        const PorosityJobResult r = run_job(job);
        return py::make_tuple(vector_array(r.map->r), vector_array(r.map->z),
                              matrix_array(r.map->porosity, r.map->z.size(), r.map->r.size()));
      },
      py::arg("particles"), py::arg("radius"), py::arg("radii") = PorosityDefaults::kMapCells,
      py::arg("heights") = PorosityDefaults::kMapCells, py::kw_only(), py::arg("height_range") = py::none(),
      py::arg("tolerance") = PorosityDefaults::kTolerance, py::arg("threads") = 0u, py::arg("overlaps") = "union",
      py::arg("clumps") = py::none(),
      "Porosity map eps(r, z) at the centres of radii x heights cells (the CLI's --map): returns (r, z, eps) with "
      "eps of shape (heights, radii), eps[i, j] at z[i], r[j].");
  bind_packing(m);
}

}  // namespace ssimarch
