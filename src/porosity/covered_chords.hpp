// The covered chords of a group of balls integrated over the angle in closed form (internal to
// porosity: the union of particles, particle_union.hpp). Source: docs/math/particle_union.md §2.
#pragma once

#include <array>
#include <vector>

#include "meeting_circle.hpp"
#include "ssimarch/porosity/particle_union.hpp"

namespace ssimarch::internal {

/// An overlap group of balls prepared for the area of its covered part P_i n U_i on the cylinders
/// about the z axis between the slab's planes: r times the integral over the angle of the length
/// of the particle's vertical chord inside the union of the earlier balls' chords. The covered
/// length is analytic between the angles where a chord appears or vanishes (shadow ends, slab
/// cuts) or two ends meet (lines through the circles where two spheres meet), all closed forms;
/// on each piece it is a signed sum of chord ends, each integrated in closed form
/// (half_chord_integral), so the area is exact up to rounding. What does not depend on the radius
/// (the balls' directions, the meeting circles, the radii the covered part can reach) is computed
/// once here, for the many radii of a profile.
class CoveredBallChords {
 public:
  /// `g` must hold balls only (OverlapGroup::spheres()).
  CoveredBallChords(const OverlapGroup& g, const BedSlab& slab);

  /// The area on the cylinder of radius r > 0; `error` bounds its rounding. Model length^2.
  QuadResult lateral_area(double r) const;

 private:
  struct Ball {
    double cx = 0, cy = 0, cz = 0, a2 = 0, a = 0, rho = 0, phi = 0;
  };
  std::vector<Ball> balls_;  // the particle first, then the earlier balls
  std::vector<MeetCircle> circles_;
  std::vector<std::array<double, 5>> circle_radius2_;  // planar_radius2 of each circle
  BedSlab slab_;
  bool cut_ = false;                    // a slab plane passes through the group's box
  double lo_ = 0, hi_ = 0;              // the angular window holding the group's box
  double reach_lo_ = 0, reach_hi_ = 0;  // the radii the covered part can reach
};

}  // namespace ssimarch::internal
