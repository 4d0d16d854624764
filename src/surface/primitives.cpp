// Constructors of the primitives: validation, frames, domains and boxes (formulas in the headers).
#include "ssimarch/surface/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "ssimarch/core/error.hpp"

namespace ssimarch {
namespace {

std::string num(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

void require_positive(double x, const char* what, const char* name) {
  if (!std::isfinite(x) || !(x > 0)) throw InputError(what, std::string(name) + " must be a finite number > 0, got " + num(x));
}

void require_interval(const Interval& i, const char* what, const char* name) {
  if (!std::isfinite(i.lo) || !std::isfinite(i.hi) || !(i.lo < i.hi))
    throw InputError(what, std::string(name) + " must be an interval [lo, hi] of finite numbers with lo < hi, got [" +
                               num(i.lo) + ", " + num(i.hi) + "]");
}

// Box of a circle of radius r about c in the plane normal to the unit vector a: half-extent
// along coordinate i is r * sqrt(1 - a_i^2).
Box circle_box(const Vec3& c, const Vec3& a, double r) {
  Vec3 h;
  for (int i = 0; i < 3; ++i) h[i] = r * std::sqrt(std::max(0.0, 1.0 - a[i] * a[i]));
  return box_from_center(c, h);
}

Box primitive_box(const Box& b) { return inflate(b, kPrimitiveBoxMargin); }

}  // namespace

Sphere::Sphere(const Vec3& center, double radius, const Vec3& axis, const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(center, axis, reference, "sphere")), r_(radius) {
  require_positive(radius, "sphere", "radius");
  domain_ = {{0, 2 * std::numbers::pi}, {-std::numbers::pi / 2, std::numbers::pi / 2}, true, false};
  box_ = primitive_box(box_from_center(center, Vec3::Constant(radius)));
}

Cylinder::Cylinder(const Vec3& point, const Vec3& axis, double radius, Interval range,
                   const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(point, axis, reference, "cylinder")), r_(radius) {
  require_positive(radius, "cylinder", "radius");
  require_interval(range, "cylinder", "range");
  domain_ = {{0, 2 * std::numbers::pi}, range, true, false};
  box_ = primitive_box(box_union(circle_box(frame_.to_world(0, 0, range.lo), frame_.e2, radius),
                                 circle_box(frame_.to_world(0, 0, range.hi), frame_.e2, radius)));
}

Cone::Cone(const Vec3& apex, const Vec3& axis, double half_angle, Interval range, const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(apex, axis, reference, "cone")), alpha_(half_angle) {
  if (!std::isfinite(half_angle) || !(half_angle > 0) || !(half_angle < std::numbers::pi / 2))
    throw InputError("cone", "half_angle must be in (0, pi/2) radians, got " + num(half_angle));
  require_interval(range, "cone", "range");
  tan_ = std::tan(alpha_);
  const double s = std::sin(alpha_), c = std::cos(alpha_);
  cos2_ = c * c;
  sin2_ = s * s;
  const double L = std::max(std::fabs(range.lo), std::fabs(range.hi));
  scale_ = 1.0 / (2 * L * s);
  domain_ = {{0, 2 * std::numbers::pi}, range, true, false};
  box_ = primitive_box(box_union(circle_box(frame_.to_world(0, 0, range.lo), frame_.e2, std::fabs(range.lo) * tan_),
                                 circle_box(frame_.to_world(0, 0, range.hi), frame_.e2, std::fabs(range.hi) * tan_)));
}

Torus::Torus(const Vec3& center, const Vec3& axis, double major_radius, double minor_radius,
             const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(center, axis, reference, "torus")), R_(major_radius), r_(minor_radius) {
  require_positive(major_radius, "torus", "major_radius");
  require_positive(minor_radius, "torus", "minor_radius");
  domain_ = {{0, 2 * std::numbers::pi}, {0, 2 * std::numbers::pi}, true, true};
  Box b = circle_box(center, frame_.e2, R_);
  box_ = primitive_box(inflate(b, 0.0, r_));
}

Ellipsoid::Ellipsoid(const Vec3& center, const std::array<double, 3>& radii, const Vec3& axis,
                     const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(center, axis, reference, "ellipsoid")), r_(radii) {
  for (double r : radii) require_positive(r, "ellipsoid", "every radius");
  for (int k = 0; k < 3; ++k) inv2_[static_cast<std::size_t>(k)] = 1.0 / (radii[static_cast<std::size_t>(k)] * radii[static_cast<std::size_t>(k)]);
  half_min_ = 0.5 * std::min({radii[0], radii[1], radii[2]});
  domain_ = {{0, 2 * std::numbers::pi}, {-std::numbers::pi / 2, std::numbers::pi / 2}, true, false};
  const Vec3* e[3] = {&frame_.e0, &frame_.e1, &frame_.e2};
  Vec3 h;
  for (int i = 0; i < 3; ++i) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += std::pow(radii[static_cast<std::size_t>(k)] * (*e[k])[i], 2);
    h[i] = std::sqrt(s);
  }
  box_ = primitive_box(box_from_center(center, h));
}

Paraboloid::Paraboloid(const Vec3& vertex, const Vec3& axis, double focal_u, double focal_v,
                       const ParamDomain& rectangle, const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(vertex, axis, reference, "paraboloid")), fu_(focal_u), fv_(focal_v) {
  require_positive(focal_u, "paraboloid", "focal length");
  require_positive(focal_v, "paraboloid", "focal length");
  require_interval(rectangle.u, "paraboloid", "u");
  require_interval(rectangle.v, "paraboloid", "v");
  ku_ = 1.0 / (4 * fu_);
  kv_ = 1.0 / (4 * fv_);
  domain_ = {rectangle.u, rectangle.v, false, false, rectangle.unbounded_u, rectangle.unbounded_v};
  // World coordinate i = o_i + (t e0_i + k_u t^2 e2_i)|_{t=u} + (t e1_i + k_v t^2 e2_i)|_{t=v}:
  // a sum of two one-variable quadratics, each extreme at an end or at its stationary point.
  auto range = [](double lin, double quad, const Interval& t) {
    auto g = [&](double x) { return lin * x + quad * x * x; };
    double lo = std::min(g(t.lo), g(t.hi)), hi = std::max(g(t.lo), g(t.hi));
    if (quad != 0) {
      double x = -lin / (2 * quad);
      if (t.contains(x)) lo = std::min(lo, g(x)), hi = std::max(hi, g(x));
    }
    return Interval{lo, hi};
  };
  Interval b[3];
  for (int i = 0; i < 3; ++i) {
    Interval a = range(frame_.e0[i], ku_ * frame_.e2[i], rectangle.u);
    Interval c = range(frame_.e1[i], kv_ * frame_.e2[i], rectangle.v);
    b[i] = {vertex[i] + a.lo + c.lo, vertex[i] + a.hi + c.hi};
  }
  box_ = primitive_box({b[0], b[1], b[2]});
}

Plane::Plane(const Vec3& point, const Vec3& normal, const ParamDomain& rectangle, const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(point, normal, reference, "plane")) {
  require_interval(rectangle.u, "plane", "u");
  require_interval(rectangle.v, "plane", "v");
  domain_ = {rectangle.u, rectangle.v, false, false, rectangle.unbounded_u, rectangle.unbounded_v};
  Vec3 p = frame_.to_world(rectangle.u.lo, rectangle.v.lo, 0.0);
  Box b{{p.x(), p.x()}, {p.y(), p.y()}, {p.z(), p.z()}};
  for (double u : {rectangle.u.lo, rectangle.u.hi})
    for (double v : {rectangle.v.lo, rectangle.v.hi}) {
      Vec3 q = frame_.to_world(u, v, 0.0);
      b = box_union(b, {{q.x(), q.x()}, {q.y(), q.y()}, {q.z(), q.z()}});
    }
  box_ = primitive_box(b);
}

Capsule::Capsule(const Vec3& center, const Vec3& axis, double radius, double length,
                 const std::optional<Vec3>& reference)
    : frame_(Frame::from_axis(center, axis, reference, "capsule")), r_(radius), half_(0.5 * length) {
  require_positive(radius, "capsule", "radius");
  if (!std::isfinite(length) || length < 0)
    throw InputError("capsule", "length must be a finite number >= 0, got " + num(length));
  const double end = half_ + 0.5 * std::numbers::pi * r_;
  domain_ = {{0, 2 * std::numbers::pi}, {-end, end}, true, false};
  box_ = primitive_box(box_union(box_from_center(frame_.to_world(0, 0, -half_), Vec3::Constant(r_)),
                                 box_from_center(frame_.to_world(0, 0, half_), Vec3::Constant(r_))));
}

}  // namespace ssimarch
