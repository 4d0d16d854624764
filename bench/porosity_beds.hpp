// Benchmark packings of issue 5: 100,000 drop-and-roll spheres (d = 1, R = 10, D/d = 20) and 20,000
// RSA spherocylinders (d = 1, l = 2, R = 10, solid fraction 0.25). Generated once per process.
#pragma once

#include "ssimarch/porosity/generator.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch::porosity::bench {

struct Bed {
  std::vector<Particle> particles;
  Container container;
};

inline const Bed& sphere_bed_100k() {
  static const Bed bed = [] {
    SphereBedOptions o;
    o.container_radius = 10;
    o.count = 100000;
    o.seed = 1;
    GeneratorReport r;
    Bed b;
    b.particles = drop_and_roll_spheres(o, &r);
    b.container = {10.0, {0.0, r.height}};
    return b;
  }();
  return bed;
}

inline const Bed& rod_bed_20k() {
  static const Bed bed = [] {
    SpherocylinderRsaOptions o;
    o.container_radius = 10;
    o.diameter = 1;
    o.length = 2;
    o.count = 20000;
    o.target_solid_fraction = 0.25;
    o.seed = 1;
    GeneratorReport r;
    Bed b;
    b.particles = rsa_spherocylinders(o, &r);
    b.container = {10.0, {0.0, r.height}};
    return b;
  }();
  return bed;
}

}  // namespace ssimarch::porosity::bench
