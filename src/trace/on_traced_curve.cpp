#include "ssimarch/trace/on_traced_curve.hpp"

#include <algorithm>
#include <cmath>

#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/trace/trace_tolerances.hpp"

namespace ssimarch {

namespace {

// The cubic Hermite arc with end points a, b and end derivatives c ta, c tb (c: the chord).
Vec3 hermite(const Vec3& a, const Vec3& da, const Vec3& b, const Vec3& db, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * a + (s3 - 2 * s2 + s) * da + (-2 * s3 + 3 * s2) * b + (s3 - s2) * db;
}

bool usable_tangent(const Vec3& t) { return t.allFinite() && std::fabs(t.norm() - 1) < 1e-6; }

// hermite_arc_distance with the segment's turning angle phi = angle(ta, tb) known.
double hermite_arc_distance(const Vec3& p, const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb, double phi) {
  // End derivatives of magnitude c / cos^2(phi / 4): the cubic through a circular arc's ends with
  // Goldapp's (4/3) tan(phi / 4) control distance, whose radial error is below
  // 3e-4 (phi / (pi/2))^6 of the radius, so any curve the tracer follows with steps that turn
  // little is matched to far below the sagitta.
  const double cq = std::cos(phi / 4);
  const double m = (b - a).norm() / (cq * cq);
  const Vec3 da = m * ta, db = m * tb;
  // Samples, then golden-section search on the bracket of the best one: the squared distance to a
  // cubic is a polynomial of degree 6, unimodal on so short a bracket for any arc the tracer
  // accepts (it turns by at most max_turn_angle).
  constexpr int kSamples = 32;
  int best = 0;
  double best_d = (p - a).norm();
  for (int k = 1; k <= kSamples; ++k) {
    const double d = (p - hermite(a, da, b, db, static_cast<double>(k) / kSamples)).norm();
    if (d < best_d) best_d = d, best = k;
  }
  double lo = std::max(0.0, (best - 1.0) / kSamples), hi = std::min(1.0, (best + 1.0) / kSamples);
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = (p - hermite(a, da, b, db, x1)).norm(), f2 = (p - hermite(a, da, b, db, x2)).norm();
  // The bracket shrinks by g each pass: 60 passes take it from 1/16 below 1e-13 of the arc.
  for (int pass = 0; pass < 60; ++pass) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = (p - hermite(a, da, b, db, x1)).norm();
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = (p - hermite(a, da, b, db, x2)).norm();
    }
  }
  return std::min({best_d, f1, f2});
}

}  // namespace

double chord_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 seg = b - a;
  const double L2 = seg.squaredNorm();
  const double t = L2 > 0 ? std::clamp((p - a).dot(seg) / L2, 0.0, 1.0) : 0.0;
  return (p - (a + t * seg)).norm();
}

double hermite_arc_distance(const Vec3& p, const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb) {
  return hermite_arc_distance(p, a, ta, b, tb, normal_angle(ta, tb));
}

bool on_traced_curve(const Vec3& p, const std::vector<TracedCurve>& curves, double radius, double tolerance) {
  for (const TracedCurve& c : curves)
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const CurvePoint &a = c.points[i], &b = c.points[i + 1];
      if (chord_distance(p, a.p, b.p) > radius) continue;
      if (!usable_tangent(a.t) || !usable_tangent(b.t)) return true;
      const double chord = (b.p - a.p).norm();
      const double turn = normal_angle(a.t, b.t);
      if (turn > kOnCurveMaxTurn) return true;
      const double sagitta = chord * turn / 8;
      if (hermite_arc_distance(p, a.p, a.t, b.p, b.t, turn) <= on_curve_distance(tolerance, sagitta)) return true;
    }
  return false;
}

}  // namespace ssimarch
