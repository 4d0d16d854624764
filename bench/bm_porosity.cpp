// Google Benchmark timings of the exact porosity module (docs/benchmarks.md, "Porosity").
#include <benchmark/benchmark.h>

#include <random>

#include "testing/packed_beds.hpp"
#include "ssimarch/porosity/circle_spherocylinder.hpp"
#include "ssimarch/porosity/sphere_arc.hpp"

namespace {

using namespace ssimarch;

void radial(benchmark::State& state, const testing::PackedBed& bed) {
  const auto radii = even_radii(bed.container.radius, 200);
  ProfileOptions opt;
  opt.tolerance = 1e-8;
  PorosityProfile p;
  for (auto _ : state) {
    p = radial_profile(bed.particles, bed.container, radii, opt);
    benchmark::DoNotOptimize(p.porosity.data());
  }
  state.counters["particles"] = static_cast<double>(bed.particles.size());
  state.counters["max_error_estimate"] = p.stats.max_error;
  state.counters["evaluations"] = static_cast<double>(p.stats.evaluations);
}

void BM_RadialProfile_Spheres100k(benchmark::State& s) { radial(s, testing::sphere_bed_100k()); }
void BM_RadialProfile_Spherocylinders20k(benchmark::State& s) { radial(s, testing::rod_bed_20k()); }

void BM_Bins50_Spherocylinders20k(benchmark::State& state) {
  const auto& bed = testing::rod_bed_20k();
  const auto edges = even_edges(bed.container.radius, 50);
  for (auto _ : state) benchmark::DoNotOptimize(bin_profile(bed.particles, bed.container, edges).porosity.data());
}

void BM_Axial200_Spherocylinders20k(benchmark::State& state) {
  const auto& bed = testing::rod_bed_20k();
  const auto z = slice_centres(bed.container.slab.z_min, bed.container.slab.z_max, 200);
  for (auto _ : state) benchmark::DoNotOptimize(axial_profile(bed.particles, bed.container, z).porosity.data());
}

// Single kernel calls on random configurations (the oracle's distribution), cycling inputs.
void BM_CircleSpherocylinderKernel(benchmark::State& state) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N;
  struct In {
    SpherocylinderT<double> s;
    double z, r;
  };
  std::vector<In> in(1024);
  for (auto& c : in) {
    c.s.centre = {-1.5 + 3 * U(rng), -1.5 + 3 * U(rng), -1.5 + 3 * U(rng)};
    c.s.axis = Vec3(N(rng), N(rng), N(rng)).normalized();
    c.s.diameter = 0.2 + 1.8 * U(rng);
    c.s.length = 3 * U(rng);
    c.z = -1 + 2 * U(rng);
    c.r = 0.2 + 2.3 * U(rng);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const In& c = in[k++ & 1023];
    benchmark::DoNotOptimize(circle_spherocylinder(c.s, c.z, c.r).inside_length);
  }
}

BENCHMARK(BM_RadialProfile_Spheres100k)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_RadialProfile_Spherocylinders20k)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_Bins50_Spherocylinders20k)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_Axial200_Spherocylinders20k)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_CircleSpherocylinderKernel);

}  // namespace

BENCHMARK_MAIN();
