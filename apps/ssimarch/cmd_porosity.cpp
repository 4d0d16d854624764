// `ssimarch porosity`: exact porosity profiles of a packing file (issue 5). Argument parsing and
// output only; the run itself is the library's porosity job (pipeline/porosity_job.hpp). See
// docs/porosity.md.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "flag_error.hpp"
#include "run_budget.hpp"
#include "run_progress.hpp"
#include "ssimarch/core/input_files.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/porosity_vtk.hpp"
#include "ssimarch/io/profile_plot.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"
#ifdef SSIMARCH_WITH_MPI
#include "ssimarch/porosity_mpi/mpi_communicator.hpp"
#endif
#include "ssimarch/porosity/packing.hpp"
#include "ssimarch/io/html_writer.hpp"
#include "viewer_page.hpp"

namespace ssimarch::cli {

namespace {

struct PorosityArgs {
  std::string packing, output, plot, summary, z_range, map, method = "chord", format, html, overlaps = "union";
  double radius = 0, tolerance = 1e-8;
  // Profile sizes; kNotGiven where the flag is absent (an explicit 0 is an error, not "absent").
  static constexpr int kNotGiven = std::numeric_limits<int>::min();
  int radii = kNotGiven, bins = kNotGiven, axial = kNotGiven;
  unsigned threads = 0;
  bool strict = false, quiet = false;
};

// The flag that sets each field of PorosityJob, to name it in errors.
const std::map<std::string, std::string> kFlagOfJobField = {
    {"container_radius", "--container-radius"}, {"options.tolerance", "--tolerance"}, {"radial_points", "--radii"},
    {"bins", "--bins"}, {"axial_slices", "--axial"}, {"map_radii", "--map"}, {"map_heights", "--map"},
    {"height_range", "--z-range"}};

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

// VTK XML (io/porosity_vtk.hpp) by --format, or else by -o's extension.
bool vtk_format(const PorosityArgs& a) {
  if (!a.format.empty()) return a.format != "csv";
  const std::string e = std::filesystem::path(a.output).extension().string();
  return e == ".vtm" || e == ".vtp" || e == ".vti";
}

// The job the flags describe; flag syntax and combinations are checked here, values by the job.
// The count a profile flag gives: 0 when absent; an explicit value must be at least 1 (issue 29:
// `--radii 0` silently meant the default).
int profile_count(int given, const char* flag) {
  if (given == PorosityArgs::kNotGiven) return 0;
  if (given < 1) throw CliError(std::string(flag) + ": must be a positive number, got " + std::to_string(given));
  return given;
}

PorosityJob make_job(const PorosityArgs& given) {
  PorosityArgs a = given;
  a.radii = profile_count(given.radii, "--radii");
  a.bins = profile_count(given.bins, "--bins");
  a.axial = profile_count(given.axial, "--axial");
  if (a.radii && a.bins) throw CliError("--radii and --bins are mutually exclusive");
  if (a.method != "chord" && a.method != "kernel") throw CliError("--method must be 'chord' or 'kernel'");
  if (a.overlaps != "union" && a.overlaps != "sum")
    throw CliError(
        "--overlaps must be 'union' (a shared volume counted once) or 'sum' (once per particle holding it), "
        "got '" +
        a.overlaps + "'");
  PorosityJob job;
  job.packing_file = a.packing;
  job.input_limits = input_limits();
  job.container_radius = a.radius;
  job.radial_points = a.radii;
  job.bins = a.bins;
  job.axial_slices = a.axial;
  if (!a.map.empty()) {
    const auto [nr, nz] = parse_pair(a.map, "--map");
    if (nr < 1 || nz < 1 || nr != std::floor(nr) || nz != std::floor(nz) || nr > 1e5 || nz > 1e5)
      throw CliError("--map expects two positive integers NR,NZ, got '" + a.map + "'");
    job.map_radii = static_cast<int>(nr);
    job.map_heights = static_cast<int>(nz);
  }
  if (!a.radii && !a.bins && !a.axial && !job.map_radii) job.radial_points = 200;  // default: radial profile
  if (!a.z_range.empty()) {
    const auto [z0, z1] = parse_pair(a.z_range, "--z-range");
    if (!(z1 > z0)) throw CliError("--z-range A,B needs A < B");
    job.height_range = BedSlab{z0, z1};
  }
  job.options.tolerance = a.tolerance;
  job.options.threads = a.threads;
  job.options.method = a.method == "kernel" ? ProfileMethod::kKernel : ProfileMethod::kChord;
  job.options.overlaps = overlap_rule_named(a.overlaps, "--overlaps");
  const int kinds = (job.radial_points > 0) + (job.bins > 0) + (job.axial_slices > 0) + (job.map_radii > 0);
  if (a.format != "" && a.format != "csv" && a.format != "vtk" && a.format != "vtk-ascii")
    throw CliError("--format must be csv, vtk or vtk-ascii, got '" + a.format + "'");
  if (vtk_format(a) && a.output.empty()) throw CliError("VTK output needs -o FILE.vtm, FILE.vtp or FILE.vti");
  if (kinds > 1 && a.output.empty())
    throw CliError("several profiles requested: give -o FILE (the others go to FILE_axial.csv, FILE_map.csv)");
  if (!a.plot.empty()) {
    if (std::filesystem::path(a.plot).extension() != ".svg")
      throw CliError("--plot file must end in .svg: " + a.plot);
    if (!job.radial_points && !job.bins && !job.axial_slices) throw CliError("--plot needs --radii, --bins or --axial");
  }
  return job;
}

PorosityJobResult run_job(const PorosityJob& job) {
  try {
    return run_porosity_job(job);
  } catch (const InputError& e) {
    throw flag_error(e, kFlagOfJobField);
  }
}

std::string derived_path(const std::string& base, const std::string& suffix) {
  const std::filesystem::path p(base);
  return (p.parent_path() / (p.stem().string() + "_" + suffix + p.extension().string())).string();
}

void write_csv(OutputFiles& files, const std::string& path, const std::string& header,
               const std::vector<std::vector<double>>& cols) {
  std::ostream& out = files.open(path.empty() ? "-" : path);
  out << header << "\n";
  out.precision(std::numeric_limits<double>::max_digits10);
  for (std::size_t i = 0; i < cols[0].size(); ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c) out << (c ? "," : "") << cols[c][i];
    out << "\n";
  }
}

nlohmann::json stats_json(const ProfileStats& s) {
  return {{"evaluations", s.evaluations}, {"unconverged", s.unconverged}, {"max_error_estimate", s.max_error}};
}

// Writes each profile as CSV (the first to -o or stdout, further ones to files named after -o) and
// returns the summary's "outputs" entry.
nlohmann::json write_profiles(OutputFiles& files, const PorosityArgs& a, const PorosityJobResult& r) {
  nlohmann::json outputs = nlohmann::json::object();
  int emitted = 0;
  auto next_out = [&](const char* suffix) { return emitted++ == 0 ? a.output : derived_path(a.output, suffix); };
  auto entry = [](const std::string& path, const char* columns, nlohmann::json n) {
    return nlohmann::json{{"file", path.empty() ? "-" : path}, {"columns", columns}, {"n", std::move(n)}};
  };
  if (r.radial) {
    const std::string path = next_out("radial");
    write_csv(files, path, "r,porosity", {r.radial->x, r.radial->porosity});
    outputs["radial"] = entry(path, "r,porosity", r.radial->x.size());
    outputs["radial"]["stats"] = stats_json(r.radial->stats);
  } else if (r.bins) {
    const std::string path = next_out("radial");
    write_csv(files, path, "r_inner,r_outer,porosity", {r.bins->x, r.bins->x_upper, r.bins->porosity});
    outputs["bins"] = entry(path, "r_inner,r_outer,porosity", r.bins->x.size());
    outputs["bins"]["stats"] = stats_json(r.bins->stats);
  }
  if (r.axial) {
    const std::string path = next_out("axial");
    write_csv(files, path, "z,porosity", {r.axial->x, r.axial->porosity});
    outputs["axial"] = entry(path, "z,porosity", r.axial->x.size());
    outputs["axial"]["stats"] = stats_json(r.axial->stats);
  }
  if (r.map) {
    const std::string path = next_out("map");
    std::vector<double> cr, cz;
    for (double z : r.map->z)
      for (double rr : r.map->r) cr.push_back(rr), cz.push_back(z);
    write_csv(files, path, "r,z,porosity", {cr, cz, r.map->porosity});
    outputs["map"] = entry(path, "r,z,porosity", {r.map->r.size(), r.map->z.size()});
  }
  return outputs;
}

// Each profile as VTK: a 1-D profile as a .vtp polyline, the map as .vti image data. -o itself takes
// the first output of its own extension; the others are named <stem>_radial.vtp, <stem>_axial.vtp,
// <stem>_map.vti beside it; with -o FILE.vtm (or another extension) FILE.vtm lists them all.
nlohmann::json write_profiles_vtk(OutputFiles& files, const PorosityArgs& a, const PorosityJobResult& r) {
  const VtkEncoding enc = a.format == "vtk-ascii" ? VtkEncoding::kAscii : VtkEncoding::kBase64;
  const std::filesystem::path out(a.output);
  bool output_used = false;
  std::vector<std::pair<std::string, std::string>> blocks;
  nlohmann::json outputs = nlohmann::json::object();
  auto path_for = [&](const char* suffix, const char* ext) {
    if (!output_used && out.extension() == ext) {
      output_used = true;
      return out;
    }
    return out.parent_path() / (out.stem().string() + "_" + suffix + ext);
  };
  auto put = [&](const char* key, const std::filesystem::path& p, const char* arrays, nlohmann::json n) {
    blocks.emplace_back(key, p.filename().string());
    outputs[key] = {{"file", p.string()}, {"format", p.extension().string().substr(1)}, {"columns", arrays}, {"n", std::move(n)}};
  };
  if (r.radial) {
    const auto p = path_for("radial", ".vtp");
    write_vtp(files.open(p), radial_profile_poly_data(*r.radial, r.container), enc);
    put("radial", p, "r,porosity", r.radial->x.size());
    outputs["radial"]["stats"] = stats_json(r.radial->stats);
  } else if (r.bins) {
    const auto p = path_for("radial", ".vtp");
    write_vtp(files.open(p), bin_profile_poly_data(*r.bins, r.container), enc);
    put("bins", p, "r_inner,r_outer,porosity", r.bins->x.size());
    outputs["bins"]["stats"] = stats_json(r.bins->stats);
  }
  if (r.axial) {
    const auto p = path_for("axial", ".vtp");
    write_vtp(files.open(p), axial_profile_poly_data(*r.axial), enc);
    put("axial", p, "z,porosity", r.axial->x.size());
    outputs["axial"]["stats"] = stats_json(r.axial->stats);
  }
  if (r.map) {
    const auto p = path_for("map", ".vti");
    write_vti(files.open(p), porosity_map_image_data(*r.map), enc);
    put("map", p, "porosity", {r.map->r.size(), r.map->z.size()});
  }
  if (out.extension() != ".vtp" && out.extension() != ".vti") {
    const std::filesystem::path vtm = out.parent_path() / (out.stem().string() + ".vtm");
    write_vtm(files.open(vtm), blocks);
    outputs["multiblock"] = vtm.string();
  }
  return outputs;
}

// The first 1D profile against r (radial or bins) or else z.
void write_plot(OutputFiles& files, const PorosityArgs& a, const PorosityJobResult& r) {
  ProfilePlot plot;
  if (r.radial) {
    plot.series.push_back({"exact radial porosity", r.radial->x, r.radial->porosity, "#1f77b4", false});
    plot.xlabel = "r";
  } else if (r.bins) {
    plot.series.push_back(staircase("exact annular-bin porosity", r.bins->x, r.bins->x_upper, r.bins->porosity));
    plot.xlabel = "r";
  } else if (r.axial) {
    plot.series.push_back({"exact axial porosity", r.axial->x, r.axial->porosity, "#1f77b4", false});
    plot.xlabel = "z";
  }
  plot.title = "Porosity profile of " + std::filesystem::path(a.packing).filename().string();
  plot.ylabel = "porosity";
  write_profile_plot(files.open(a.plot), plot);
}

nlohmann::json summary(const PorosityArgs& a, const PorosityJobResult& r) {
  nlohmann::json js;
  js["packing"] = a.packing;
  js["particles"] = r.particles;
  js["particle_type"] = r.spherocylinders ? "spherocylinder" : "sphere";
  js["container_radius"] = r.container.radius;
  js["z_range"] = {r.container.slab.z_min, r.container.slab.z_max};
  js["tolerance"] = a.tolerance;
  js["method"] = a.method;
  js["bulk_porosity"] = r.bulk.porosity;
  js["solid_volume"] = r.bulk.solid_volume;
  js["particles_in_container"] = r.bulk.stats.particles_used;
  js["particles_clipped"] = r.bulk.stats.particles_clipped;
  const std::pair<const char*, const std::optional<double>*> stages[] = {
      {"bulk", &r.timings.bulk}, {"radial", &r.timings.radial}, {"axial", &r.timings.axial}, {"map", &r.timings.map}};
  for (const auto& [name, t] : stages)
    if (*t) js["timings_s"][name] = **t;
  js["unconverged_integrals"] = r.unconverged;
  js["overlaps"] = {{"rule", a.overlaps},
                    {"pairs", r.overlaps.pairs},
                    {"max_depth", r.overlaps.max_depth},
                    {"doubled_volume", r.overlaps.doubled_volume},
                    {"groups", r.bulk.stats.overlap_groups}};
  return js;
}

void report(const PorosityJobResult& r, bool quiet) {
  const Container& c = r.container;
  if (r.bulk.stats.particles_clipped > 0)
    std::cerr << "ssimarch: note: " << r.bulk.stats.particles_clipped
              << " particles stick out of the container (radius or height range); only their parts inside are counted\n";
  if (r.bulk.stats.particles_used < r.particles)
    std::cerr << "ssimarch: note: " << r.particles - r.bulk.stats.particles_used
              << " particles lie entirely outside the container and are ignored\n";
  std::ostringstream msg;
  msg.precision(10);
  msg << "bulk porosity: " << r.bulk.porosity << " (R = " << c.radius << ", z in [" << c.slab.z_min << ", "
      << c.slab.z_max << "], " << r.bulk.stats.particles_used << " particles)\n";
  if (!quiet) std::cerr << msg.str();
  if (r.unconverged > 0)
    std::cerr << "ssimarch: warning: " << r.unconverged
              << " per-particle integrals did not reach the requested tolerance (see --summary)\n";
}

// Porosity values outside [0, 1] over every profile (overlapping particles push them below 0).
long values_outside_unit_interval(const PorosityJobResult& r) {
  long n = !(r.bulk.porosity >= 0 && r.bulk.porosity <= 1);
  auto count = [&n](const std::vector<double>& v) {
    for (double x : v) n += !(x >= 0 && x <= 1);
  };
  if (r.radial) count(r.radial->porosity);
  if (r.bins) count(r.bins->porosity);
  if (r.axial) count(r.axial->porosity);
  if (r.map) count(r.map->porosity);
  return n;
}

// Overlapping particles: said with the count, the worst pair (1-based, in file order) and the
// volume they share, and how it was counted (--overlaps); a failure under --strict.
std::string overlap_message(const PorosityJobResult& r, bool union_rule) {
  const ParticleOverlaps& o = r.overlaps;
  std::ostringstream m;
  m.precision(6);
  m << o.pairs << " pair" << (o.pairs == 1 ? "" : "s") << " of particles overlap (worst: particles "
    << o.worst_first + 1 << " and " << o.worst_second + 1 << " by " << o.max_depth << "); their common volume ("
    << o.doubled_volume << ")";
  if (union_rule) {
    m << " is counted once: the profiles are those of the union of the particles";
    return m.str();
  }
  m << " is counted once per particle holding it (--overlaps sum), so the porosities are too low";
  if (const long bad = values_outside_unit_interval(r); bad > 0)
    m << " (" << bad << " value" << (bad == 1 ? " is" : "s are") << " outside [0, 1] for this reason)";
  return m.str();
}

void write_outputs(const PorosityArgs& a, const PorosityJobResult& r, const PorosityJob& job, std::string_view script);

// Under mpirun (an SSIMARCH_MPI build): every rank computes its share and gets the whole result;
// rank 0 alone writes files, warnings and the progress bar (docs/scaling.md).
void run(const PorosityArgs& a) {
  PorosityJob job = make_job(a);
#ifdef SSIMARCH_WITH_MPI
  std::optional<MpiCommunicator> mpi;
  if (launched_by_mpirun()) {
    if (!a.html.empty())
      throw CliError("--html: the viewer page needs every particle in one process; run it without mpirun", 2);
    mpi.emplace(nullptr, nullptr);
    job.options.communicator = &*mpi;
  }
  const bool writer = !mpi || mpi->rank() == 0;
#else
  const bool writer = true;
#endif
  if (!writer) {
    try {
      run_job(job);  // every rank takes part in the overlap search; --strict and warnings are rank 0's
    } catch (const CliError&) {
      // Every rank has the same error (the shares agree on it): rank 0 reports it and sets the exit
      // status. A quiet non-zero exit here would make mpirun kill rank 0 before it prints.
    }
    return;
  }
  // An output never replaces the packing (issue 29), refused before the work; OutputFiles checks
  // every file it opens again.
  note_input_file(a.packing);
  for (const std::string* out : {&a.output, &a.plot, &a.summary, &a.html})
    if (!out->empty() && *out != "-") refuse_input_as_output(*out);
  std::string_view script;
  if (!a.html.empty()) {  // the viewer page needs the particles: read once, given to the job
    script = require_viewer_script();
    job.packing = read_packing(job.packing_file, job.input_limits).particles;
    job.packing_file.clear();
  }
  RunProgress progress(a.quiet);
  job.progress = progress.meter().fraction_callback();
  const PorosityJobResult r = run_job(job);
  progress.meter().close();
  write_outputs(a, r, job, script);
}

void write_outputs(const PorosityArgs& a, const PorosityJobResult& r, const PorosityJob& job, std::string_view script) {
  if (r.overlaps.pairs > 0) {
    const bool union_rule = a.overlaps == "union";
    if (a.strict) throw CliError("--strict: " + overlap_message(r, union_rule) + "; no output was written", 1);
    std::cerr << "ssimarch: " << (union_rule ? "note: " : "warning: ") << overlap_message(r, union_rule) << "\n";
  }
  nlohmann::json js = summary(a, r);
  OutputFiles files;  // every output or none (io/output_files.hpp)
  js["outputs"] = vtk_format(a) ? write_profiles_vtk(files, a, r) : write_profiles(files, a, r);
  if (!a.plot.empty()) write_plot(files, a, r);
  if (!a.summary.empty()) files.open(a.summary) << js.dump(2) << "\n";
  if (!a.html.empty())
    write_viewer_page(files.open(a.html), porosity_page_data(r, job.packing, std::filesystem::path(a.packing).filename().string()),
                      script);
  files.commit();
  report(r, a.quiet);
}

}  // namespace

