// The circle where the surfaces of two balls meet, and the angles at which a cylinder about the z
// axis crosses it (internal to porosity: the union of particles). There two chord ends of the
// balls coincide, a kink of the covered length. Source: docs/math/particle_union.md §2.
#pragma once

#include <array>
#include <vector>

#include "ssimarch/porosity/particle_union.hpp"

namespace ssimarch::internal {

/// A root of a trigonometric polynomial, as the cosine and sine of its angle psi.
struct TrigRoot {
  double c = 1, s = 0;
};

/// Real roots psi of c0 + c1 cos psi + s1 sin psi + c2 cos 2psi + s2 sin 2psi (a near-double root
/// twice, as real_roots reports tangencies). Returns their count.
int trig2_roots(double c0, double c1, double s1, double c2, double s2, std::array<TrigRoot, 4>& out);

/// The circle where the surfaces of two balls meet: centre c, radius rho, orthonormal e1, e2 in its
/// plane.
struct MeetCircle {
  Vec3 c, e1, e2;
  double rho = 0;
};

/// The meeting circle of two balls; false when their surfaces do not meet in a circle.
bool meet_circle(const Particle& p, const Particle& q, MeetCircle& m);

/// |xy of the point at psi|^2 = f0 + c1 cos psi + s1 sin psi + c2 cos 2psi + s2 sin 2psi, as
/// {f0, c1, s1, c2, s2}.
std::array<double, 5> planar_radius2(const MeetCircle& m);

/// The point of the circle at the root psi.
inline Vec3 meet_point(const MeetCircle& m, const TrigRoot& psi) { return m.c + m.rho * (psi.c * m.e1 + psi.s * m.e2); }

/// Appends the angles theta at which the vertical line over the circle of radius r passes through m
/// (`radius2` its planar_radius2).
void meet_angles(const MeetCircle& m, const std::array<double, 5>& radius2, double r, std::vector<double>& out);
inline void meet_angles(const MeetCircle& m, double r, std::vector<double>& out) {
  meet_angles(m, planar_radius2(m), r, out);
}

/// Appends the meeting circles of every pair of balls of the group (spherocylinders have none).
void meeting_circles(const OverlapGroup& g, std::vector<MeetCircle>& out);

}  // namespace ssimarch::internal
