// The covered chords of a group of balls in closed form (covered_chords.hpp). Source:
// docs/math/particle_union.md §2 ("Balls: the covered length as a sum of chord ends").
#include "covered_chords.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "interval_cover.hpp"
#include "meeting_circle.hpp"
#include "ssimarch/porosity/sphere_arc.hpp"

namespace ssimarch::internal {

namespace {

// A ball seen from the circle of radius r: its half chord over the angle theta is
// sqrt(A + B cos(theta - phi)), s = A + B and twoB = 2B as half_chord_integral takes them.
struct BallOnCircle {
  double cx = 0, cy = 0, cz = 0, a2 = 0, s = 0, twoB = 0, phi = 0;
};

// An end of a chord: the top (side +1) or bottom (side -1) of ball `ball`, or a plane of the slab
// (ball -1, side 0) at height z.
struct End {
  double z = 0;
  int ball = -1, side = 0;
};

struct Interval {
  End lo, hi;
};
// The chords of the balls on the vertical line over (x, y), clipped to the slab; the particle's
// (ball 0) in `own` (false when it has none there), the others' merged into disjoint intervals.
bool chords_at(const std::vector<BallOnCircle>& balls, double x, double y, const BedSlab& slab, Interval& own,
               std::vector<Interval>& others) {
  others.clear();
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const BallOnCircle& b = balls[k];
    const double q = b.a2 - (x - b.cx) * (x - b.cx) - (y - b.cy) * (y - b.cy);
    Interval c{{b.cz, static_cast<int>(k), -1}, {b.cz, static_cast<int>(k), 1}};
    if (q > 0) c.lo.z -= std::sqrt(q), c.hi.z += std::sqrt(q);
    if (c.lo.z < slab.z_min) c.lo = {slab.z_min, -1, 0};
    if (c.hi.z > slab.z_max) c.hi = {slab.z_max, -1, 0};
    if (!(q > 0) || !(c.hi.z > c.lo.z)) {
      if (k == 0) return false;
      continue;
    }
    (k == 0 ? own : others.emplace_back()) = c;
  }
  std::sort(others.begin(), others.end(), [](const Interval& a, const Interval& b) { return a.lo.z < b.lo.z; });
  std::size_t m = 0;
  for (const Interval& c : others) {
    if (m > 0 && c.lo.z <= others[m - 1].hi.z) {
      if (c.hi.z > others[m - 1].hi.z) others[m - 1].hi = c.hi;
    } else {
      others[m++] = c;
    }
  }
  others.resize(m);
  return true;
}

struct Scratch {
  std::vector<BallOnCircle> balls;
  std::vector<double> angles, br, phi, G;
  std::vector<Interval> others;
};

// Appends the two angles where the circle of radius r crosses the circle of squared radius
// `reach2` about the point at distance rho > 0 and angle phi from the axis (a ball's shadow's
// outline, or its section by a slab plane).
void crossing_angles(double phi, double r, double rho, double reach2, std::vector<double>& out) {
  if (!(rho > 0)) return;
  const double cs = (r * r + rho * rho - reach2) / (2 * r * rho);
  if (!(std::abs(cs) < 1)) return;
  const double al = std::acos(cs);
  out.push_back(phi - al), out.push_back(phi + al);
}

// The radii that the lens of two balls can reach: those of the ball centred on the circle where
// their spheres meet that holds both caps (docs/math/particle_union.md §1), or of the smaller
// ball where a centre lies beyond the circle's plane.
std::pair<double, double> lens_reach(const Particle& p, const Particle& q) {
  const Particle& small = p.radius() <= q.radius() ? p : q;
  const double rs = std::hypot(small.centre.x(), small.centre.y());
  std::pair<double, double> out{rs - small.radius(), rs + small.radius()};
  const Vec3 d = q.centre - p.centre;
  const double D = d.norm(), a = p.radius(), b = q.radius();
  if (!(D > std::abs(a - b)) || !(D < a + b)) return out;
  const double t = (D * D + a * a - b * b) / (2 * D);
  if (t < 0 || t > D) return out;
  const double rho2 = std::max(0.0, (a - t) * (a + t)), cap = std::max(a - t, b - (D - t));
  const double R = std::sqrt(rho2 + cap * cap);
  const Vec3 c = p.centre + (t / D) * d;
  const double rc = std::hypot(c.x(), c.y());
  return {std::max(out.first, rc - R), std::min(out.second, rc + R)};
}

// r times the integral of the covered length over the pieces between the breakpoints s.br, into
// out (value, rounding bound, evaluations).
void sum_pieces(double r, const BedSlab& slab, Scratch& scratch, QuadResult& out) {
  const std::vector<BallOnCircle>& balls = scratch.balls;
  const std::vector<double>& br = scratch.br;
  const std::size_t nb = balls.size(), np = br.size();
  // The angle from ball k's centre and G_k at each breakpoint, computed once for the two pieces it
  // bounds (NaN: not yet).
  scratch.phi.assign(nb * np, std::numeric_limits<double>::quiet_NaN());
  scratch.G.assign(nb * np, std::numeric_limits<double>::quiet_NaN());
  auto phi_at = [&](std::size_t k, std::size_t j) {
    double& v = scratch.phi[k * np + j];
    if (std::isnan(v)) v = std::remainder(br[j] - balls[k].phi, 2 * std::numbers::pi);
    return v;
  };
  auto G_at = [&](std::size_t k, std::size_t j) {
    double& v = scratch.G[k * np + j];
    if (std::isnan(v)) {
      v = half_chord_integral(balls[k].s, balls[k].twoB, phi_at(k, j));
      ++out.evaluations;
    }
    return v;
  };
  // Integral of ball k's half chord over piece j: a piece that passes the far side of the ball
  // (angle pi from its centre, where the remainder wraps; the whole circle passes it once) adds
  // G(pi) - G(-pi) = 2 G(pi) for each pass.
  auto half_chord = [&](std::size_t k, std::size_t j) {
    const double d = G_at(k, j + 1) - G_at(k, j);
    const double passes = std::round((br[j + 1] - br[j] - (phi_at(k, j + 1) - phi_at(k, j))) / (2 * std::numbers::pi));
    if (passes == 0) return d;
    return d + passes * 2 * half_chord_integral(balls[k].s, balls[k].twoB, std::numbers::pi);
  };
  Interval own;
  std::vector<Interval>& others = scratch.others;
  double total = 0, magnitude = 0;
  for (std::size_t j = 0; j + 1 < np; ++j) {
    const double w = br[j + 1] - br[j], mid = (br[j] + br[j + 1]) / 2;
    if (!(w > 0)) continue;
    ++out.evaluations;
    if (!chords_at(balls, r * std::cos(mid), r * std::sin(mid), slab, own, others)) continue;
    // Between breakpoints no end passes another and no chord appears or vanishes, so the ends that
    // bound the covered intervals at the midpoint bound them on the whole piece.
    double level = 0, heights = 0;  // the ends' heights without their half chords (ball centres, planes)
    for (const Interval& o : others) {
      const End& bottom = o.lo.z > own.lo.z ? o.lo : own.lo;
      const End& top = o.hi.z < own.hi.z ? o.hi : own.hi;
      if (!(top.z > bottom.z)) continue;
      for (const auto& [e, sign] : {std::pair{top, 1.0}, std::pair{bottom, -1.0}}) {
        const double z = e.ball < 0 ? e.z : balls[static_cast<std::size_t>(e.ball)].cz;
        level += sign * z;
        heights += std::abs(z);
        if (e.ball < 0) continue;
        const double S = half_chord(static_cast<std::size_t>(e.ball), j);
        total += sign * e.side * S;
        magnitude += std::abs(G_at(static_cast<std::size_t>(e.ball), j)) + std::abs(S);
      }
    }
    total += level * w;
    magnitude += heights * w;
  }
  // Rounding: a few ulps of every term (Carlson's duplication is accurate to a few ulps, Carlson
  // 1995, §2), the level's heights included.
  out.value = r * total;
  out.error = r * 64 * std::numeric_limits<double>::epsilon() * magnitude;
}

}  // namespace

