#include "ssimarch/surface/expr_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/core/error.hpp"
#include "ssimarch/surface/frame.hpp"

namespace ssimarch {
namespace {

void check_interval(const Interval& i, const std::string& where, const char* name) {
  if (!std::isfinite(i.lo) || !std::isfinite(i.hi) || !(i.lo < i.hi))
    throw InputError(where, std::string(name) + " must be an interval [lo, hi] of finite numbers with lo < hi");
}

}  // namespace

ExprParametric::ExprParametric(std::array<Program, 3> xyz, const ParamDomain& domain) : domain_(domain) {
  for (const auto& p : xyz)
    if (p.num_variables() != 2)
      throw InputError("parametric", "each coordinate must be compiled in exactly the variables (u, v)");
  check_interval(domain.u, "parametric", "u");
  check_interval(domain.v, "parametric", "v");
  programs_ = std::make_shared<const std::array<Program, 3>>(std::move(xyz));
  // Sampled box: 65 x 65 values of F (non-finite samples skipped).
  constexpr int kSamples = 65;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Box b{{kInf, -kInf}, {kInf, -kInf}, {kInf, -kInf}};
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const double u = domain.u.lo + domain.u.width() * i / (kSamples - 1);
      const double v = domain.v.lo + domain.v.width() * j / (kSamples - 1);
      const Vec3T<double> p = point<double>(u, v);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      b = box_union(b, {{p.x, p.x}, {p.y, p.y}, {p.z, p.z}});
    }
  if (!(b.x.lo <= b.x.hi)) b = {{0, 0}, {0, 0}, {0, 0}};  // no finite sample: the domain is reported by the tracer
  box_ = inflate(b, 0.05);
}

ExprParametric ExprParametric::compile(const std::array<std::string, 3>& sources, const ParamDomain& domain,
                                       const Constants& constants, const std::string& where) {
  static const std::vector<std::string> kVars = {"u", "v"};
  std::array<Program, 3> p;
  for (std::size_t i = 0; i < 3; ++i)
    p[i] = Program::compile_or_throw(sources[i], std::span<const std::string>(kVars), constants,
                                           where + "[" + std::to_string(i) + "]");
  check_interval(domain.u, where, "u");
  check_interval(domain.v, where, "v");
  return ExprParametric(std::move(p), domain);
}

ExprImplicit::ExprImplicit(Program f, const Box& box) : box_(box) {
  if (f.num_variables() != 3)
    throw InputError("implicit", "the expression must be compiled in exactly the variables (x, y, z)");
  check_interval(box.x, "implicit", "box x");
  check_interval(box.y, "implicit", "box y");
  check_interval(box.z, "implicit", "box z");
  program_ = std::make_shared<const Program>(std::move(f));
}

ExprImplicit ExprImplicit::compile(const std::string& source, const Box& box, const Constants& constants,
                                   const std::string& where) {
  static const std::vector<std::string> kVars = {"x", "y", "z"};
  auto p = Program::compile_or_throw(source, std::span<const std::string>(kVars), constants, where);
  check_interval(box.x, where, "box x");
  check_interval(box.y, where, "box y");
  check_interval(box.z, where, "box z");
  return ExprImplicit(std::move(p), box);
}

}  // namespace ssimarch
