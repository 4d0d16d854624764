// `ssimarch porosity`: exact porosity profiles of a packing file (issue 5). See docs/porosity.md.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "ssimarch/porosity/packing.hpp"
#include "ssimarch/porosity/plot.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch::cli {

namespace {

namespace po = ssimarch::porosity;

struct PorosityArgs {
  std::string packing, output, plot, summary, z_range, map, method = "chord";
  double radius = 0, tolerance = 1e-8;
  int radii = 0, bins = 0, axial = 0;
  unsigned threads = 0;
};

std::pair<double, double> parse_pair(const std::string& s, const char* opt) {
  const auto comma = s.find(',');
  if (comma == std::string::npos) throw CliError(std::string(opt) + " expects two comma-separated numbers, got '" + s + "'");
  try {
    std::size_t p1 = 0, p2 = 0;
    const double a = std::stod(s.substr(0, comma), &p1), b = std::stod(s.substr(comma + 1), &p2);
    if (p1 != comma || p2 != s.size() - comma - 1) throw std::invalid_argument("trailing");
    return {a, b};
  } catch (const std::exception&) {
    throw CliError(std::string(opt) + " expects two comma-separated numbers, got '" + s + "'");
  }
}

// Progress bar on stderr, only when stderr is a terminal.
std::function<void(double)> progress_bar(const char* what) {
  if (!isatty(fileno(stderr))) return {};
  return [what](double f) {
    const int w = 30, n = static_cast<int>(f * w + 0.5);
    std::fprintf(stderr, "\r%-8s [%s%s] %3d%%", what, std::string(n, '#').c_str(), std::string(w - n, ' ').c_str(),
                 static_cast<int>(f * 100 + 0.5));
    if (f >= 1.0) std::fprintf(stderr, "\r%*s\r", w + 18, "");
    std::fflush(stderr);
  };
}

std::string derived_path(const std::string& base, const std::string& suffix) {
  const std::filesystem::path p(base);
  return (p.parent_path() / (p.stem().string() + "_" + suffix + p.extension().string())).string();
}

void write_csv(const std::string& path, const std::string& header, const std::vector<std::vector<double>>& cols) {
  std::ofstream file;
  std::ostream* out = &std::cout;
  if (!path.empty()) {
    file.open(path);
    if (!file) throw CliError(path + ": cannot open for writing");
    out = &file;
  }
  *out << header << "\n";
  out->precision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c) *out << (c ? "," : "") << cols[c][i];
    *out << "\n";
  }
  if (!*out) throw CliError((path.empty() ? std::string("stdout") : path) + ": write failed");
}

nlohmann::json stats_json(const po::ProfileStats& s) {
  return {{"evaluations", s.evaluations}, {"unconverged", s.unconverged}, {"max_error_estimate", s.max_error}};
}

