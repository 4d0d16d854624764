// Porosity demo (see porosity_demo.hpp). Bed: 3000 monodisperse spheres d = 1 in a cylinder R = 5
// (D/d = 10); profile over z in [3, top - 3] to stay away from the floor and the free surface.
#include "ssimarch/io/porosity_demo.hpp"

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/html_writer.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/profile_plot.hpp"
#include "ssimarch/pipeline/packing_job.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"
#include "ssimarch/porosity/correlation.hpp"

namespace ssimarch {

namespace {

constexpr double kRadius = 5.0, kDiameter = 1.0;

void write_profiles(OutputFiles& files, const std::filesystem::path& out_dir, const PorosityJobResult& r) {
  std::ostream& o = files.open(out_dir / "radial_profile.csv");
  o.precision(12);
  o << "r,porosity\n";
  for (std::size_t j = 0; j < r.radial->x.size(); ++j) o << r.radial->x[j] << "," << r.radial->porosity[j] << "\n";
  std::ostream& b = files.open(out_dir / "bins.csv");
  b.precision(12);
  b << "r_inner,r_outer,porosity\n";
  for (std::size_t k = 0; k < r.bins->x.size(); ++k)
    b << r.bins->x[k] << "," << r.bins->x_upper[k] << "," << r.bins->porosity[k] << "\n";
}

// Exact profile against the de Klerk (2003) correlation, over the distance from the wall in
// diameters; the correlation's eps_b is the mean exact porosity far from the wall (x > 2.5 d).
double write_plot(OutputFiles& files, const std::filesystem::path& path, const PorosityJobResult& r) {
  const PorosityProfile& p = *r.radial;
  double core = 0;
  int nc = 0;
  for (std::size_t j = 0; j < p.x.size(); ++j)
    if (kRadius - p.x[j] > 2.5 * kDiameter) core += p.porosity[j], ++nc;
  const double eps_b = nc ? core / nc : r.bulk.porosity;
  ProfilePlot plot;
  plot.title = "Radial porosity, drop-and-roll spheres, D/d = 10";
  plot.xlabel = "distance from the wall (R - r)/d";
  plot.ylabel = "porosity";
  PlotSeries exact{"exact (ssimarch)", {}, {}, "#1f77b4", false};
  PlotSeries corr{"de Klerk (2003) correlation", {}, {}, "#d62728", true};
  for (std::size_t j = 0; j < p.x.size(); ++j) {
    const double x = (kRadius - p.x[j]) / kDiameter;
    exact.x.push_back(x);
    exact.y.push_back(p.porosity[j]);
    corr.x.push_back(x);
    corr.y.push_back(de_klerk_porosity(x, eps_b));
  }
  plot.series = {exact, corr};
  write_profile_plot(files.open(path), plot);
  return eps_b;
}

}  // namespace

void run_porosity_demo(const std::filesystem::path& out_dir, std::ostream& log, std::string_view viewer_script) {
  using clock = std::chrono::steady_clock;
  std::filesystem::create_directories(out_dir);
  SphereBedOptions gen;
  gen.container_radius = kRadius;
  gen.diameter = kDiameter;
  gen.count = 3000;
  gen.seed = 2003;
  const auto t0 = clock::now();
  const PackingJobResult bed = run_packing_job(gen);
  const double t_gen = std::chrono::duration<double>(clock::now() - t0).count();
  log << "porosity demo: " << bed.report.placed
      << " spheres (d = 1) dropped and rolled into a cylinder of diameter 10, bed height " << bed.report.height << " ("
      << t_gen << " s)\n";
  OutputFiles files;  // all or nothing (io/output_files.hpp)
  write_packing_csv(files.open(out_dir / "packing.csv"), bed.particles);
  PorosityJob job;
  job.packing = bed.particles;
  job.container_radius = kRadius;
  job.height_range = BedSlab{3.0, bed.report.height - 3.0};
  job.radial_points = 200;
  job.bins = 50;
  if (!viewer_script.empty()) {  // the page's axial profile and map
    job.axial_slices = 60;
    job.map_radii = 25;
    job.map_heights = 40;
  }
  const auto t1 = clock::now();
  const PorosityJobResult r = run_porosity_job(job);
  const double t_prof = std::chrono::duration<double>(clock::now() - t1).count();
  const Container& c = r.container;
  log << "porosity demo: exact radial profile (200 radii, 50 bins) over z in [" << c.slab.z_min << ", "
      << c.slab.z_max << "], bulk porosity " << r.bulk.porosity << " (" << t_prof << " s)\n";
  write_profiles(files, out_dir, r);
  const double eps_b = write_plot(files, out_dir / "radial_profile.svg", r);
  nlohmann::json js = {{"spheres", bed.report.placed},
                       {"container_radius", kRadius},
                       {"diameter", kDiameter},
                       {"z_range", {c.slab.z_min, c.slab.z_max}},
                       {"bulk_porosity", r.bulk.porosity},
                       {"core_porosity", eps_b},
                       {"wall_porosity", r.radial->porosity.back()},
                       {"generation_s", t_gen},
                       {"profile_s", t_prof},
                       {"correlation", "de Klerk (2003), AIChE J. 49(8) 2022-2029"}};
  files.open(out_dir / "summary.json") << js.dump(2) << "\n";
  if (!viewer_script.empty())
    write_viewer_page(files.open(out_dir / "bed.html"),
                      porosity_page_data(r, bed.particles, "drop-and-roll spheres, D/d = 10"), viewer_script);
  files.commit();
  log << "porosity demo: wrote " << (out_dir / "radial_profile.svg").string() << " (exact vs de Klerk 2003)\n";
}

}  // namespace ssimarch
