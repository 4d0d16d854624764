// Direct closed form for spheres (a spherocylinder of length 0): the plane z cuts the sphere
// (centre c, radius a) in a disk of radius s = sqrt(a^2 - (z - c_z)^2) centred at horizontal
// distance rho = |c_xy| from the axis; the circle of radius r meets that disk in the arc of
// half-angle alpha with cos alpha = (r^2 + rho^2 - s^2) / (2 r rho) (law of cosines).
// Source: seed 001 (thesis Appendix A §A.3: the cap sphere of A.30-A.44 with l = 0).
#pragma once

#include "ssimarch/porosity/particle.hpp"

namespace ssimarch {

/// Length of the circle (radius r > 0, height z, centred on the z axis) inside the closed ball of
/// the given centre and diameter. Model length.
double circle_sphere_arc(const Vec3& centre, double diameter, double z, double r);

/// Area of the part of the cylinder surface x^2 + y^2 = r^2 (unbounded in z) inside the closed ball
/// of radius a whose centre lies at horizontal distance rho >= 0 from the axis: the lateral area
/// L(r) of the radial profile for a sphere the height range does not cut. Closed form through
/// Carlson's symmetric elliptic integrals R_G and R_D (docs/math/cylinder_in_sphere.md); exact to a
/// few ulps relative to L. Model length^2.
double cylinder_area_in_sphere(double rho, double a, double r);

/// The same area between two horizontal planes, at heights `below` under and `above` over the
/// ball's centre (negative when the centre lies outside the slab): the lateral area of a sphere
/// the height range cuts. Closed form through Carlson's R_F and R_D at the angles where the
/// chord reaches a plane (docs/math/cylinder_in_sphere.md §4). Model length^2.
double cylinder_area_in_sphere_slab(double rho, double a, double r, double below, double above);

/// G(phi) = integral over [0, phi] of h(t) = sqrt(A + B cos t), |phi| <= pi: the primitive of the
/// half chord of a ball (radius a, centre at horizontal distance rho from the axis) over the angle t
/// of the circle of radius r measured from the centre's direction, with s = A + B =
/// a^2 - (r - rho)^2 > 0 and twoB = 2B = 4 r rho >= 0 as in cylinder_area_in_sphere; phi must lie
/// in the ball's shadow (A + B cos phi >= 0, rounding tolerated). Odd in phi. Closed form through
/// Carlson's R_F and R_D (docs/math/cylinder_in_sphere.md §4, eq. 9). Model length (angle x length).
double half_chord_integral(double s, double twoB, double phi);

/// Area of the intersection of two disks (radii r1, r2, centre distance d), the "lens" area.
double disk_disk_area(double r1, double r2, double d);

}  // namespace ssimarch
