// Points per second of the library's own loop over surface evaluations (docs/benchmarks.md,
// "Python layer"): the reference for ssimarch.Surface.point / .normal on numpy arrays, which run the
// same calls in one C++ loop (python/surface_bindings.cpp). bench/python-overhead --surfaces
// measures the Python side. Usage: surface_throughput [N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "ssimarch/surface/derivatives.hpp"
#include "ssimarch/surface/surface.hpp"

namespace {

using ssimarch::Surface;
using ssimarch::Vec3;

// Median of 5 runs of f over n parameter pairs, in points per second.
template <class F>
double points_per_second(long n, F f) {
  std::vector<double> rates;
  for (int run = 0; run < 5; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rates.push_back(static_cast<double>(n) / s);
  }
  std::sort(rates.begin(), rates.end());
  return rates[2];
}

void measure(const char* name, const Surface& s, long n) {
  std::vector<double> u(static_cast<std::size_t>(n)), v(u.size()), out(3 * u.size());
  for (long i = 0; i < n; ++i) {  // the grid of bench/python-overhead
    u[static_cast<std::size_t>(i)] = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    v[static_cast<std::size_t>(i)] = std::fmod(0.37 * static_cast<double>(i), 1.0) * 2.0 - 1.0;
  }
  const double points = points_per_second(n, [&] {
    for (std::size_t i = 0; i < u.size(); ++i) {
      const Vec3 p = ssimarch::point(s, u[i], v[i]);
      out[3 * i] = p.x(), out[3 * i + 1] = p.y(), out[3 * i + 2] = p.z();
    }
  });
  const double normals = points_per_second(n, [&] {
    for (std::size_t i = 0; i < u.size(); ++i) {
      const auto p = ssimarch::unit_normal(s, u[i], v[i]);
      out[3 * i] = p ? p->x() : NAN;
    }
  });
  std::printf("%-6s N=%ld  point: %.3g points/s  normal: %.3g points/s  (checksum %.3f)\n", name, n, points, normals,
              out[0] + out[3 * u.size() - 3]);
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000000;
  measure("sphere", Surface(ssimarch::Sphere(Vec3(1, -2, 0.5), 2.0)), n);
  measure("torus", Surface(ssimarch::Torus(Vec3::Zero(), Vec3::UnitZ(), 3.0, 1.0)), n);
  return 0;
}
