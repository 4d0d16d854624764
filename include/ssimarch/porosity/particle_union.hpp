// The union of overlapping particles, counted once (docs/porosity.md, "Overlapping particles";
// derivation in docs/math/particle_union.md).
//
// A profile value is a measure mu (an area on a cylinder, a volume of a shell, an area of a disk, a
// length of a circle) of the solid, the union of the particles P_1 ... P_n. Ownership by index
// writes it as a sum over particles without inclusion-exclusion:
//
//   mu(P_1 u ... u P_n) = sum_i mu(P_i) - sum_i mu(P_i n U_i),   U_i = union of the P_j, j < i,
//                                                                        that overlap P_i
//
// (each point of the union is counted by the first particle holding it). The first sum is what
// the per-particle closed forms compute; the second is the covered part of each particle that
// overlaps an earlier one, and is zero for all others. P_i n U_i splits into components whose
// bounding boxes do not meet (the lenses of a DEM particle with its neighbours lie apart), each an
// `OverlapGroup`, and mu adds over them.
//
// On a circle (r, z) each particle holds angular arcs, and on a vertical line a chord; the covered
// part is the length of P_i's arcs (chords) inside the merged arcs (chords) of the group's earlier
// particles. Between breakpoints where no two ends of those intervals meet, the covered length is
// analytic: for spheres the breakpoints are closed forms (a circle or line tangent to a ball, or
// through the circle where two spheres' surfaces meet), and on a cylinder each piece is a signed
// sum of chord ends integrated in closed form, so radial values are exact up to rounding and the
// other integrals up to quadrature, like the disjoint ones; for spherocylinders the ends' order is
// sampled (256 samples per piece) and every change located by bisection (integrate_piecewise),
// which misses only features narrower than a sample.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "ssimarch/porosity/overlaps.hpp"
#include "ssimarch/porosity/particle_integrals.hpp"
#include "ssimarch/porosity/profile_communicator.hpp"

namespace ssimarch {

/// How a profile counts a volume that several particles share.
enum class OverlapRule {
  kUnion,  ///< the union of the particles: every point of solid once (default)
  kSum,    ///< each particle on its own: shared volume counted once per particle holding it
};

/// "union" or "sum", as the CLI's --overlaps and Python's `overlaps=` spell them.
const char* to_string(OverlapRule rule);
/// The rule named `name`; InputError located by `key` for any other name.
OverlapRule overlap_rule_named(std::string_view name, const char* key = "overlaps");

/// A particle and the earlier particles (lower index in the packing) whose overlaps with it form
/// one component; `box_lo`, `box_hi` bound the covered part P_i n (P_j1 u P_j2 u ...).
struct OverlapGroup {
  Particle particle;
  std::vector<Particle> earlier;
  Vec3 box_lo, box_hi;
  /// Smallest and largest distance of the box from the z axis (bounds of the covered part's radii).
  double rho_min() const;
  double rho_max() const;
  /// True when every particle of the group is a sphere: the breakpoints are closed forms.
  bool spheres() const;
};

/// The overlap groups of a packing held by one process. Pairs overlap when their depth exceeds
/// `relative_tolerance` times the smaller diameter (the same rule as find_overlaps).
std::vector<OverlapGroup> overlap_groups(std::span<const Particle> particles,
                                         double relative_tolerance = kOverlapRelativeTolerance, unsigned threads = 0);

/// The same over a packing split among processes (`share` holds particles first, first + 1, ...):
/// each process returns the groups of the particles of its slab of the bed (overlaps.hpp), so
/// every group is held by exactly one process and the profiles' sums over processes are those of
/// one process. Collective.
std::vector<OverlapGroup> overlap_groups(std::span<const Particle> share, long first, const ProfileCommunicator& comm,
                                         double relative_tolerance = kOverlapRelativeTolerance, unsigned threads = 0);

/// Length of the circle (radius r > 0, height z) inside P_i n U_i. Model length.
double covered_arc_length(const OverlapGroup& g, double z, double r);

/// Area of the cylinder surface of radius r between the slab's planes inside P_i n U_i, to
/// absolute tolerance abs_tol (groups of balls: in closed form, exact up to rounding whatever
/// abs_tol). Model length^2.
QuadResult covered_lateral_area(const OverlapGroup& g, double r, const BedSlab& slab, double abs_tol);

/// Volume of P_i n U_i between the cylinders r0 <= r1 and the slab's planes. Model length^3.
QuadResult covered_shell_volume(const OverlapGroup& g, double r0, double r1, const BedSlab& slab, double abs_tol);

/// Area of the section of P_i n U_i by the plane z inside the disk of radius R. Model length^2.
QuadResult covered_slice_area(const OverlapGroup& g, double z, double R, double abs_tol);

}  // namespace ssimarch
