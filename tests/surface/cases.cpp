#include "surface/cases.hpp"

#include <cmath>
#include <numbers>

#include "ssimarch/surface/primitives.hpp"

namespace ssimarch::testing {
namespace {

const Vec3 kCenter(0.3, -1.2, 2.1);
const Vec3 kAxis(1.0, 2.0, -0.5);  // a general direction: every world coordinate mixes
constexpr double kPi = std::numbers::pi;

// 4 x 4 interior points of the domain at fractions chosen to miss poles, apexes and knots.
std::vector<std::array<double, 2>> grid(const ParamDomain& d) {
  const double f[] = {0.13, 0.37, 0.61, 0.87};
  std::vector<std::array<double, 2>> uv;
  for (double a : f)
    for (double b : f) uv.push_back({d.u.lo + a * d.u.width(), d.v.lo + b * d.v.width()});
  return uv;
}

ControlNet net(int nu, int nv, double wobble) {
  ControlNet p(static_cast<std::size_t>(nu), std::vector<Vec3>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          Vec3(i + 0.3 * std::sin(1.7 * j + i), j + 0.2 * std::cos(2.3 * i - j),
               wobble * std::sin(0.9 * i + 1.3 * j) + 0.1 * i * j);
  return p;
}

WeightNet weights(int nu, int nv) {
  WeightNet w(static_cast<std::size_t>(nu), std::vector<double>(static_cast<std::size_t>(nv)));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      w[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = 1.0 + 0.6 * std::sin(1.1 * i + 0.7 * j);
  return w;
}

SurfaceCase parametric_case(std::string name, std::function<Surface()> make, bool unit, int sign) {
  SurfaceCase c{std::move(name), std::move(make), {}, {}, unit, sign};
  c.uv = grid(c.make().domain());
  return c;
}

}  // namespace

std::vector<SurfaceCase> all_surface_cases() {
  std::vector<SurfaceCase> cases;
  cases.push_back(parametric_case(
      "plane", [] { return Surface(Plane(kCenter, kAxis, {{-2, 3}, {-1, 1}})); }, true, +1));
  cases.push_back(parametric_case("sphere", [] { return Surface(Sphere(kCenter, 1.7, kAxis)); }, true, +1));
  cases.push_back(parametric_case("sphere_z", [] { return Surface(Sphere(Vec3::Zero(), 2.0)); }, true, +1));
  cases.push_back(parametric_case(
      "cylinder", [] { return Surface(Cylinder(kCenter, kAxis, 0.8, {-1, 2}, Vec3(0, 0, 1))); }, true, +1));
  cases.push_back(parametric_case(
      "cone", [] { return Surface(Cone(kCenter, kAxis, 0.4, {-1.5, 2})); }, false, 0));
  cases.push_back(parametric_case("torus", [] { return Surface(Torus(kCenter, kAxis, 2.0, 0.6)); }, false, +1));
  cases.push_back(parametric_case(
      "ellipsoid", [] { return Surface(Ellipsoid(kCenter, {1.5, 0.9, 2.2}, kAxis)); }, false, +1));
  cases.push_back(parametric_case(
      "paraboloid", [] { return Surface(Paraboloid(kCenter, kAxis, 0.7, 1.3, {{-1.5, 1}, {-1, 2}})); }, false, -1));
  {
    SurfaceCase c{"capsule", [] { return Surface(Capsule(kCenter, kAxis, 0.7, 1.5)); }, {}, {}, true, +1};
    // Joins at v = +-0.75, poles at +-(0.75 + 0.35 pi) = +-1.8496.
    for (double u : {0.3, 2.0, 4.1})
      for (double v : {-1.6, -1.0, -0.5, 0.1, 0.6, 1.2, 1.7}) c.uv.push_back({u, v});
    cases.push_back(c);
  }
  {
    SurfaceCase c{"capsule_sphere", [] { return Surface(Capsule(kCenter, kAxis, 1.1, 0.0)); }, {}, {}, true, +1};
    for (double u : {0.3, 2.0, 4.1})
      for (double v : {-1.2, -0.4, 0.3, 1.1}) c.uv.push_back({u, v});
    cases.push_back(c);
  }
  cases.push_back(parametric_case(
      "expr_parametric",
      [] {
        return Surface(ExprParametric::compile(
            {"(a+cos(3*u))*cos(u) + v*sin(u)", "(a+cos(3*u))*sin(u) - v*cos(u)", "sin(3*u) + v^2/2 + exp(v/3)"},
            {{0, 2 * kPi}, {-1, 1}, true, false}, {{"a", 2.0}}));
      },
      false, 0));
  {
    SurfaceCase c{"expr_implicit_cylinder",
                  [] { return Surface(ExprImplicit::compile("x^2+y^2-x", {{-2, 2}, {-2, 2}, {-2, 2}}, {})); },
                  {}, {}, true, 0};
    for (double t : {0.2, 1.3, 2.9, 4.4, 5.8}) c.xyz.emplace_back(0.5 + 0.5 * std::cos(t), 0.5 * std::sin(t), 0.6 * (t - 3));
    cases.push_back(c);
  }
  {
    SurfaceCase c{"expr_implicit_transcendental",
                  [] {
                    return Surface(
                        ExprImplicit::compile("exp(x) + y*z^3 - sin(z) - k", {{-3, 3}, {-3, 3}, {-3, 3}}, {{"k", 2.0}}));
                  },
                  {}, {}, false, 0};
    for (double y : {-0.7, 0.2, 0.9})
      for (double z : {-0.8, 0.4, 1.0}) c.xyz.emplace_back(std::log(2.0 + std::sin(z) - y * z * z * z), y, z);
    cases.push_back(c);
  }
  cases.push_back(parametric_case("bezier_bicubic", [] { return Surface(BezierPatch(net(4, 4, 1.0))); }, false, 0));
  cases.push_back(parametric_case(
      "bezier_rational", [] { return Surface(BezierPatch(net(3, 5, 0.8), weights(3, 5))); }, false, 0));
  cases.push_back(parametric_case(
      "bspline_3x2",
      [] {
        return Surface(BSplineSurface(3, 2, {0, 0, 0, 0, 0.3, 0.55, 1, 1, 1, 1}, {0, 0, 0, 0.25, 0.5, 1, 1, 1},
                                      net(6, 5, 1.0)));
      },
      false, 0));
  cases.push_back(parametric_case(
      "nurbs_unclamped",
      [] {
        return Surface(BSplineSurface(2, 3, {0, 1, 2, 3, 4, 5, 6, 7}, {0, 0.5, 1.5, 2, 3, 4, 4.5, 5, 6, 7},
                                      net(5, 6, 0.7), weights(5, 6)));
      },
      false, 0));
  return cases;
}

}  // namespace ssimarch::testing