void add_porosity_command(CLI::App& app) {
  auto args = std::make_shared<PorosityArgs>();
  CLI::App* sub = app.add_subcommand(
      "porosity",
      "Exact porosity profiles of a packing of spheres/spherocylinders in a cylinder (CSV or LAMMPS dump). "
      "Writes CSV (r,porosity | r_inner,r_outer,porosity | z,porosity | r,z,porosity) to -o or stdout, or "
      "VTK XML files for ParaView (--format vtk); the bulk porosity and, on a terminal, a progress bar go to "
      "stderr. Exit status 130: interrupted (Ctrl-C), nothing written.");
  sub->add_option("packing", args->packing, "packing file: CSV (x,y,z,d or x,y,z,ux,uy,uz,d,l) or LAMMPS dump")->required();
  sub->add_option("--container-radius", args->radius, "container radius R (packing units)")->required();
  sub->add_option("--z-range", args->z_range, "height range A,B (default: the packing's vertical extent)");
  sub->add_option("--radii", args->radii, "radial profile at N radii evenly on (0, R] (default 200)");
  sub->add_option("--bins", args->bins, "profile averaged over N equal annular bins on [0, R]");
  sub->add_option("--axial", args->axial, "axial profile at N slice centres of the height range");
  sub->add_option("--map", args->map, "2D map eps(r, z) at NR x NZ cell centres (NR,NZ)");
  sub->add_option("-o,--output", args->output,
                  "output file (default stdout, CSV); FILE.vtm, FILE.vtp or FILE.vti: VTK XML for ParaView");
  sub->add_option("--format", args->format,
                  "csv, vtk (VTK XML, base64 binary: profiles .vtp, map .vti, a .vtm listing them) or vtk-ascii "
                  "(default: vtk for -o *.vtm|*.vtp|*.vti, else csv; docs/output-format.md)");
  sub->add_option("--plot", args->plot, "plot the profile: FILE.svg");
  sub->add_option("--summary", args->summary, "write a JSON summary (bulk porosity, timings, accuracy)");
  sub->add_option("--html", args->html,
                  "write the viewer page PAGE.html: the bed in 3D and the profiles, one offline file (docs/viewer.md)");
  sub->add_option("--tolerance", args->tolerance, "absolute accuracy of each porosity value (default 1e-8)");
  sub->add_option("--threads", args->threads, "worker threads (default: all cores)");
  sub->add_flag("--strict", args->strict,
                "fail (exit 1, no output) when particles overlap each other instead of saying so (overlapping input "
                "rejected)");
  sub->add_option("--overlaps", args->overlaps,
                  "union (default): a volume that overlapping particles share counts once, the profiles of their "
                  "union (soft-sphere DEM beds, multi-sphere clumps); sum: once per particle holding it");
  sub->add_option("--method", args->method, "chord (fast, default) or kernel (seed kernel integrated directly)");
  sub->add_flag("-q,--quiet", args->quiet, "no progress and no bulk-porosity line on stderr (notes and warnings stay)");
  add_progress_option(sub);
  add_budget_options(sub);
  sub->callback([args] { run(*args); });
}

}  // namespace ssimarch::cli
