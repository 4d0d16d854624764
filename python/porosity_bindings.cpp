// ssimarch.porosity (docs/python.md): numpy particles in, numpy profiles out, through
// run_porosity_job (pipeline/porosity_job.hpp); no porosity logic here.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"

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
  }
  return out;
}

PorosityJob porosity_job(const py::object& particles, double radius, const py::object& height_range,
                         double tolerance, unsigned threads) {
  PorosityJob job;
  if (py::isinstance<py::str>(particles) || py::hasattr(particles, "__fspath__"))
    job.packing_file = py::str(py::module_::import("os").attr("fspath")(particles)).cast<std::string>();
  else
    job.packing = particles_of(particles);
  job.container_radius = radius;
  if (!height_range.is_none()) {
    const auto h = height_range.cast<std::pair<double, double>>();
    job.height_range = BedSlab{h.first, h.second};
  }
  job.options.tolerance = tolerance;
  job.options.threads = threads;
  return job;
}

PorosityJobResult run_job(const PorosityJob& job) {
  py::gil_scoped_release release;
  return run_porosity_job(job);
}

Array vector_array(const std::vector<double>& v) {
  Array a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

}  // namespace

void bind_porosity(py::module_& m) {
  m.def(
      "radial",
      [](const py::object& particles, double radius, int points, const py::object& height, double tol, unsigned threads) {
        PorosityJob job = porosity_job(particles, radius, height, tol, threads);
        if (points == 0) throw InputError("radial_points", "needs at least one radius (got 0)");
        job.radial_points = points;
        const PorosityJobResult r = run_job(job);
        return py::make_tuple(vector_array(r.radial->x), vector_array(r.radial->porosity));
      },
      py::arg("particles"), py::arg("radius"), py::arg("points") = 100, py::kw_only(), py::arg("height_range") = py::none(),
      py::arg("tolerance") = 1e-8, py::arg("threads") = 0u,
      "Radial porosity eps(r) at `points` radii evenly on (0, radius]: returns (r, eps) as numpy arrays.");
  m.def(
      "axial",
      [](const py::object& particles, double radius, int slices, const py::object& height, double tol, unsigned threads) {
        PorosityJob job = porosity_job(particles, radius, height, tol, threads);
        if (slices == 0) throw InputError("axial_slices", "needs at least one slice (got 0)");
        job.axial_slices = slices;
        const PorosityJobResult r = run_job(job);
        return py::make_tuple(vector_array(r.axial->x), vector_array(r.axial->porosity));
      },
      py::arg("particles"), py::arg("radius"), py::arg("slices") = 100, py::kw_only(), py::arg("height_range") = py::none(),
      py::arg("tolerance") = 1e-8, py::arg("threads") = 0u,
      "Axial porosity eps(z) at the centres of `slices` equal slices of the height range: returns (z, eps).");
  m.def(
      "bulk",
      [](const py::object& particles, double radius, const py::object& height, double tol, unsigned threads) {
        return run_job(porosity_job(particles, radius, height, tol, threads)).bulk.porosity;
      },
      py::arg("particles"), py::arg("radius"), py::kw_only(), py::arg("height_range") = py::none(),
      py::arg("tolerance") = 1e-8, py::arg("threads") = 0u,
      "Bulk porosity of the container (radius, height range; default: the packing's vertical extent).");
}

}  // namespace ssimarch
