// `ssimarch porosity`: exact porosity profiles of a packing file (issue 5). Argument parsing and
// output only; the run itself is the library's porosity job (pipeline/porosity_job.hpp). See
// docs/porosity.md.
#include <algorithm>
#include <charconv>
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
#include "ssimarch/io/porosity_outputs.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"
#ifdef SSIMARCH_WITH_MPI
#include "ssimarch/porosity_mpi/mpi_communicator.hpp"
#endif
#include "ssimarch/io/html_writer.hpp"
#include "viewer_page.hpp"

namespace ssimarch::cli {

namespace {

struct PorosityArgs {
  std::string packing, output, plot, summary, z_range, map, method = "chord", format, html, overlaps = "union";
  double radius = 0, tolerance = PorosityDefaults::kTolerance;
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
  double a = 0, b = 0;
  const char* end = s.data() + s.size();
  const auto ra = std::from_chars(s.data(), s.data() + std::min(comma, s.size()), a);
  const bool ok = comma != std::string::npos && ra.ec == std::errc() && ra.ptr == s.data() + comma && [&] {
    const auto rb = std::from_chars(s.data() + comma + 1, end, b);
    return rb.ec == std::errc() && rb.ptr == end;
  }();
  if (!ok) throw CliError(std::string(opt) + " expects two comma-separated numbers, got '" + s + "'");
  return {a, b};
}

// CSV or VTK XML (io/porosity_outputs.hpp) by --format, or else by -o's extension.
PorosityFileFormat output_format(const PorosityArgs& a) { return porosity_file_format(a.format, a.output, "--format"); }

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
  if (!a.radii && !a.bins && !a.axial && !job.map_radii) job.radial_points = PorosityDefaults::kRadialPoints;
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
  if (output_format(a) != PorosityFileFormat::kCsv && a.output.empty())
    throw CliError("VTK output needs -o FILE.vtm, FILE.vtp or FILE.vti");
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
      << c.slab.z_max << "], " << r.bulk.stats.particles_used;
  if (r.clumped_particles > 0)
    msg << " spheres of " << r.clumped_particles << " clumped particles)\n";
  else
    msg << " particles)\n";
  if (!quiet) std::cerr << msg.str();
  if (r.unconverged > 0)
    std::cerr << "ssimarch: warning: " << r.unconverged
              << " per-particle integrals did not reach the requested tolerance (see --summary)\n";
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
  if (!a.html.empty()) {  // the viewer page shows the bed: the job returns the particles it read
    script = require_viewer_script();
    job.keep_particles = true;
  }
  RunProgress progress(a.quiet);
  job.progress = progress.meter().fraction_callback();
  const PorosityJobResult r = run_job(job);
  progress.meter().close();
  write_outputs(a, r, job, script);
}

void write_outputs(const PorosityArgs& a, const PorosityJobResult& r, const PorosityJob& job, std::string_view script) {
  if (r.overlaps.pairs > 0) {
    const std::string what = describe_overlaps(r, job.options.overlaps);
    if (a.strict) throw CliError("--strict: " + what + "; no output was written", 1);
    std::cerr << "ssimarch: " << (job.options.overlaps == OverlapRule::kUnion ? "note: " : "warning: ") << what << "\n";
  }
  if (const std::string within = describe_clump_overlaps(r, job.options.overlaps); !within.empty() && !a.quiet)
    std::cerr << "ssimarch: note: " << within << "\n";
  const std::string name = std::filesystem::path(a.packing).filename().string();
  nlohmann::json js = porosity_summary_json(job, r, a.packing);
  OutputFiles files;  // every output or none (io/output_files.hpp)
  js["outputs"] = write_porosity_profiles(files, a.output, output_format(a), r);
  if (!a.plot.empty()) write_porosity_plot(files, a.plot, r, name);
  if (!a.summary.empty()) files.open(a.summary) << js.dump(2) << "\n";
  if (!a.html.empty()) write_viewer_page(files.open(a.html), porosity_page_data(r, r.packing, name), script);
  files.commit();
  report(r, a.quiet);
}

}  // namespace

void add_porosity_command(CLI::App& app, Commands& commands) {
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
  sub->add_option(
      "--radii", args->radii,
      "radial profile at N radii evenly on (0, R] (default " + std::to_string(PorosityDefaults::kRadialPoints) + ")");
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
                "rejected; the spheres of one clumped particle, a packing's clump column, may overlap)");
  sub->add_option("--overlaps", args->overlaps,
                  "union (default): a volume that overlapping particles share counts once, the profiles of their "
                  "union (soft-sphere DEM beds, multi-sphere clumps); sum: once per particle holding it");
  sub->add_option("--method", args->method, "chord (fast, default) or kernel (seed kernel integrated directly)");
  sub->add_flag("-q,--quiet", args->quiet, "no progress and no bulk-porosity line on stderr (notes and warnings stay)");
  add_progress_option(sub);
  add_budget_options(sub);
  commands.add(sub, [args] {
    run(*args);
    return 0;
  });
}

}  // namespace ssimarch::cli
