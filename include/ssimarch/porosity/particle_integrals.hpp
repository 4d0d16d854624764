// Integrals of one particle that the profiles add up (docs/math/circle_spherocylinder.md):
//   lateral area  L_i(r)      = integral of p_i(z, r) dz over the height range   (radial profile)
//   shell volume  V_i(r0, r1) = integral of L_i(r) dr over [r0, r1]               (bins, bulk)
//   slice area    S_i(z)      = integral of p_i(z, r) dr over [0, R]              (axial profile)
// Each comes in two formulations: `chord` (Fubini-swapped, closed-form vertical chords and shadow
// arcs; fast) and `kernel` (the seed's p_i(z, r) integrated directly, breakpoints found from the
// kernel's crossing signature; the reference). Tests check that both agree.
#pragma once

#include "ssimarch/porosity/circle_spherocylinder.hpp"
#include "ssimarch/porosity/particle_shape.hpp"
#include "ssimarch/porosity/quadrature.hpp"

namespace ssimarch {

/// Which formulation integrates the kernel (see the file comment).
enum class ProfileMethod { kChord, kKernel };

/// Height range of the profiles: z in [z_min, z_max].
struct BedSlab {
  double z_min = 0.0, z_max = 0.0;
};

/// p_i(z, r): the seed kernel (closed form for spheres when `sphere_closed_form`).
double arc_length(const Particle& p, double z, double r, const KernelTolerances& tol = {},
                  bool sphere_closed_form = true);

/// Crossing signature of the kernel at (z, r): changes exactly where p_i stops being analytic.
long kernel_signature(const Particle& p, double z, double r, const KernelTolerances& tol = {});

/// L_i(r) to absolute tolerance abs_tol (units length^2).
QuadResult lateral_area(const ParticleShape& s, double r, const BedSlab& slab, double abs_tol,
                        ProfileMethod method = ProfileMethod::kChord, const KernelTolerances& tol = {});

/// V_i(r0, r1) to absolute tolerance abs_tol (units length^3).
QuadResult shell_volume(const ParticleShape& s, double r0, double r1, const BedSlab& slab, double abs_tol,
                        ProfileMethod method = ProfileMethod::kChord, const KernelTolerances& tol = {});

/// S_i(z) inside the disk of radius R to absolute tolerance abs_tol (units length^2). Spheres use the
/// closed-form disk-disk lens area. Spherocylinders inside the disk use the closed-form slice area
/// (ProfileMethod::kChord); those crossing the circle r = R, or all with ProfileMethod::kKernel, integrate the seed
/// kernel over r.
QuadResult slice_area(const ParticleShape& s, double z, double R, double abs_tol, const KernelTolerances& tol = {},
                      ProfileMethod method = ProfileMethod::kChord);

/// Area of the horizontal section of a particle at height z: an ellipse (section of the cylinder)
/// between the two chords lambda = -+l/2, plus the sections of the two cap spheres beyond them
/// (closed form through the area of a unit-disk band). Units length^2.
double slice_area_unclipped(const Particle& p, double z);

}  // namespace ssimarch
