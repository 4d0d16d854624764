// Surface: a value type over the closed set of surface kinds, dispatched with std::visit.
//
// The geometry stays in small templated value types (primitives, expression surfaces, Bezier
// and B-spline patches) whose point<T>(u, v) and value<T>(p) are written once for every number
// type (double, Jet<NV,K>); Surface only forwards (style.md 3.4, "run-time polymorphism only at
// the boundary"). A kind without a form (ExprParametric has no implicit form, ExprImplicit no
// parametric one, Bezier and B-spline patches no implicit one) throws std::logic_error when
// that form is asked for: callers check is_parametric() / is_implicit() first.
//
// Copying is cheap: heavy data (programs, control nets) is shared and immutable.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "ssimarch/core/contract.hpp"
#include "ssimarch/surface/bezier_patch.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "ssimarch/surface/domain.hpp"
#include "ssimarch/surface/expr_surface.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {

class Surface {
 public:
  using Variant = std::variant<Plane, Sphere, Cylinder, Cone, Torus, Ellipsoid, Paraboloid, Capsule, ExprParametric,
                               ExprImplicit, BezierPatch, BSplineSurface>;

  template <class S>
    requires std::is_constructible_v<Variant, S&&> && (!std::is_same_v<std::remove_cvref_t<S>, Surface>)
  Surface(S&& s) : s_(std::forward<S>(s)) {}  // NOLINT: implicit, any concrete kind is a Surface

  bool is_parametric() const;
  bool is_implicit() const;
  /// "plane", "sphere", "cylinder", "cone", "torus", "ellipsoid", "paraboloid", "capsule",
  /// "parametric", "implicit", "bezier", "bspline".
  std::string_view type_name() const;
  /// Domain of the parametric form; throws std::logic_error if !is_parametric().
  const ParamDomain& domain() const;
  /// Region of interest: for implicit expressions the given box; for primitives a box around
  /// the shape (its trimmed part for unbounded ones); for patches the control-point box; for
  /// parametric expressions a sampled box (see each type's header).
  const Box& box() const;

  /// Parametric form F(u,v); throws std::logic_error if !is_parametric().
  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    return std::visit(
        [&](const auto& s) -> Vec3T<T> {
          if constexpr (requires { s.template point<T>(u, v); }) {
            return s.template point<T>(u, v);
          } else {
            SSIMARCH_CONTRACT_FAILURE(std::string("ssimarch::Surface::point: a ") + std::string(type_name()) +
                                      " surface has no parametric form");
          }
        },
        s_);
  }

  /// Implicit form f(p), zero on the surface; throws std::logic_error if !is_implicit().
  template <class T>
  T value(const Vec3T<T>& p) const {
    return std::visit(
        [&](const auto& s) -> T {
          if constexpr (requires { s.template value<T>(p); }) {
            return s.template value<T>(p);
          } else {
            SSIMARCH_CONTRACT_FAILURE(std::string("ssimarch::Surface::value: a ") + std::string(type_name()) +
                                      " surface has no implicit form");
          }
        },
        s_);
  }

  const Variant& variant() const { return s_; }
  template <class S>
  const S* get_if() const {
    return std::get_if<S>(&s_);
  }

 private:
  Variant s_;
};

}  // namespace ssimarch
