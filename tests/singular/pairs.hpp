// Surface pairs with singular intersection points in closed form (thesis ch. 5 examples,
// thesis ch. 5; Viviani's node), and germs built from monomials, for the singular tests.
#pragma once

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/local_jet.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch::testing {

inline Surface param(const std::string& x, const std::string& y, const std::string& z, Interval u = {-2, 2},
                     Interval v = {-2, 2}, bool periodic_u = false, bool periodic_v = false) {
  std::vector<std::string> vars = {"u", "v"};
  expr::Constants c;
  std::array<expr::Program, 3> p = {expr::Program::compile_or_throw(x, vars, c), expr::Program::compile_or_throw(y, vars, c),
                                    expr::Program::compile_or_throw(z, vars, c)};
  return ExprParametric(p, ParamDomain{u, v, periodic_u, periodic_v});
}

inline Surface implicit_surface(const std::string& f, const Box& box = Box{{-3, 3}, {-3, 3}, {-3, 3}}) {
  std::vector<std::string> vars = {"x", "y", "z"};
  return ExprImplicit(expr::Program::compile_or_throw(f, vars, expr::Constants{}), box);
}

/// The thesis' graph pairs: F(u,v) = (u, v, f(u,v)) against the plane z = c, as a
/// parametric-implicit problem (h = f - c) or a parametric-parametric one (G(p,q) = (p, q, c)).
inline Problem graph_vs_plane_pi(const std::string& f, const std::string& c = "0") {
  return Problem(param("u", "v", f), implicit_surface("z-(" + c + ")"), PairKind::kParametricImplicit);
}
inline Problem graph_vs_plane_pp(const std::string& f, const std::string& c = "0") {
  return Problem(param("u", "v", f), param("u", "v", c), PairKind::kParametricParametric);
}

/// A germ sum c x^i y^j.
inline LocalJet germ(const std::vector<std::tuple<int, int, double>>& terms) {
  LocalJet h;
  for (auto [i, j, c] : terms) set_coef(h, i, j, coef(h, i, j) + c);
  return h;
}

}  // namespace ssimarch::testing
