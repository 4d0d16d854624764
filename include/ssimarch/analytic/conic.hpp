// A conic of 3D space (or a piece of one) as the closed-form sections of quadrics return it:
// type, centre, unit axes, semi-axes and the parameter range of the piece
// (docs/math/closed_form_quadrics.md, "Parameterisations").
#pragma once

#include <string_view>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

enum class ConicType {
  kCircle,     // C + a (cos t e0 + sin t e1), t in [0, 2 pi)
  kEllipse,    // C + a cos t e0 + b sin t e1, a >= b, t in [0, 2 pi)
  kHyperbola,  // one branch: C + a cosh t e0 + b sinh t e1, t real (the other branch: e0, e1 negated)
  kParabola,   // vertex C: C + t^2 / (4 a) e0 + t e1 (a = focal distance), t real
  kLine,       // C + t e0, t real
  kPoint,      // the single point C (a tangential contact point or a cone's apex)
};
std::string_view to_string(ConicType t);

/// How the surfaces meet along the conic.
enum class Contact {
  kTransversal,  // they cross: distinct normals along the curve
  kTangential,   // they touch along it (a double line or circle of the section, a contact point)
};
std::string_view to_string(Contact c);

struct Conic {
  ConicType type = ConicType::kPoint;
  Vec3 center = Vec3::Zero();  // centre (circle, ellipse, hyperbola), vertex (parabola), a point (line, point)
  Vec3 e0 = Vec3::UnitX();     // major / transverse axis, parabola's axis, line's direction
  Vec3 e1 = Vec3::UnitY();     // minor / conjugate axis, parabola's tangent at the vertex
  double a = 0, b = 0;         // semi-axes (a along e0); parabola: a = focal distance; line, point: 0
  Interval range{0, 0};        // the parameter range of this piece
  Contact contact = Contact::kTransversal;

  /// The point at parameter t.
  Vec3 point(double t) const;
  /// d point / dt.
  Vec3 derivative(double t) const;
  /// Whether the parameterisation is 2 pi periodic (circle, ellipse).
  bool periodic() const { return type == ConicType::kCircle || type == ConicType::kEllipse; }
};

}  // namespace ssimarch
