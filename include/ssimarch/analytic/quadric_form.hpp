// The primitives of surface/ as the algebraic objects the closed-form sections work on
// (docs/math/closed_form_quadrics.md, "The quadric of a primitive" and "Surfaces of revolution").
#pragma once

#include <optional>

#include <Eigen/Dense>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Symmetric 4x4 Q with X^T Q X = 0 exactly on the implicit surface, X = (x, y, z, 1) in world
/// coordinates, for the quadric primitives (sphere, cylinder, cone, ellipsoid, paraboloid);
/// nullopt for every other surface (plane, torus, capsule, expressions, patches).
std::optional<Eigen::Matrix4d> quadric_matrix(const Surface& surface);

/// A surface of revolution whose meridian is a conic: the points with
/// (distance from the axis)^2 = c0 + c1 h + c2 h^2, h = (p - origin) . axis.
struct RevolutionForm {
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();  // unit
  double c0 = 0, c1 = 0, c2 = 0;
  bool any_axis = false;  // a sphere: every line through `origin` is an axis
};

/// Sphere, cylinder, cone (both nappes), spheroid (two equal radii about the frame's e2) and
/// paraboloid of revolution (equal focal distances); nullopt for every other surface.
std::optional<RevolutionForm> revolution_form(const Surface& surface);

}  // namespace ssimarch
