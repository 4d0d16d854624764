#include "ssimarch/surface/surface.hpp"

#include "ssimarch/core/contract.hpp"

namespace ssimarch {
namespace {

template <class S>
constexpr std::string_view name_of() {
  if constexpr (std::is_same_v<S, Plane>) return "plane";
  else if constexpr (std::is_same_v<S, Sphere>) return "sphere";
  else if constexpr (std::is_same_v<S, Cylinder>) return "cylinder";
  else if constexpr (std::is_same_v<S, Cone>) return "cone";
  else if constexpr (std::is_same_v<S, Torus>) return "torus";
  else if constexpr (std::is_same_v<S, Ellipsoid>) return "ellipsoid";
  else if constexpr (std::is_same_v<S, Paraboloid>) return "paraboloid";
  else if constexpr (std::is_same_v<S, Capsule>) return "capsule";
  else if constexpr (std::is_same_v<S, ExprParametric>) return "parametric";
  else if constexpr (std::is_same_v<S, ExprImplicit>) return "implicit";
  else if constexpr (std::is_same_v<S, BezierPatch>) return "bezier";
  else {
    static_assert(std::is_same_v<S, BSplineSurface>, "every alternative of Surface::Variant needs a name");
    return "bspline";
  }
}

template <class S>
constexpr bool kHasPoint = requires(const S& s, double u) { s.template point<double>(u, u); };
template <class S>
constexpr bool kHasValue = requires(const S& s, const Vec3T<double>& p) { s.template value<double>(p); };

}  // namespace

bool Surface::is_parametric() const {
  return std::visit([](const auto& s) { return kHasPoint<std::remove_cvref_t<decltype(s)>>; }, s_);
}

bool Surface::is_implicit() const {
  return std::visit([](const auto& s) { return kHasValue<std::remove_cvref_t<decltype(s)>>; }, s_);
}

std::string_view Surface::type_name() const {
  return std::visit([](const auto& s) { return name_of<std::remove_cvref_t<decltype(s)>>(); }, s_);
}

const ParamDomain& Surface::domain() const {
  return std::visit(
      [this](const auto& s) -> const ParamDomain& {
        if constexpr (kHasPoint<std::remove_cvref_t<decltype(s)>>) {
          return s.domain();
        } else {
          SSIMARCH_CONTRACT_FAILURE("ssimarch::Surface::domain: a " + std::string(type_name()) +
                                    " surface has no parametric form");
        }
      },
      s_);
}

const Box& Surface::box() const {
  return std::visit([](const auto& s) -> const Box& { return s.box(); }, s_);
}

}  // namespace ssimarch
