// docs/math/closed_form_quadrics.md, "Coaxial surfaces of revolution": on a common axis both
// meridians are r^2 = g(h); their difference is a quadratic in h whose real roots are the circles.
#include "ssimarch/analytic/coaxial_section.hpp"

#include <algorithm>
#include <cmath>

#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

constexpr double kEps = kClosedFormDegeneracy;

double distance_from_axis(const Vec3& p, const RevolutionForm& f) {
  const Vec3 d = p - f.origin;
  return (d - d.dot(f.axis) * f.axis).norm();
}

// Puts a and b on one axis (a's, or the line of two spheres' centres); false when there is none.
bool common_axis(RevolutionForm* a, RevolutionForm* b, double scale) {
  if (a->any_axis && b->any_axis) {
    const Vec3 d = b->origin - a->origin;
    if (d.norm() <= kEps * scale) return false;  // concentric spheres: equal (coincident) or disjoint
    a->axis = b->axis = d.normalized();
    return true;
  }
  if (a->any_axis) std::swap(a, b);  // b is the sphere (if any)
  if (b->any_axis) {
    b->axis = a->axis;
    return distance_from_axis(b->origin, *a) <= kEps * scale;
  }
  return a->axis.cross(b->axis).norm() <= kEps && distance_from_axis(b->origin, *a) <= kEps * scale;
}

// Real roots of q0 + q1 x + q2 x^2 (normalised coefficients), with whether each is double.
std::vector<std::pair<double, bool>> quadratic_roots(double q0, double q1, double q2) {
  if (std::fabs(q2) <= kEps) {
    if (std::fabs(q1) <= kEps) return {};
    return {{-q0 / q1, false}};
  }
  const double disc = q1 * q1 - 4 * q2 * q0;
  if (std::fabs(disc) <= kEps) return {{-q1 / (2 * q2), true}};
  if (disc < 0) return {};
  const double s = -0.5 * (q1 + std::copysign(std::sqrt(disc), q1));  // no cancellation
  return {{s / q2, false}, {q0 / s, false}};
}

}  // namespace

std::optional<std::vector<Conic>> coaxial_section(RevolutionForm a, RevolutionForm b, double scale) {
  if (!common_axis(&a, &b, scale)) return std::nullopt;
  // b's axial coordinate in terms of a's h: h_b = sigma (h - d).
  const double sigma = a.axis.dot(b.axis) > 0 ? 1.0 : -1.0, d = (b.origin - a.origin).dot(a.axis);
  // g_a(h) - g_b(h) = q0 + q1 h + q2 h^2, written in eta = h / scale and normalised.
  double q0 = a.c0 - (b.c0 - b.c1 * sigma * d + b.c2 * d * d);
  double q1 = (a.c1 - (b.c1 * sigma - 2 * b.c2 * d)) * scale;
  double q2 = (a.c2 - b.c2) * scale * scale;
  const double m = std::max({std::fabs(q0), std::fabs(q1), std::fabs(q2)});
  if (m <= kEps * std::max({std::fabs(a.c0), std::fabs(a.c1) * scale, std::fabs(a.c2) * scale * scale, 1e-300}))
    return std::nullopt;  // the same surface
  q0 /= m;
  q1 /= m;
  q2 /= m;
  std::vector<Conic> out;
  const Frame f = Frame::from_axis(a.origin, a.axis);
  for (const auto& [eta, twice] : quadratic_roots(q0, q1, q2)) {
    const double h = eta * scale, r2 = a.c0 + a.c1 * h + a.c2 * h * h;
    Conic c;
    c.center = a.origin + h * a.axis;
    c.e0 = f.e0;
    c.e1 = f.e1;
    c.contact = twice ? Contact::kTangential : Contact::kTransversal;
    if (std::fabs(r2) <= kEps * scale * scale) {
      c.type = ConicType::kPoint;
    } else if (r2 > 0) {
      c.type = ConicType::kCircle;
      c.a = c.b = std::sqrt(r2);
    } else {
      continue;
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace ssimarch
