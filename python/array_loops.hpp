// Loops of the Surface methods over numpy arrays (docs/python.md, "Evaluation on numpy arrays"):
// the points are cut into chunks of kEvaluationChunk, run on the library's thread pool
// (core/thread_pool.hpp; `threads` of them, 0 = every core as the CLI's --threads) with the GIL
// released, and core/interrupt.hpp's flag is checked before each chunk, so Ctrl-C stops a long
// evaluation within one chunk per thread (python/interrupt.hpp turns it into KeyboardInterrupt).
// Every point is written by one call on its own inputs into its own slot: the result is the serial
// loop's, bit for bit, whatever the number of threads.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/core/interrupt.hpp"
#include "ssimarch/core/thread_pool.hpp"
#include "ssimarch/core/vec3.hpp"

namespace ssimarch::python {

/// Points per chunk: large enough that the pool's scheduling (an atomic increment) is negligible
/// against the evaluations, small enough that Ctrl-C is seen within milliseconds and that the
/// chunks of a few threads balance.
inline constexpr std::size_t kEvaluationChunk = 4096;

/// body(i) for i in [0, n) in chunks on `threads` threads of the shared pool (0: thread_count()),
/// the GIL released; raises KeyboardInterrupt after Ctrl-C (the rest of the chunks skipped).
/// body must not touch Python objects.
template <class Body>
void evaluate_all(std::size_t n, unsigned threads, const Body& body) {
  const std::size_t chunks = (n + kEvaluationChunk - 1) / kEvaluationChunk;
  if (chunks <= 1) {
    // One chunk (a few milliseconds at most): on this thread, without the pool and without the
    // SIGINT handler of run_interruptible (three sigaction calls, the cost of a single point's
    // evaluation many times over); a Ctrl-C meanwhile is raised as soon as the call returns.
    pybind11::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  run_interruptible([&] {
    std::atomic<std::size_t> next{0};
    const std::size_t loops = std::min<std::size_t>(threads == 0 ? thread_count() : threads, chunks);
    // One self-scheduling loop per thread (as pipeline/batch_job.cpp): the pool runs `loops`
    // indices, each taking the next chunk until none is left.
    parallel_for(loops, [&](std::size_t) {
      for (std::size_t c; (c = next.fetch_add(1)) < chunks;) {
        throw_if_interrupted();
        const std::size_t end = std::min(n, (c + 1) * kEvaluationChunk);
        for (std::size_t i = c * kEvaluationChunk; i < end; ++i) body(i);
      }
    });
  });
}

/// (u, v) broadcast against each other, as C-ordered float64 arrays of one shape.
inline std::pair<pybind11::array_t<double>, pybind11::array_t<double>> parameter_arrays(const pybind11::object& u,
                                                                                        const pybind11::object& v) {
  const pybind11::array_t<double> a = as_double_array(u, "u"), b = as_double_array(v, "v");
  pybind11::tuple ab;
  try {
    ab = pybind11::module_::import("numpy").attr("broadcast_arrays")(a, b);
  } catch (const pybind11::error_already_set&) {
    throw InputError("u, v", "shapes " + shape_text(a) + " and " + shape_text(b) + " do not broadcast");
  }
  return {as_double_array(ab[0], "u"), as_double_array(ab[1], "v")};
}

inline std::size_t product(const std::vector<pybind11::ssize_t>& dims) {
  std::size_t w = 1;
  for (pybind11::ssize_t d : dims) w *= static_cast<std::size_t>(d);
  return w;
}

/// An array of shape S + tail with f(u[i], v[i], out + i * |tail|) for every parameter pair of
/// shape S.
template <class F>
pybind11::array_t<double> map_parameters(const pybind11::object& u, const pybind11::object& v,
                                         const std::vector<pybind11::ssize_t>& tail, unsigned threads, const F& f) {
  auto [a, b] = parameter_arrays(u, v);
  pybind11::array_t<double> out = new_array(shape_with(a, tail));
  const double* pu = a.data();
  const double* pv = b.data();
  double* po = out.mutable_data();
  const std::size_t width = product(tail);
  evaluate_all(static_cast<std::size_t>(a.size()), threads, [&](std::size_t i) { f(pu[i], pv[i], po + i * width); });
  return out;
}

/// An array of shape S + tail with f(p[i], out + i * |tail|) for every point of `points`, shape
/// S + (3,).
template <class F>
pybind11::array_t<double> map_points(const pybind11::object& points, const std::vector<pybind11::ssize_t>& tail,
                                     unsigned threads, const F& f) {
  const pybind11::array_t<double> p = as_points(points, "points");
  pybind11::array_t<double> out = new_array(shape_with(p, tail, 1));
  const double* pp = p.data();
  double* po = out.mutable_data();
  const std::size_t width = product(tail);
  evaluate_all(static_cast<std::size_t>(p.size() / 3), threads, [&](std::size_t i) {
    f(Vec3(pp[3 * i], pp[3 * i + 1], pp[3 * i + 2]), po + i * width);
  });
  return out;
}

}  // namespace ssimarch::python