CoveredBallChords::CoveredBallChords(const OverlapGroup& g, const BedSlab& slab) : slab_(slab) {
  for (std::size_t k = 0; k <= g.earlier.size(); ++k) {
    const Particle& p = k == 0 ? g.particle : g.earlier[k - 1];
    Ball b;
    b.cx = p.centre.x(), b.cy = p.centre.y(), b.cz = p.centre.z(), b.a = p.radius(), b.a2 = b.a * b.a;
    b.rho = std::hypot(b.cx, b.cy);
    b.phi = std::atan2(b.cy, b.cx);
    balls_.push_back(b);
  }
  meeting_circles(g, circles_);
  for (const MeetCircle& m : circles_) circle_radius2_.push_back(planar_radius2(m));
  cut_ = slab.z_min > g.box_lo.z() || slab.z_max < g.box_hi.z();
  std::tie(lo_, hi_) = angular_window(g.box_lo, g.box_hi);
  // The covered part is the union of the particle's lenses with the earlier balls.
  reach_lo_ = g.rho_max(), reach_hi_ = g.rho_min();
  for (const Particle& q : g.earlier) {
    const auto [l, h] = lens_reach(g.particle, q);
    reach_lo_ = std::min(reach_lo_, l), reach_hi_ = std::max(reach_hi_, h);
  }
  reach_lo_ = std::max(reach_lo_, g.rho_min()), reach_hi_ = std::min(reach_hi_, g.rho_max());
}

QuadResult CoveredBallChords::lateral_area(double r) const {
  QuadResult out;
  if (!(r >= reach_lo_ && r <= reach_hi_)) return out;
  // Per thread, reused: this runs once per overlap group and radius (hundreds of thousands of
  // times for a DEM bed), where allocations would cost as much as the integrals.
  thread_local Scratch scratch;
  std::vector<BallOnCircle>& balls = scratch.balls;
  balls.clear();
  scratch.angles.clear();
  for (const Ball& b : balls_) {
    balls.push_back({b.cx, b.cy, b.cz, b.a2, (b.a - r + b.rho) * (b.a + r - b.rho), 4 * r * b.rho, b.phi});
    // Breakpoints: the shadow's ends and, where a plane of the slab passes, the section's.
    crossing_angles(b.phi, r, b.rho, b.a2, scratch.angles);
    if (!cut_) continue;
    for (double zc : {slab_.z_min, slab_.z_max}) {
      const double dz = zc - b.cz;
      if (b.a2 > dz * dz) crossing_angles(b.phi, r, b.rho, b.a2 - dz * dz, scratch.angles);
    }
  }
  for (std::size_t k = 0; k < circles_.size(); ++k) meet_angles(circles_[k], circle_radius2_[k], r, scratch.angles);
  breakpoints_in(scratch.br, scratch.angles, lo_, hi_, true);
  sum_pieces(r, slab_, scratch, out);
  return out;
}

}  // namespace ssimarch::internal
