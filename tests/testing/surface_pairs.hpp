// Surface pairs with known intersection curves, shared by the march tests and the marching
// benchmark (bench/march_compare.cpp) (style.md 3.12.5).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch::testing {

inline Surface parametric(const std::string& x, const std::string& y, const std::string& z, Interval u, Interval v,
                          bool periodic_u = false, bool periodic_v = false) {
  std::vector<std::string> vars = {"u", "v"};
  Constants c;
  std::array<Program, 3> p = {Program::compile_or_throw(x, vars, c), Program::compile_or_throw(y, vars, c),
                                    Program::compile_or_throw(z, vars, c)};
  return ExprParametric(p, ParamDomain{u, v, periodic_u, periodic_v});
}

inline Surface implicit(const std::string& f, const Box& box) {
  std::vector<std::string> vars = {"x", "y", "z"};
  return ExprImplicit(Program::compile_or_throw(f, vars, Constants{}), box);
}

// The plane (u, v, 0) against the implicit surface z = q(x, y): the curve q(u, v) = 0.
inline Problem plane_against(const std::string& q) {
  return Problem(parametric("u", "v", "0", {-1, 1}, {-1, 1}), implicit("z-(" + q + ")", Box{{-2, 2}, {-2, 2}, {-2, 2}}),
                 PairKind::kParametricImplicit);
}

// Thesis pair 1 (thesis ch. 3): ruled surface F1 and torus G1; curve C1.
inline Surface ruled_surface() {
  return parametric("(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)",
                    "(4+cos(4*u))*sin(u) + v*(cos(4*u)+sin(4*u))*sin(u)", "sin(4*u) + v*(sin(4*u)-cos(4*u))",
                    {0, 2 * M_PI}, {-0.5, 0.5}, true, false);
}
inline Surface torus_g1() {
  return parametric("(4+cos(u))*sin(v)", "(4+cos(u))*cos(v)", "sin(u)", {0, 2 * M_PI}, {0, 2 * M_PI}, true, true);
}
inline Vec3 c1(double s) {
  return {(4 + std::cos(4 * s)) * std::cos(s), (4 + std::cos(4 * s)) * std::sin(s), std::sin(4 * s)};
}
inline constexpr double kC1Length = 35.6831156534;

// Thesis pair 2 as the issue states it: sphere radius 2 and cylinder (cos u, sin u - 1, v);
// Viviani's curve (sin s, -1 - cos s, 2 sin(s/2)), s in [0, 4 pi), node at (0, -2, 0).
inline Surface cylinder_f2() {
  return parametric("cos(u)", "sin(u)-1", "v", {0, 2 * M_PI}, {-3, 3}, true, false);
}
// Poles on the x axis, off Viviani's curve (|x| <= 1 there): at a pole the parameterisation is
// singular and the curve would leave the domain through it.
inline Surface sphere_g2_parametric() {
  return parametric("2*sin(u)", "2*cos(u)*cos(v)", "2*cos(u)*sin(v)", {-M_PI / 2, M_PI / 2}, {0, 2 * M_PI}, false, true);
}
inline Surface sphere_g2_implicit() {
  return implicit("(x^2+y^2+z^2-4)/4", Box{{-3, 3}, {-3, 3}, {-3, 3}});
}
inline Surface cylinder_f2_implicit() {
  return implicit("(x^2+(y+1)^2-1)/2", Box{{-3, 3}, {-3, 3}, {-3, 3}});
}
inline Vec3 viviani(double s) { return {std::sin(s), -1 - std::cos(s), 2 * std::sin(s / 2)}; }
// integral_0^{4 pi} sqrt(1 + cos^2(s/2)) ds
inline constexpr double kVivianiLength = 15.2807911561;

}  // namespace ssimarch::testing
