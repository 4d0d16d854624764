// What a surface kind must provide to take part in Surface (style.md 3.4): templated evaluation
// that compiles for double and for jets (first-order multivariate, high-order univariate).
#pragma once

#include <concepts>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

template <class S>
concept ParametricSurface = requires(const S& s, double u, const Jet<2, 4>& j, const Taylor<6>& t) {
  { s.template point<double>(u, u) } -> std::same_as<Vec3T<double>>;
  { s.template point<Jet<2, 4>>(j, j) } -> std::same_as<Vec3T<Jet<2, 4>>>;
  { s.template point<Taylor<6>>(t, t) } -> std::same_as<Vec3T<Taylor<6>>>;
  { s.domain() } -> std::convertible_to<const ParamDomain&>;
  { s.box() } -> std::convertible_to<const Box&>;
};

template <class S>
concept ImplicitSurface = requires(const S& s, const Vec3T<double>& p, const Vec3T<Jet<3, 3>>& j,
                                   const Vec3T<Taylor<6>>& t) {
  { s.template value<double>(p) } -> std::same_as<double>;
  { s.template value<Jet<3, 3>>(j) } -> std::same_as<Jet<3, 3>>;
  { s.template value<Taylor<6>>(t) } -> std::same_as<Taylor<6>>;
  { s.box() } -> std::convertible_to<const Box&>;
};

}  // namespace ssimarch