void run(const PorosityArgs& a) {
  using clock = std::chrono::steady_clock;
  if (!(a.radius > 0) || !std::isfinite(a.radius)) throw CliError("--container-radius must be a positive number");
  if (!(a.tolerance > 0) || !std::isfinite(a.tolerance)) throw CliError("--tolerance must be a positive number");
  if (a.radii && a.bins) throw CliError("--radii and --bins are mutually exclusive");
  if (a.radii < 0 || a.bins < 0 || a.axial < 0) throw CliError("--radii, --bins and --axial need a positive count");
  if (a.method != "chord" && a.method != "kernel") throw CliError("--method must be 'chord' or 'kernel'");
  int map_nr = 0, map_nz = 0;
  if (!a.map.empty()) {
    const auto [nr, nz] = parse_pair(a.map, "--map");
    if (nr < 1 || nz < 1 || nr != std::floor(nr) || nz != std::floor(nz) || nr > 1e5 || nz > 1e5)
      throw CliError("--map expects two positive integers NR,NZ, got '" + a.map + "'");
    map_nr = static_cast<int>(nr);
    map_nz = static_cast<int>(nz);
  }
  int radii = a.radii;
  if (!radii && !a.bins && !a.axial && !map_nr) radii = 200;  // default: radial profile
  const int kinds = (radii > 0) + (a.bins > 0) + (a.axial > 0) + (map_nr > 0);
  if (kinds > 1 && a.output.empty())
    throw CliError("several profiles requested: give -o FILE (the others go to FILE_axial.csv, FILE_map.csv)");
  if (!a.plot.empty()) {
    const auto ext = std::filesystem::path(a.plot).extension().string();
    if (ext != ".svg" && ext != ".png") throw CliError("--plot file must end in .svg or .png: " + a.plot);
    if (!radii && !a.bins && !a.axial) throw CliError("--plot needs --radii, --bins or --axial");
  }

  po::Packing pk;
  try {
    pk = po::read_packing(a.packing);
  } catch (const po::PackingError& e) {
    throw CliError(e.what());
  }
  if (pk.particles.empty()) throw CliError(a.packing + ": no particles");
  po::Container c;
  c.radius = a.radius;
  if (!a.z_range.empty()) {
    const auto [z0, z1] = parse_pair(a.z_range, "--z-range");
    if (!(z1 > z0)) throw CliError("--z-range A,B needs A < B");
    c.slab = {z0, z1};
  } else {
    double z0 = INFINITY, z1 = -INFINITY;
    for (const auto& p : pk.particles) {
      const double ext = std::abs(p.axis.z()) * p.half_length() + p.radius();
      z0 = std::min(z0, p.centre.z() - ext);
      z1 = std::max(z1, p.centre.z() + ext);
    }
    c.slab = {z0, z1};
  }
  po::ProfileOptions opt;
  opt.tolerance = a.tolerance;
  opt.threads = a.threads;
  opt.method = a.method == "kernel" ? po::Method::kernel : po::Method::chord;

  nlohmann::json js;
  js["packing"] = a.packing;
  js["particles"] = pk.particles.size();
  js["particle_type"] = pk.spherocylinders ? "spherocylinder" : "sphere";
  js["container_radius"] = c.radius;
  js["z_range"] = {c.slab.z_min, c.slab.z_max};
  js["tolerance"] = a.tolerance;
  js["method"] = a.method;
  js["outputs"] = nlohmann::json::object();

  auto t0 = clock::now();
  opt.progress = progress_bar("bulk");
  const po::Bulk bulk = po::bulk_porosity(pk.particles, c, opt);
  js["bulk_porosity"] = bulk.porosity;
  js["solid_volume"] = bulk.solid_volume;
  js["particles_in_container"] = bulk.stats.particles_used;
  js["particles_clipped"] = bulk.stats.particles_clipped;
  js["timings_s"]["bulk"] = std::chrono::duration<double>(clock::now() - t0).count();
  if (bulk.stats.particles_clipped > 0)
    std::cerr << "ssimarch: note: " << bulk.stats.particles_clipped
              << " particles stick out of the container (radius or height range); only their parts inside are counted\n";
  if (bulk.stats.particles_used < static_cast<long>(pk.particles.size()))
    std::cerr << "ssimarch: note: " << pk.particles.size() - bulk.stats.particles_used
              << " particles lie entirely outside the container and are ignored\n";

  po::PlotSpec plot;
  // The first profile goes to -o (or stdout); further ones to files named after -o.
  int emitted = 0;
  auto next_out = [&](const char* suffix) { return emitted++ == 0 ? a.output : derived_path(a.output, suffix); };
  long unconverged = bulk.stats.unconverged;
  if (radii > 0 || a.bins > 0) {
    t0 = clock::now();
    opt.progress = progress_bar("radial");
    const std::string path = next_out("radial");
    if (radii > 0) {
      const auto p = po::radial_profile(pk.particles, c, po::even_radii(c.radius, radii), opt);
      write_csv(path, "r,porosity", {p.x, p.porosity});
      js["outputs"]["radial"] = {{"file", path.empty() ? "-" : path}, {"columns", "r,porosity"}, {"n", radii}, {"stats", stats_json(p.stats)}};
      plot.series.push_back({"exact radial porosity", p.x, p.porosity, "#1f77b4", false});
      plot.xlabel = "r";
      unconverged += p.stats.unconverged;
    } else {
      const auto p = po::bin_profile(pk.particles, c, po::even_edges(c.radius, a.bins), opt);
      write_csv(path, "r_inner,r_outer,porosity", {p.x, p.x_upper, p.porosity});
      js["outputs"]["bins"] = {{"file", path.empty() ? "-" : path}, {"columns", "r_inner,r_outer,porosity"}, {"n", a.bins}, {"stats", stats_json(p.stats)}};
      std::vector<double> xs, ys;  // staircase
      for (std::size_t k = 0; k < p.x.size(); ++k) {
        xs.insert(xs.end(), {p.x[k], p.x_upper[k]});
        ys.insert(ys.end(), {p.porosity[k], p.porosity[k]});
      }
      plot.series.push_back({"exact annular-bin porosity", xs, ys, "#1f77b4", false});
      plot.xlabel = "r";
      unconverged += p.stats.unconverged;
    }
    js["timings_s"]["radial"] = std::chrono::duration<double>(clock::now() - t0).count();
  }
  if (a.axial > 0) {
    t0 = clock::now();
    opt.progress = progress_bar("axial");
    const std::string path = next_out("axial");
    const auto p = po::axial_profile(pk.particles, c, po::slice_centres(c.slab.z_min, c.slab.z_max, a.axial), opt);
    write_csv(path, "z,porosity", {p.x, p.porosity});
    js["outputs"]["axial"] = {{"file", path.empty() ? "-" : path}, {"columns", "z,porosity"}, {"n", a.axial}, {"stats", stats_json(p.stats)}};
    if (plot.series.empty()) {
      plot.series.push_back({"exact axial porosity", p.x, p.porosity, "#1f77b4", false});
      plot.xlabel = "z";
    }
    unconverged += p.stats.unconverged;
    js["timings_s"]["axial"] = std::chrono::duration<double>(clock::now() - t0).count();
  }
  if (map_nr > 0) {
    t0 = clock::now();
    opt.progress = progress_bar("map");
    const std::string path = next_out("map");
    std::vector<double> rs(map_nr);
    for (int k = 0; k < map_nr; ++k) rs[k] = c.radius * (k + 0.5) / map_nr;
    const auto m = po::porosity_map(pk.particles, c, rs, po::slice_centres(c.slab.z_min, c.slab.z_max, map_nz), opt);
    std::vector<double> cr, cz;
    for (double z : m.z)
      for (double r : m.r) cr.push_back(r), cz.push_back(z);
    write_csv(path, "r,z,porosity", {cr, cz, m.porosity});
    js["outputs"]["map"] = {{"file", path.empty() ? "-" : path}, {"columns", "r,z,porosity"}, {"n", {map_nr, map_nz}}};
    js["timings_s"]["map"] = std::chrono::duration<double>(clock::now() - t0).count();
  }
  js["unconverged_integrals"] = unconverged;
  if (!a.plot.empty()) {
    plot.title = "Porosity profile of " + std::filesystem::path(a.packing).filename().string();
    plot.ylabel = "porosity";
    try {
      po::write_plot(a.plot, plot);
    } catch (const std::exception& e) {
      throw CliError(e.what(), 1);
    }
  }
  std::ostringstream msg;
  msg.precision(10);
  msg << "bulk porosity: " << bulk.porosity << " (R = " << c.radius << ", z in [" << c.slab.z_min << ", " << c.slab.z_max
      << "], " << bulk.stats.particles_used << " particles)\n";
  std::cerr << msg.str();
  if (unconverged > 0)
    std::cerr << "ssimarch: warning: " << unconverged
              << " per-particle integrals did not reach the requested tolerance (see --summary)\n";
  if (!a.summary.empty()) {
    std::ofstream o(a.summary);
    if (!o) throw CliError(a.summary + ": cannot open for writing");
    o << js.dump(2) << "\n";
  }
}

}  // namespace

