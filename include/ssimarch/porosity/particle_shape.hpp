// Closed-form line and shadow geometry of one spherocylinder, used by the chord formulation of the
// radial profile (docs/math/circle_spherocylinder.md, "Chord formulation"):
//
//   integral over z of p_i(z, r) dz  =  r * integral over theta of chord_i(r cos theta, r sin theta) dtheta
//
// (Fubini on the cylinder surface x^2 + y^2 = r^2), where chord_i(x, y) is the length of the vertical
// line through (x, y) inside the particle. The particle is the union of the two cap balls and the
// finite cylinder, so the line meets it in the hull of three closed-form intervals (quadratics). The
// line meets the particle iff (x, y) lies in its shadow, the 2D stadium {dist((x,y), P-P+) <= sigma/2}
// (projection of a Minkowski sum = Minkowski sum of projections), whose crossings with the circle of
// radius r are closed-form circle-circle and circle-line intersections. At those crossings chord_i
// vanishes like a square root, which integrate_sqrt_ends absorbs.
#pragma once

#include <array>
#include <vector>

#include "ssimarch/porosity/particle.hpp"

namespace ssimarch {

/// The vertical chord [lo, hi] of a particle along a line x, y = const (empty when hi < lo).
struct Chord {
  double lo = 0.0, hi = -1.0;
  bool empty() const { return !(hi >= lo); }
  double length() const { return empty() ? 0.0 : hi - lo; }
};

/// An arc of the circle of radius r: theta in [begin, end], end - begin in (0, 2 pi].
struct Arc {
  double begin = 0.0, end = 0.0;
};

class ParticleShape {
 public:
  explicit ParticleShape(const Particle& p);

  const Particle& particle() const { return p_; }
  /// Vertical chord: the z interval of the line through (x, y) inside the closed particle.
  Chord vertical_chord(double x, double y) const;
  /// Whether (x, y) is in the particle's shadow on the xy plane.
  bool shadow_contains(double x, double y) const;
  /// Arcs of the circle of radius r (centred on the z axis) inside the shadow; `full` when the whole
  /// circle is inside (then no arcs are returned).
  int shadow_arcs(double r, std::array<Arc, 4>& arcs, bool& full) const;
  /// Angles theta at which the circle of radius r passes under a cylinder-cap junction circle (the
  /// projections of the two junction circles are ellipses; circle-ellipse = a quartic in
  /// tan(psi/2)): there the chord's end switches between cylinder and cap, a curvature jump that the
  /// quadrature should not straddle. Returns the count (<= 8), angles in (-pi, pi].
  int junction_angles(double r, std::array<double, 8>& out) const;
  /// Angles at which the circle of radius r passes under the rim of a cap sphere's section by the
  /// plane z = z_cut (circle-circle intersections): where the chord clipped at z_cut has a kink.
  int clip_angles(double r, double z_cut, std::array<double, 8>& out, int n) const;
  /// Radii at which the circle is tangent to those sections (breakpoints in r of clipped integrals).
  void clip_radii(double z_cut, std::vector<double>& out) const;
  /// Radii at which the circle's crossings with the shadow outline change (tangencies to the outline,
  /// outline corners): the breakpoints of the lateral area as a function of r. Sorted.
  std::vector<double> critical_radii() const;

  double rho_min() const { return rho_min_; }  ///< smallest distance of the particle from the z axis
  double rho_max() const { return rho_max_; }  ///< largest distance of the particle from the z axis
  double z_min() const { return z_min_; }
  double z_max() const { return z_max_; }

 private:
  Particle p_;
  double a_, a2_, h_;
  Vec3 cp_, cm_;
  double alpha_;            // 1 - u_z^2 = u_x^2 + u_y^2
  bool has_lines_ = false;  // shadow has straight edges (projected axis not degenerate)
  double ex_ = 0, ey_ = 0, plen_ = 0;
  double rho_min_, rho_max_, z_min_, z_max_;
};

}  // namespace ssimarch
