// Generating a packing as one typed job: the generator and its options in, the particles, the
// generator's report and the bed's bulk porosity out. The library's entry point for `ssimarch
// packing` (issue 9); generators in include/ssimarch/porosity/generator.hpp.
#pragma once

#include <variant>
#include <vector>

#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch {

/// Drop-and-roll spheres or RSA spherocylinders, with their options.
using PackingJob = std::variant<SphereBedOptions, SpherocylinderRsaOptions>;

struct PackingJobResult {
  std::vector<Particle> particles;
  GeneratorReport report;
  /// The bed: the container radius and z in [0, height] (spheres: the top of the bed, or the largest
  /// diameter for an empty bed; spherocylinders: the container height used).
  Container bed;
  BulkPorosity bulk;  ///< of `bed`, default ProfileOptions
};

/// Runs the generator. Throws InputError (located by the option's field name) for impossible options.
PackingJobResult run_packing_job(const PackingJob& job);

}  // namespace ssimarch
