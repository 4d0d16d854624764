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

#include <cstdint>
#include <memory>
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

/// The overlap groups of a packing in the compact form the profiles hold them in: each group names
/// its particle and earlier particles by index, with its box (about 70 bytes a lens, where a list
/// of OverlapGroup copies every member: a DEM bed has three lenses per particle). The set refers to
/// the particles it was found among, which must outlive it, or holds them itself (a process's
/// slab of the bed under MPI). Movable, not copyable (shared through std::shared_ptr).
class OverlapGroupSet {
 public:
  /// A group: its box and its members, particles_[members[first]] the particle, then the earlier.
  struct Entry {
    Vec3 box_lo, box_hi;
    std::uint32_t first = 0, count = 0;
  };

  OverlapGroupSet() = default;
  /// `particles` are those the members index; `held`, when not empty, is where they live.
  OverlapGroupSet(std::span<const Particle> particles, std::vector<Particle> held, std::vector<Entry> entries,
                  std::vector<std::uint32_t> members);
  OverlapGroupSet(OverlapGroupSet&&) = default;
  OverlapGroupSet& operator=(OverlapGroupSet&&) = default;
  OverlapGroupSet(const OverlapGroupSet&) = delete;
  OverlapGroupSet& operator=(const OverlapGroupSet&) = delete;

  std::size_t size() const { return entries_.size(); }
  bool empty() const { return entries_.empty(); }
  /// Group k, written into g (its storage reused: no allocation once g has grown).
  void get(std::size_t k, OverlapGroup& g) const;
  /// Group k's box and members' place.
  const Entry& entry(std::size_t k) const { return entries_[k]; }
  /// Every group, each with copies of its members.
  std::vector<OverlapGroup> all() const;

 private:
  std::vector<Particle> held_;
  std::span<const Particle> particles_;
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> members_;
};

/// The overlap groups of a packing held by one process. Pairs overlap when their depth exceeds
/// `relative_tolerance` times the smaller diameter (the same rule as find_overlaps). `particles`
/// must outlive the set.
std::shared_ptr<const OverlapGroupSet> overlap_group_set(std::span<const Particle> particles,
                                                         double relative_tolerance = kOverlapRelativeTolerance,
                                                         unsigned threads = 0);

/// The same over a packing split among processes (`share` holds particles first, first + 1, ...):
/// each process finds the groups of the particles of its slab of the bed (overlaps.hpp), so every
/// group is held by exactly one process and the profiles' sums over processes are those of one
/// process; the set holds the slab's particles. Collective.
std::shared_ptr<const OverlapGroupSet> overlap_group_set(std::span<const Particle> share, long first,
                                                         const ProfileCommunicator& comm,
                                                         double relative_tolerance = kOverlapRelativeTolerance,
                                                         unsigned threads = 0);

/// The groups of overlap_group_set, each with copies of its members.
std::vector<OverlapGroup> overlap_groups(std::span<const Particle> particles,
                                         double relative_tolerance = kOverlapRelativeTolerance, unsigned threads = 0);
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
