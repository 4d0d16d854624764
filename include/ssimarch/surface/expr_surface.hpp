// Surfaces given by expressions of the expression language (docs/expressions.md).
//
// ExprParametric: F(u,v) = (x(u,v), y(u,v), z(u,v)) on a domain rectangle with periodic flags
//   (the flags are trusted: the caller says F(u.lo, v) = F(u.hi, v)). No implicit form.
// ExprImplicit: f(x,y,z) = 0 inside a box (the region of interest where the tracer hunts for
//   the surface); no parametric form and no normalisation: |grad f| is whatever the expression
//   gives.
// Both are cheap to copy: the compiled programs are shared (immutable).
#pragma once

#include <array>
#include <memory>
#include <string>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/expr/program.hpp"
#include "ssimarch/surface/domain.hpp"

namespace ssimarch {

class ExprParametric {
 public:
  /// Programs in the variables (u, v) (in that order). Throws InputError for a program with a
  /// different number of variables, an empty or non-finite domain. `box()` is the box of the
  /// values at a 65 x 65 grid of the domain (inflated by 5 %): a guide for plots and sampling,
  /// not a guaranteed enclosure.
  ExprParametric(std::array<Program, 3> xyz, const ParamDomain& domain);
  /// Compiles the three sources (variables u, v); errors are InputError(where[i], ...).
  static ExprParametric compile(const std::array<std::string, 3>& sources, const ParamDomain& domain,
                                const Constants& constants, const std::string& where = "parametric");

  const ParamDomain& domain() const { return domain_; }
  const Box& box() const { return box_; }
  const Program& program(int i) const { return (*programs_)[static_cast<std::size_t>(i)]; }

  template <class T>
  Vec3T<T> point(const T& u, const T& v) const {
    const std::array<T, 2> uv{u, v};
    std::span<const T> s(uv);
    const auto& p = *programs_;
    return {p[0].template eval<T>(s), p[1].template eval<T>(s), p[2].template eval<T>(s)};
  }

 private:
  std::shared_ptr<const std::array<Program, 3>> programs_;
  ParamDomain domain_;
  Box box_;
};

class ExprImplicit {
 public:
  /// Program in the variables (x, y, z). Throws InputError for a wrong variable count or an
  /// empty or non-finite box.
  ExprImplicit(Program f, const Box& box);
  static ExprImplicit compile(const std::string& source, const Box& box, const Constants& constants,
                              const std::string& where = "implicit");

  const Box& box() const { return box_; }
  const Program& program() const { return *program_; }

  template <class T>
  T value(const Vec3T<T>& p) const {
    const std::array<T, 3> xyz{p.x, p.y, p.z};
    return program_->template eval<T>(std::span<const T>(xyz));
  }

 private:
  std::shared_ptr<const Program> program_;
  Box box_;
};

}  // namespace ssimarch
