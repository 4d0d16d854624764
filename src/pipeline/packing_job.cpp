// The packing job (see packing_job.hpp).
#include "ssimarch/pipeline/packing_job.hpp"

#include <algorithm>

namespace ssimarch {

namespace {

PackingJobResult generate(const SphereBedOptions& o) {
  PackingJobResult out;
  out.particles = drop_and_roll_spheres(o, &out.report);
  const double d = std::max(o.diameter, o.diameter_max);
  out.bed = {o.container_radius, {0.0, out.report.height > 0 ? out.report.height : d}};
  return out;
}

PackingJobResult generate(const SpherocylinderRsaOptions& o) {
  PackingJobResult out;
  out.particles = rsa_spherocylinders(o, &out.report);
  out.bed = {o.container_radius, {0.0, out.report.height}};
  return out;
}

}  // namespace

PackingJobResult run_packing_job(const PackingJob& job) {
  PackingJobResult out = std::visit([](const auto& options) { return generate(options); }, job);
  out.bulk = bulk_porosity(out.particles, out.bed);
  return out;
}

}  // namespace ssimarch
