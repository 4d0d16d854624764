// Packed beds shared by the porosity tests and benchmarks (ssimarch::testing): generated with the
// library's generators from fixed seeds, so every run sees the same particles.
// The benchmark beds of issue 5: 100,000 drop-and-roll spheres (d = 1, R = 10, D/d = 20) and 20,000
// RSA spherocylinders (d = 1, l = 2, R = 10, solid fraction 0.25), generated once per process.
#pragma once

#include <cstdint>
#include <vector>

#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch::testing {

/// Particles and the container they were generated in, z in [0, bed height].
struct PackedBed {
  std::vector<Particle> particles;
  Container container;
};

/// Drop-and-roll spheres of diameter 1 in a cylinder of radius R.
inline PackedBed drop_and_roll_bed(double R, long count, std::uint64_t seed) {
  SphereBedOptions o;
  o.container_radius = R;
  o.count = count;
  o.seed = seed;
  GeneratorReport r;
  PackedBed b;
  b.particles = drop_and_roll_spheres(o, &r);
  b.container = {R, {0.0, r.height}};
  return b;
}

/// RSA spherocylinders (diameter d, length l) in a cylinder of radius R filled to `solid_fraction`.
inline PackedBed rsa_bed(double R, double d, double l, long count, double solid_fraction, std::uint64_t seed) {
  SpherocylinderRsaOptions o;
  o.container_radius = R;
  o.diameter = d;
  o.length = l;
  o.count = count;
  o.target_solid_fraction = solid_fraction;
  o.seed = seed;
  GeneratorReport r;
  PackedBed b;
  b.particles = rsa_spherocylinders(o, &r);
  b.container = {R, {0.0, r.height}};
  return b;
}

inline const PackedBed& sphere_bed_100k() {
  static const PackedBed bed = drop_and_roll_bed(10, 100000, 1);
  return bed;
}

inline const PackedBed& rod_bed_20k() {
  static const PackedBed bed = rsa_bed(10, 1, 2, 20000, 0.25, 1);
  return bed;
}

}  // namespace ssimarch::testing
