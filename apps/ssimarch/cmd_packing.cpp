// `ssimarch packing`: packing generators (drop-and-roll spheres, RSA spherocylinders). See docs/porosity.md.
#include <cmath>
#include <fstream>
#include <iostream>

#include "commands.hpp"
#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/packing.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch::cli {

namespace {

namespace po = ssimarch::porosity;

struct PackingArgs {
  std::string output;
  double radius = 0, diameter = 1, diameter_max = 0, length = 2, height = 0, fraction = 0.2;
  long count = 1000;
  std::uint64_t seed = 1;
};

void write(const std::string& path, const std::vector<po::Particle>& ps) {
  std::ofstream file;
  std::ostream* out = &std::cout;
  if (!path.empty()) {
    file.open(path);
    if (!file) throw CliError(path + ": cannot open for writing");
    out = &file;
  }
  po::write_packing_csv(*out, ps);
  if (!*out) throw CliError((path.empty() ? std::string("stdout") : path) + ": write failed");
}

void check_common(const PackingArgs& a) {
  if (!(a.radius > 0) || !std::isfinite(a.radius)) throw CliError("--container-radius must be a positive number");
  if (!(a.diameter > 0) || !std::isfinite(a.diameter)) throw CliError("--diameter must be a positive number");
  if (a.diameter >= 2 * a.radius) throw CliError("--diameter must be smaller than the container diameter");
  if (a.count < 1) throw CliError("--count must be >= 1");
}

void report(const char* what, const po::GeneratorReport& r, const std::vector<po::Particle>& ps, double R, double z0,
            double z1) {
  po::Container c;
  c.radius = R;
  c.slab = {z0, z1};
  const auto bulk = po::bulk_porosity(ps, c);
  std::cerr << what << ": " << r.placed << " particles, height " << r.height << ", bulk porosity " << bulk.porosity
            << " (z in [" << z0 << ", " << z1 << "])";
  if (r.max_overlap > 0) std::cerr << ", max overlap " << r.max_overlap;
  if (r.unstable > 0) std::cerr << ", " << r.unstable << " spheres stopped at the roll iteration limit";
  std::cerr << "\n";
}

}  // namespace

void add_packing_command(CLI::App& app) {
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
  }
  sp->add_option("--diameter-max", a->diameter_max, "if > d: diameters uniform in [d, diameter-max]");
  sc->add_option("--length", a->length, "cylinder length l (default 2)");
  sc->add_option("--height", a->height, "container height H (default: from --solid-fraction)");
  sc->add_option("--solid-fraction", a->fraction, "target solid fraction fixing H when --height is not given (default 0.2)");
  sp->callback([a] {
    check_common(*a);
    if (a->diameter_max != 0 && !(a->diameter_max >= a->diameter)) throw CliError("--diameter-max must be >= --diameter");
    po::SphereBedOptions o;
    o.container_radius = a->radius;
    o.diameter = a->diameter;
    o.diameter_max = a->diameter_max;
    o.count = a->count;
    o.seed = a->seed;
    po::GeneratorReport r;
    const auto ps = po::drop_and_roll_spheres(o, &r);
    write(a->output, ps);
    const double d = std::max(a->diameter, a->diameter_max);
    report("drop-and-roll", r, ps, a->radius, 0.0, r.height > 0 ? r.height : d);
  });
  sc->callback([a] {
    check_common(*a);
    if (!(a->length >= 0) || !std::isfinite(a->length)) throw CliError("--length must be >= 0");
    if (a->height < 0 || !std::isfinite(a->height)) throw CliError("--height must be >= 0");
    if (!(a->fraction > 0 && a->fraction < 1)) throw CliError("--solid-fraction must be in (0, 1)");
    po::SpherocylinderRsaOptions o;
    o.container_radius = a->radius;
    o.diameter = a->diameter;
    o.length = a->length;
    o.count = a->count;
    o.height = a->height;
    o.target_solid_fraction = a->fraction;
    o.seed = a->seed;
    po::GeneratorReport r;
    const auto ps = po::rsa_spherocylinders(o, &r);
    write(a->output, ps);
    if (r.placed < a->count)
      std::cerr << "ssimarch: warning: RSA jammed after " << r.attempts << " attempts: placed " << r.placed << " of "
                << a->count << "\n";
    report("RSA", r, ps, a->radius, 0.0, r.height);
  });
}

}  // namespace ssimarch::cli
