// docs/math/closed_form_quadrics.md, "Coaxial surfaces of revolution": on a common axis both
// meridians are r^2 = g(h); their difference is a quadratic in h whose real roots are the circles.
#include "ssimarch/analytic/coaxial_section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nearest_root.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

double distance_from_axis(const Vec3& p, const RevolutionForm& f) {
  const Vec3 d = p - f.origin;
  return (d - d.dot(f.axis) * f.axis).norm();
}

// Puts a and b on one axis (a's, or the line of two spheres' centres); false when there is none.
bool common_axis(RevolutionForm* a, RevolutionForm* b, double scale) {
  if (a->any_axis && b->any_axis) {
    const Vec3 d = b->origin - a->origin;
    if (d.norm() <= kClosedFormDegeneracy * scale) return false;  // concentric spheres: equal (coincident) or disjoint
    a->axis = b->axis = d.normalized();
    return true;
  }
  if (a->any_axis) std::swap(a, b);  // b is the sphere (if any)
  if (b->any_axis) {
    b->axis = a->axis;
    return distance_from_axis(b->origin, *a) <= kClosedFormDegeneracy * scale;
  }
  return a->axis.cross(b->axis).norm() <= kClosedFormDegeneracy &&
         distance_from_axis(b->origin, *a) <= kClosedFormDegeneracy * scale;
}

// A meridian r^2 = g(h) = c0 + c1 h + c2 h^2 on the common axis (h in model units from a.origin).
struct Meridian {
  double c0 = 0, c1 = 0, c2 = 0;
  double at(double h) const { return c0 + (c1 + c2 * h) * h; }
  double slope(double h) const { return c1 + 2 * c2 * h; }
  // Signed axial distance from h to the nearest pole (r = 0: a sphere's pole, a cone's apex);
  // +infinity when there is none (a cylinder).
  double to_pole(double h) const { return internal::nearest_root(at(h), slope(h) / 2, c2); }
};

// A root of g_a - g_b: where (model units) and whether the meridians touch there (a double root).
struct AxialRoot {
  double h = 0;
  bool twice = false;
};

// The roots of g_a - g_b = q0 + q1 eta + q2 eta^2 (eta = h / scale, normalised coefficients; the
// shape tests are relative). Two simple roots merge into one double root (the surfaces touch along
// a circle) when at the extremum h* of g_a - g_b the distance of b's circle from a, |g_a - g_b| /
// |grad (r^2 - g_a)|, is within the gap tolerance.
std::vector<AxialRoot> axial_roots(double q0, double q1, double q2, double scale, const Meridian& a, const Meridian& b,
                                   double gap_tolerance) {
  if (std::fabs(q2) <= kClosedFormDegeneracy) {
    if (std::fabs(q1) <= kClosedFormDegeneracy) return {};
    return {{-q0 / q1 * scale, false}};
  }
  const double hstar = -q1 / (2 * q2) * scale, f = a.at(hstar) - b.at(hstar);
  const double grad = std::hypot(a.slope(hstar), 2 * std::sqrt(std::max(b.at(hstar), 0.0)));
  const double gap = grad > 0 ? std::fabs(f) / grad : (f == 0 ? 0.0 : std::numeric_limits<double>::infinity());
  const double disc = q1 * q1 - 4 * q2 * q0;
  // Within the gap tolerance the surfaces touch along one circle, unless they cross by more than
  // rounding in two circles farther apart than the tolerance (issue 26: the geometry decides, as
  // in plane sections).
  const double rounding = kClosedFormGapRounding * std::numeric_limits<double>::epsilon() * scale;
  const double separation = disc > 0 ? std::sqrt(disc) / std::fabs(q2) * scale : 0.0;
  if (gap <= gap_tolerance && !(disc > 0 && gap > rounding && separation > gap_tolerance)) return {{hstar, true}};
  if (disc < 0) return {};
  const double s = -0.5 * (q1 + std::copysign(std::sqrt(disc), q1));  // no cancellation
  return {{s / q2 * scale, false}, {q0 / s * scale, false}};
}

}  // namespace

std::optional<std::vector<Conic>> coaxial_section(RevolutionForm a, RevolutionForm b, double scale, double gap_tolerance) {
  if (!common_axis(&a, &b, scale)) return std::nullopt;
  // b's axial coordinate in terms of a's h: h_b = sigma (h - d).
  const double sigma = a.axis.dot(b.axis) > 0 ? 1.0 : -1.0, d = (b.origin - a.origin).dot(a.axis);
  const Meridian ma{a.c0, a.c1, a.c2}, mb{b.c0 - b.c1 * sigma * d + b.c2 * d * d, b.c1 * sigma - 2 * b.c2 * d, b.c2};
  // g_a(h) - g_b(h) = q0 + q1 h + q2 h^2, written in eta = h / scale and normalised.
  double q0 = ma.c0 - mb.c0, q1 = (ma.c1 - mb.c1) * scale, q2 = (ma.c2 - mb.c2) * scale * scale;
  const double m = std::max({std::fabs(q0), std::fabs(q1), std::fabs(q2)});
  if (m <= kClosedFormDegeneracy *
               std::max({std::fabs(a.c0), std::fabs(a.c1) * scale, std::fabs(a.c2) * scale * scale, 1e-300}))
    return std::nullopt;  // the same surface
  q0 /= m;
  q1 /= m;
  q2 /= m;
  std::vector<Conic> out;
  const Frame f = Frame::from_axis(a.origin, a.axis);
  for (const auto& [h, twice] : axial_roots(q0, q1, q2, scale, ma, mb, gap_tolerance)) {
    Conic c;
    c.e0 = f.e0;
    c.e1 = f.e1;
    c.contact = twice ? Contact::kTangential : Contact::kTransversal;
    // The surfaces meet at a pole of both (spheres touching, a sphere on a cone's apex) when the
    // poles nearest the root are within the gap tolerance of it and of each other.
    const double pa = ma.to_pole(h), pb = mb.to_pole(h);
    const double r2 = ma.at(h);
    const double to_poles = std::max({std::fabs(pa), std::fabs(pb), std::fabs(pa - pb)});
    const double rounding = kClosedFormGapRounding * std::numeric_limits<double>::epsilon() * scale;
    // A circle about the poles farther from them than the tolerance, the surfaces crossing by more
    // than rounding, is that circle (two spheres overlapping by 1e-12 meet in a circle of 1e-6).
    const bool resolved_circle = r2 > 0 && std::sqrt(r2) > gap_tolerance && to_poles > rounding;
    if (to_poles <= gap_tolerance && !resolved_circle) {
      c.type = ConicType::kPoint;
      c.center = a.origin + (h + 0.5 * (pa + pb)) * a.axis;
    } else if (r2 > 0) {
      c.type = ConicType::kCircle;
      c.center = a.origin + h * a.axis;
      c.a = c.b = std::sqrt(r2);
    } else {
      continue;
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace ssimarch
