// `ssimarch packing`: packing generators (drop-and-roll spheres, RSA spherocylinders). Argument
// parsing and output only; generation is the library's packing job (pipeline/packing_job.hpp).
// See docs/porosity.md.
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "commands.hpp"
#include "flag_error.hpp"
#include "run_budget.hpp"
#include "run_progress.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/pipeline/packing_job.hpp"
#include "ssimarch/porosity/packing.hpp"

namespace ssimarch::cli {

namespace {

struct PackingArgs {
  std::string output;
  double radius = 0, diameter = 1, diameter_max = 0, length = 2, height = 0, fraction = 0.2;
  long count = 1000;
  std::uint64_t seed = 1;
  bool quiet = false;
};

// The flag that sets each generator option, to name it in errors.
const std::map<std::string, std::string> kFlagOfOption = {
    {"container_radius", "--container-radius"}, {"diameter", "--diameter"}, {"count", "--count"},
    {"diameter_max", "--diameter-max"}, {"length", "--length"}, {"height", "--height"},
    {"target_solid_fraction", "--solid-fraction"}};

void write(const std::string& path, const std::vector<Particle>& ps) {
  OutputFiles files;  // all or nothing (io/output_files.hpp)
  write_packing_csv(files.open(path.empty() ? "-" : path), ps);
  files.commit();
}

void report(const char* what, const PackingJobResult& r) {
  std::cerr << what << ": " << r.report.placed << " particles, height " << r.report.height << ", bulk porosity "
            << r.bulk.porosity << " (z in [" << r.bed.slab.z_min << ", " << r.bed.slab.z_max << "])";
  if (r.report.max_overlap > 0) std::cerr << ", max overlap " << r.report.max_overlap;
  if (r.report.unstable > 0) std::cerr << ", " << r.report.unstable << " spheres stopped at the roll iteration limit";
  std::cerr << "\n";
}

// The generators promise no overlaps beyond the contact tolerance (docs/porosity.md): a packing
// that breaks it is not written, and the run fails.
void check_no_overlap(const char* what, const PackingJobResult& r, double limit) {
  if (r.report.max_overlap <= limit) return;
  std::ostringstream m;
  m << what << ": the packing has an overlap of " << r.report.max_overlap << ", above the contact tolerance " << limit
    << " that the generator promises; no output was written";
  throw CliError(m.str(), 1);
}

PackingJobResult run_job(const PackingJob& job, bool quiet) {
  try {
    RunProgress progress(quiet);  // the generators report to the thread's meter
    return run_packing_job(job);
  } catch (const InputError& e) {
    throw flag_error(e, kFlagOfOption);
  }
}

// Both generators: run the job, hold the no-overlap promise, write the particles, report.
void generate(const char* what, const PackingArgs& a, const PackingJob& job, double overlap_limit) {
  if (a.count < 1) throw CliError("--count must be >= 1");
  const PackingJobResult r = run_job(job, a.quiet);
  check_no_overlap(what, r, overlap_limit);
  write(a.output, r.particles);
  if (r.report.placed < a.count)
    std::cerr << "ssimarch: warning: " << what << " jammed after " << r.report.attempts << " attempts: placed "
              << r.report.placed << " of " << a.count << "\n";
  if (!a.quiet) report(what, r);
}

void generate_spheres(const PackingArgs& a) {
  SphereBedOptions o;
  o.container_radius = a.radius;
  o.diameter = a.diameter;
  o.diameter_max = a.diameter_max;
  o.count = a.count;
  o.seed = a.seed;
  generate("drop-and-roll", a, o, o.contact_tolerance * o.diameter);
}

void generate_spherocylinders(const PackingArgs& a) {
  SpherocylinderRsaOptions o;
  o.container_radius = a.radius;
  o.diameter = a.diameter;
  o.length = a.length;
  o.count = a.count;
  o.height = a.height;
  o.target_solid_fraction = a.fraction;
  o.seed = a.seed;
  generate("RSA", a, o, 0.0);
}

}  // namespace

void add_packing_command(CLI::App& app, Commands& commands) {
  auto a = std::make_shared<PackingArgs>();
  CLI::App* sub = app.add_subcommand("packing", "Generate packings in a cylinder (CSV for `ssimarch porosity`)");
  sub->require_subcommand(1);
  CLI::App* sp = sub->add_subcommand("spheres", "Sequential deposition (drop and roll) of spheres on the floor z = 0");
  CLI::App* sc = sub->add_subcommand("spherocylinders", "Random sequential addition of spherocylinders (non-overlapping)");
  for (CLI::App* s : {sp, sc}) {
    s->add_option("--container-radius", a->radius, "container radius R")->required();
    s->add_option("--count", a->count, "number of particles (default 1000)");
    s->add_option("--diameter", a->diameter, "particle diameter d (default 1)");
    s->add_option("--seed", a->seed, "random seed (default 1)");
    s->add_option("-o,--output", a->output, "output CSV (default stdout)");
    s->add_flag("-q,--quiet", a->quiet, "no progress and no summary line on stderr (warnings stay)");
    add_progress_option(s);
    // A time and memory budget: the generator's cost depends on the bed (docs/reliability.md).
    add_budget_options(s);
  }
  sp->add_option("--diameter-max", a->diameter_max, "if > d: diameters uniform in [d, diameter-max]");
  sc->add_option("--length", a->length, "cylinder length l (default 2)");
  sc->add_option("--height", a->height, "container height H (default: from --solid-fraction)");
  sc->add_option("--solid-fraction", a->fraction, "target solid fraction fixing H when --height is not given (default 0.2)");
  commands.add(sp, [a] {
    generate_spheres(*a);
    return 0;
  });
  commands.add(sc, [a] {
    generate_spherocylinders(*a);
    return 0;
  });
}

}  // namespace ssimarch::cli
