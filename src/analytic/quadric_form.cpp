// Local forms and their placement: docs/math/closed_form_quadrics.md, "The quadric of a primitive".
#include "ssimarch/analytic/quadric_form.hpp"

#include <cmath>

namespace ssimarch {

namespace {

// World-to-local map of a frame in homogeneous coordinates: local = R^T (p - o).
Eigen::Matrix4d world_to_local(const Frame& f) {
  Eigen::Matrix3d rt;
  rt.row(0) = f.e0.transpose();
  rt.row(1) = f.e1.transpose();
  rt.row(2) = f.e2.transpose();
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() = rt;
  t.topRightCorner<3, 1>() = -rt * f.origin;
  return t;
}

Eigen::Matrix4d placed(const Frame& f, const Eigen::Matrix4d& local) {
  const Eigen::Matrix4d t = world_to_local(f);
  return t.transpose() * local * t;
}

Eigen::Matrix4d diagonal(double a, double b, double c, double d) { return Eigen::Vector4d(a, b, c, d).asDiagonal(); }

}  // namespace

std::optional<Eigen::Matrix4d> quadric_matrix(const Surface& surface) {
  if (const auto* s = surface.get_if<Sphere>()) {
    const double r = s->radius();
    return placed(s->frame(), diagonal(1, 1, 1, -r * r));
  }
  if (const auto* c = surface.get_if<Cylinder>()) {
    const double r = c->radius();
    return placed(c->frame(), diagonal(1, 1, 0, -r * r));
  }
  if (const auto* k = surface.get_if<Cone>()) {
    const double t = std::tan(k->half_angle());
    return placed(k->frame(), diagonal(1, 1, -t * t, 0));
  }
  if (const auto* e = surface.get_if<Ellipsoid>()) {
    const auto& r = e->radii();
    return placed(e->frame(), diagonal(1 / (r[0] * r[0]), 1 / (r[1] * r[1]), 1 / (r[2] * r[2]), -1));
  }
  if (const auto* p = surface.get_if<Paraboloid>()) {
    // z = x^2 / (4 fu) + y^2 / (4 fv): the linear term -z splits over the (2,3) and (3,2) entries.
    Eigen::Matrix4d q = diagonal(1 / (4 * p->focal_u()), 1 / (4 * p->focal_v()), 0, 0);
    q(2, 3) = q(3, 2) = -0.5;
    return placed(p->frame(), q);
  }
  return std::nullopt;
}

std::optional<RevolutionForm> revolution_form(const Surface& surface) {
  if (const auto* s = surface.get_if<Sphere>())
    return RevolutionForm{s->center(), s->frame().e2, s->radius() * s->radius(), 0, -1, true};
  if (const auto* c = surface.get_if<Cylinder>())
    return RevolutionForm{c->frame().origin, c->frame().e2, c->radius() * c->radius(), 0, 0, false};
  if (const auto* k = surface.get_if<Cone>()) {
    const double t = std::tan(k->half_angle());
    return RevolutionForm{k->frame().origin, k->frame().e2, 0, 0, t * t, false};
  }
  if (const auto* e = surface.get_if<Ellipsoid>()) {
    const auto& r = e->radii();
    if (r[0] != r[1]) return std::nullopt;
    return RevolutionForm{e->frame().origin, e->frame().e2, r[0] * r[0], 0, -(r[0] * r[0]) / (r[2] * r[2]), false};
  }
  if (const auto* p = surface.get_if<Paraboloid>()) {
    if (p->focal_u() != p->focal_v()) return std::nullopt;
    return RevolutionForm{p->frame().origin, p->frame().e2, 0, 4 * p->focal_u(), 0, false};
  }
  return std::nullopt;
}

}  // namespace ssimarch
