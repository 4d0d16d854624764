#include "ssimarch/analytic/conic.hpp"

#include <cmath>

namespace ssimarch {

std::string_view to_string(ConicType t) {
  switch (t) {
    case ConicType::kCircle: return "circle";
    case ConicType::kEllipse: return "ellipse";
    case ConicType::kHyperbola: return "hyperbola";
    case ConicType::kParabola: return "parabola";
    case ConicType::kLine: return "line";
    case ConicType::kPoint: return "point";
  }
  return "?";
}

std::string_view to_string(Contact c) { return c == Contact::kTangential ? "tangential" : "transversal"; }

Vec3 Conic::point(double t) const {
  switch (type) {
    case ConicType::kCircle:
    case ConicType::kEllipse: return center + a * std::cos(t) * e0 + b * std::sin(t) * e1;
    case ConicType::kHyperbola: return center + a * std::cosh(t) * e0 + b * std::sinh(t) * e1;
    case ConicType::kParabola: return center + (t * t / (4 * a)) * e0 + t * e1;
    case ConicType::kLine: return center + t * e0;
    case ConicType::kPoint: return center;
  }
  return center;
}

Vec3 Conic::derivative(double t) const {
  switch (type) {
    case ConicType::kCircle:
    case ConicType::kEllipse: return -a * std::sin(t) * e0 + b * std::cos(t) * e1;
    case ConicType::kHyperbola: return a * std::sinh(t) * e0 + b * std::cosh(t) * e1;
    case ConicType::kParabola: return (t / (2 * a)) * e0 + e1;
    case ConicType::kLine: return e0;
    case ConicType::kPoint: return Vec3::Zero();
  }
  return Vec3::Zero();
}

}  // namespace ssimarch