void add_porosity_command(CLI::App& app) {
  auto args = std::make_shared<PorosityArgs>();
  CLI::App* sub = app.add_subcommand(
      "porosity",
      "Exact porosity profiles of a packing of spheres/spherocylinders in a cylinder (CSV or LAMMPS dump). "
      "Writes CSV (r,porosity | r_inner,r_outer,porosity | z,porosity | r,z,porosity) to -o or stdout; "
      "the bulk porosity goes to stderr.");
  sub->add_option("packing", args->packing, "packing file: CSV (x,y,z,d or x,y,z,ux,uy,uz,d,l) or LAMMPS dump")->required();
  sub->add_option("--container-radius", args->radius, "container radius R (packing units)")->required();
  sub->add_option("--z-range", args->z_range, "height range A,B (default: the packing's vertical extent)");
  sub->add_option("--radii", args->radii, "radial profile at N radii evenly on (0, R] (default 200)");
  sub->add_option("--bins", args->bins, "profile averaged over N equal annular bins on [0, R]");
  sub->add_option("--axial", args->axial, "axial profile at N slice centres of the height range");
  sub->add_option("--map", args->map, "2D map eps(r, z) at NR x NZ cell centres (NR,NZ)");
  sub->add_option("-o,--output", args->output, "output CSV (default stdout)");
  sub->add_option("--plot", args->plot, "plot the profile: FILE.svg or FILE.png");
  sub->add_option("--summary", args->summary, "write a JSON summary (bulk porosity, timings, accuracy)");
  sub->add_option("--tolerance", args->tolerance, "absolute accuracy of each porosity value (default 1e-8)");
  sub->add_option("--threads", args->threads, "worker threads (default: all cores)");
  sub->add_option("--method", args->method, "chord (fast, default) or kernel (seed kernel integrated directly)");
  sub->callback([args] {
    try {
      run(*args);
    } catch (const std::invalid_argument& e) {  // library input checks: a user error, not internal
      throw CliError(e.what());
    }
  });
}

}  // namespace ssimarch::cli
