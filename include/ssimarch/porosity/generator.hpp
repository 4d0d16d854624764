// Packing generators, so that users and tests have realistic beds without a DEM code.
//
// drop_and_roll_spheres: sequential deposition (Visscher & Bolsterli, Nature 239 (1972) 504): each
//   sphere falls vertically from a random point over the cylinder until it touches the floor or a
//   sphere, then rolls down the steepest feasible direction (gravity projected on the cone allowed by
//   its contacts with spheres, the wall and the floor) until it rests on the floor or is stable
//   (gravity balanced by its contacts). Contacts are resolved to contact_tolerance.
// rsa_spherocylinders: random sequential addition (Widom 1966; Sherwood, J. Phys. A 30 (1997) L839
//   for spherocylinders): uniformly random positions and isotropic orientations inside the
//   container, accepted when the segment-segment distance to every placed particle is >= d.
// Both are seedable (std::mt19937_64) and deterministic for a given seed. Bulk porosities reached
// are in docs/porosity.md ("Generators").
#pragma once

#include <cstdint>
#include <vector>

#include "ssimarch/porosity/particle.hpp"

namespace ssimarch {

struct SphereBedOptions {
  double container_radius = 5.0;  ///< R, model length
  double diameter = 1.0;          ///< d (minimum diameter when diameter_max > diameter)
  double diameter_max = 0.0;      ///< > diameter: diameters uniform in [diameter, diameter_max]
  long count = 1000;
  std::uint64_t seed = 1;
  /// Gaps <= contact_tolerance * d count as contacts; final overlaps are below it. Default 1e-9.
  double contact_tolerance = 1e-9;
};

struct SpherocylinderRsaOptions {
  double container_radius = 5.0;  ///< R
  double height = 0.0;            ///< H; 0: chosen so that `count` particles fill target_solid_fraction
  double diameter = 1.0;          ///< sigma
  double length = 2.0;            ///< l
  long count = 1000;
  double target_solid_fraction = 0.2;
  long max_attempts_per_particle = 10000;
  std::uint64_t seed = 1;
};

struct GeneratorReport {
  long placed = 0;
  long attempts = 0;
  double height = 0.0;       ///< container height used (RSA) or top of the bed (spheres)
  double max_overlap = 0.0;  ///< largest overlap depth found between particles, model length
  long unstable = 0;         ///< spheres whose roll broke its termination bound (left where they were; 0 unless a bug)
  long roll_passes = 0;      ///< roll passes of all spheres (drop-and-roll): the work, a few dozen per sphere
  long max_roll_passes = 0;  ///< the most passes one sphere took
};

/// Both throw InputError, located by the option's field name (e.g. "diameter"), for impossible options.
std::vector<Particle> drop_and_roll_spheres(const SphereBedOptions& opt, GeneratorReport* report = nullptr);
std::vector<Particle> rsa_spherocylinders(const SpherocylinderRsaOptions& opt, GeneratorReport* report = nullptr);

/// Distance between the segments [p0, p1] and [q0, q1] (Ericson, Real-Time Collision Detection, 5.1.9).
double segment_distance(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                        const Vec3& q1);

}  // namespace ssimarch
