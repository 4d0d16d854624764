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
#include "ssimarch/core/jet.hpp"
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
  Vec3T<T> point(const T& u, const T& v) const;

  /// Implicit form f(p), zero on the surface; throws std::logic_error if !is_implicit().
  template <class T>
  T value(const Vec3T<T>& p) const;

  const Variant& variant() const { return s_; }
  template <class S>
  const S* get_if() const {
    return std::get_if<S>(&s_);
  }

 private:
  Variant s_;
};

// Defined outside the class, and not inline, so that the explicit instantiation declarations
// below keep every translation unit from compiling its own copy of each form for each number
// type (an inline member would still be instantiated for inlining, [temp.explicit]). Twelve
// kinds times a jet type made Surface::point<Jet<2, 1>> alone compile in 15 translation units
// (issue 29: `make demo` built for 19 minutes on 2 cores).
template <class T>
Vec3T<T> Surface::point(const T& u, const T& v) const {
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

template <class T>
T Surface::value(const Vec3T<T>& p) const {
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

// Both forms of a surface on the number type __VA_ARGS__, declared (PREFIX `extern template`) or
// instantiated (PREFIX `template`). Doubles stay implicit: they are cheap to compile and the hot
// loops gain from inlining them.
#define SSIMARCH_SURFACE_FORMS(PREFIX, ...)                                                            \
  PREFIX Vec3T<__VA_ARGS__> Surface::point<__VA_ARGS__>(const __VA_ARGS__&, const __VA_ARGS__&) const; \
  PREFIX __VA_ARGS__ Surface::value<__VA_ARGS__>(const Vec3T<__VA_ARGS__>&) const

// The jets the library evaluates surfaces on, compiled once in src/surface/surface_jets_*.cpp. A
// type missing here still works (it is instantiated where it is used); listing it saves compiling it
// in every translation unit that uses it.
#define SSIMARCH_SURFACE_JET_TYPES_1(X) \
  X(Jet<1, 1>);                         \
  X(Jet<1, 2>);                         \
  X(Jet<1, 3>);                         \
  X(Jet<1, 4>);                         \
  X(Jet<1, 5>);                         \
  X(Jet<1, 6>);                         \
  X(Jet<1, 7>);                         \
  X(Jet<1, 8>)
#define SSIMARCH_SURFACE_JET_TYPES_2(X) \
  X(Jet<2, 1>);                         \
  X(Jet<2, 2>);                         \
  X(Jet<2, 3>);                         \
  X(Jet<2, 4>);                         \
  X(Jet<2, 12>)
#define SSIMARCH_SURFACE_JET_TYPES_3(X) \
  X(Jet<3, 1>);                         \
  X(Jet<3, 2>);                         \
  X(Jet<3, 3>);                         \
  X(Jet<3, 4>);                         \
  X(Jet<4, 1>)

#define SSIMARCH_SURFACE_FORMS_EXTERN(...) SSIMARCH_SURFACE_FORMS(extern template, __VA_ARGS__)
SSIMARCH_SURFACE_JET_TYPES_1(SSIMARCH_SURFACE_FORMS_EXTERN);
SSIMARCH_SURFACE_JET_TYPES_2(SSIMARCH_SURFACE_FORMS_EXTERN);
SSIMARCH_SURFACE_JET_TYPES_3(SSIMARCH_SURFACE_FORMS_EXTERN);
#undef SSIMARCH_SURFACE_FORMS_EXTERN

}  // namespace ssimarch
