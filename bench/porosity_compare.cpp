// Exact radial profile vs Monte Carlo at equal time (issue 5 benchmark; docs/benchmarks.md,
// "Porosity"). For each benchmark bed: the exact profile at 200 radii with tolerance 1e-8 (median of
// 3 runs), its actual error against a 1e-11 reference run, and a Monte Carlo estimate given the same
// wall-clock time (samples per radius calibrated from a pilot run). Prints a Markdown table.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "testing/packed_beds.hpp"
#include "ssimarch/porosity/monte_carlo.hpp"

using namespace ssimarch;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void row(const char* name, const testing::PackedBed& bed) {
  const auto radii = even_radii(bed.container.radius, 200);
  ProfileOptions opt;
  opt.tolerance = 1e-8;
  std::vector<double> times;
  PorosityProfile p;
  for (int k = 0; k < 3; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    p = radial_profile(bed.particles, bed.container, radii, opt);
    times.push_back(seconds_since(t0));
  }
  std::sort(times.begin(), times.end());
  const double t_exact = times[1];
  ProfileOptions ref_opt;
  ref_opt.tolerance = 1e-11;
  const PorosityProfile ref = radial_profile(bed.particles, bed.container, radii, ref_opt);
  double err = 0;
  for (std::size_t j = 0; j < radii.size(); ++j) err = std::max(err, std::abs(p.porosity[j] - ref.porosity[j]));
  // Monte Carlo pilot, then the sample count that fills t_exact.
  MonteCarloOptions mo;
  mo.samples_per_radius = 2000;
  auto t0 = std::chrono::steady_clock::now();
  monte_carlo_radial(bed.particles, bed.container, radii, mo);
  const double per_sample = seconds_since(t0) / (mo.samples_per_radius * 200.0);
  mo.samples_per_radius = std::max(100L, static_cast<long>(t_exact / (per_sample * 200.0)));
  t0 = std::chrono::steady_clock::now();
  const MonteCarloProfile mc = monte_carlo_radial(bed.particles, bed.container, radii, mo);
  const double t_mc = seconds_since(t0);
  double mc_max = 0, mc_rms = 0, se = 0;
  for (std::size_t j = 0; j < radii.size(); ++j) {
    const double e = mc.porosity[j] - ref.porosity[j];
    mc_max = std::max(mc_max, std::abs(e));
    mc_rms += e * e;
    se += mc.std_error[j];
  }
  mc_rms = std::sqrt(mc_rms / radii.size());
  se /= radii.size();
  // Samples needed for the Monte Carlo standard error to reach 1e-8 at eps = 0.4.
  const double need = 0.4 * 0.6 / 1e-16;
  std::printf("| %s | %zu | %.2f | %.1e | %.1e | %.2f | %ld | %.1e | %.1e | %.1e | %.0e s |\n", name, bed.particles.size(),
              t_exact, p.stats.max_error, err, t_mc, mo.samples_per_radius, mc_max, mc_rms, se,
              need * per_sample * 200.0);
}

}  // namespace

int main() {
  std::printf("Radial profile, 200 radii on (0, R], tolerance 1e-8, %u threads.\n\n", std::thread::hardware_concurrency());
  std::printf("| packing | particles | exact time (s, median of 3) | estimated max error | actual max error (vs 1e-11 run) "
              "| MC time (s) | MC samples per radius | MC max error | MC rms error | MC mean std. error | MC time for 1e-8 |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  row("drop-and-roll spheres, D/d = 20", testing::sphere_bed_100k());
  row("RSA spherocylinders l/d = 2, D/d = 20", testing::rod_bed_20k());
  return 0;
}
