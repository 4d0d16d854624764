// Porosity demo (see demo.hpp). Bed: 3000 monodisperse spheres d = 1 in a cylinder R = 5 (D/d = 10);
// profile over z in [3, top - 3] to stay away from the floor and the free surface.
#include "ssimarch/porosity/demo.hpp"

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ssimarch/porosity/correlation.hpp"
#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/packing.hpp"
#include "ssimarch/porosity/plot.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch::porosity {

void run_porosity_demo(const std::filesystem::path& out_dir, std::ostream& log) {
  using clock = std::chrono::steady_clock;
  std::filesystem::create_directories(out_dir);
  const double R = 5.0, d = 1.0;
  SphereBedOptions gen;
  gen.container_radius = R;
  gen.diameter = d;
  gen.count = 3000;
  gen.seed = 2003;
  const auto t0 = clock::now();
  GeneratorReport rep;
  const auto spheres = drop_and_roll_spheres(gen, &rep);
  const double t_gen = std::chrono::duration<double>(clock::now() - t0).count();
  log << "porosity demo: " << rep.placed << " spheres (d = 1) dropped and rolled into a cylinder of diameter 10, bed height "
      << rep.height << " (" << t_gen << " s)\n";
  {
    std::ofstream o(out_dir / "packing.csv");
    write_packing_csv(o, spheres);
    if (!o) throw std::runtime_error((out_dir / "packing.csv").string() + ": write failed");
  }
  Container c;
  c.radius = R;
  c.slab = {3.0, rep.height - 3.0};
  const auto t1 = clock::now();
  const auto radii = even_radii(R, 200);
  const Profile radial = radial_profile(spheres, c, radii);
  const Profile bins = bin_profile(spheres, c, even_edges(R, 50));
  const Bulk bulk = bulk_porosity(spheres, c);
  const double t_prof = std::chrono::duration<double>(clock::now() - t1).count();
  log << "porosity demo: exact radial profile (200 radii, 50 bins) over z in [" << c.slab.z_min << ", " << c.slab.z_max
      << "], bulk porosity " << bulk.porosity << " (" << t_prof << " s)\n";
  {
    std::ofstream o(out_dir / "radial_profile.csv");
    o.precision(12);
    o << "r,porosity\n";
    for (std::size_t j = 0; j < radii.size(); ++j) o << radial.x[j] << "," << radial.porosity[j] << "\n";
    std::ofstream b(out_dir / "bins.csv");
    b.precision(12);
    b << "r_inner,r_outer,porosity\n";
    for (std::size_t k = 0; k < bins.x.size(); ++k) b << bins.x[k] << "," << bins.x_upper[k] << "," << bins.porosity[k] << "\n";
    if (!o || !b) throw std::runtime_error("porosity demo: writing the profile CSV files failed");
  }
  // Porosity far from the wall (x > 2.5 d) as the correlation's eps_b.
  double core = 0;
  int nc = 0;
  for (std::size_t j = 0; j < radii.size(); ++j)
    if (R - radii[j] > 2.5 * d) core += radial.porosity[j], ++nc;
  const double eps_b = nc ? core / nc : bulk.porosity;
  PlotSpec spec;
  spec.title = "Radial porosity, drop-and-roll spheres, D/d = 10";
  spec.xlabel = "distance from the wall (R - r)/d";
  spec.ylabel = "porosity";
  PlotSeries exact{"exact (ssimarch)", {}, {}, "#1f77b4", false};
  PlotSeries corr{"de Klerk (2003) correlation", {}, {}, "#d62728", true};
  for (std::size_t j = 0; j < radii.size(); ++j) {
    const double x = (R - radii[j]) / d;
    exact.x.push_back(x);
    exact.y.push_back(radial.porosity[j]);
    corr.x.push_back(x);
    corr.y.push_back(de_klerk_porosity(x, eps_b));
  }
  spec.series = {exact, corr};
  write_svg_plot(out_dir / "radial_profile.svg", spec);
  nlohmann::json js = {{"spheres", rep.placed},
                       {"container_radius", R},
                       {"diameter", d},
                       {"z_range", {c.slab.z_min, c.slab.z_max}},
                       {"bulk_porosity", bulk.porosity},
                       {"core_porosity", eps_b},
                       {"wall_porosity", radial.porosity.back()},
                       {"generation_s", t_gen},
                       {"profile_s", t_prof},
                       {"correlation", "de Klerk (2003), AIChE J. 49(8) 2022-2029"}};
  std::ofstream(out_dir / "summary.json") << js.dump(2) << "\n";
  log << "porosity demo: wrote " << (out_dir / "radial_profile.svg").string() << " (exact vs de Klerk 2003)\n";
}

}  // namespace ssimarch::porosity
