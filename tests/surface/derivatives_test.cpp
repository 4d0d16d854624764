// Derivatives, normals, fundamental forms and curvatures against closed forms; degenerate points.
#include "ssimarch/surface/derivatives.hpp"

#include <gtest/gtest.h>
#include "testing/matchers.hpp"

#include <cmath>
#include <numbers>

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;
const Vec3 kC(0.3, -1.2, 2.1);
const Vec3 kAxis(1.0, 2.0, -0.5);

void expect_forms(const FundamentalForms& ff, const FundamentalForms& want, double tol) {
  EXPECT_NEAR(ff.E, want.E, tol);
  EXPECT_NEAR(ff.F, want.F, tol);
  EXPECT_NEAR(ff.G, want.G, tol);
  EXPECT_NEAR(ff.L, want.L, tol);
  EXPECT_NEAR(ff.M, want.M, tol);
  EXPECT_NEAR(ff.N, want.N, tol);
}

TEST(FundamentalForms, SphereClosedForms) {
  const double r = 1.7;
  const Surface s = Sphere(kC, r, kAxis);
  for (auto [u, v] : {std::array{0.0, 0.0}, {1.1, 0.4}, {4.0, -1.2}}) {
    const auto ff = fundamental_forms(s, u, v);
    ASSERT_TRUE(ff);
    const double c2 = std::cos(v) * std::cos(v);
    expect_forms(*ff, {r * r * c2, 0, r * r, -r * c2, 0, -r}, 1e-13);
    EXPECT_NEAR(ff->L, -ff->E / r, 1e-13);
    EXPECT_NEAR(ff->N, -ff->G / r, 1e-13);
    const Curvatures k = curvatures(*ff);
    EXPECT_NEAR(k.gaussian, 1 / (r * r), 1e-13);
    EXPECT_NEAR(k.mean, -1 / r, 1e-13);
    EXPECT_NEAR(k.k1, -1 / r, 1e-6);  // umbilic: k1 = k2 up to sqrt of rounding
    EXPECT_NEAR(k.k2, -1 / r, 1e-6);
    EXPECT_NEAR(normal_curvature(*ff, 0.3, -2.0), -1 / r, 1e-13);
  }
}

TEST(FundamentalForms, CylinderClosedForms) {
  const double r = 0.8;
  const Surface s = Cylinder(kC, kAxis, r, {-1, 2});
  for (auto [u, v] : {std::array{0.0, 0.0}, {2.2, 1.5}, {5.0, -0.7}}) {
    const auto ff = fundamental_forms(s, u, v);
    ASSERT_TRUE(ff);
    expect_forms(*ff, {r * r, 0, 1, -r, 0, 0}, 1e-14);
    const Curvatures k = curvatures(*ff);
    EXPECT_NEAR(k.gaussian, 0, 1e-14);
    EXPECT_NEAR(k.mean, -1 / (2 * r), 1e-14);
    EXPECT_NEAR(k.k1, 0, 1e-14);
    EXPECT_NEAR(k.k2, -1 / r, 1e-14);
    // The implicit form: -1/r around, 0 along the axis.
    const Vec3 p = point(s, u, v);
    const auto F = parametric_jet<1>(s, u, v);
    EXPECT_NEAR(*normal_curvature(s, p, partial(F, 1, 0)), -1 / r, 1e-14);
    EXPECT_NEAR(*normal_curvature(s, p, kAxis), 0, 1e-14);
  }
}

TEST(FundamentalForms, TorusClosedForms) {
  const double R = 2.0, r = 0.6;
  const Surface s = Torus(kC, kAxis, R, r);
  for (auto [u, v] : {std::array{0.0, 0.0}, {1.0, 1.3}, {3.0, kPi}, {5.5, 4.4}}) {
    const auto ff = fundamental_forms(s, u, v);
    ASSERT_TRUE(ff);
    const double rho = R + r * std::cos(v);
    expect_forms(*ff, {rho * rho, 0, r * r, -rho * std::cos(v), 0, -r}, 1e-13);
    const double K = std::cos(v) / (r * rho);
    const double H = -(R + 2 * r * std::cos(v)) / (2 * r * rho);
    const Curvatures k = curvatures(*ff);
    EXPECT_NEAR(k.gaussian, K, 1e-13);
    EXPECT_NEAR(k.mean, H, 1e-13);
    const auto ki = implicit_curvatures(s, point(s, u, v));
    ASSERT_TRUE(ki);
    EXPECT_NEAR(ki->gaussian, K, 1e-12);
    EXPECT_NEAR(ki->mean, H, 1e-12);
    // Principal curvatures: -1/r around the tube, -cos v / rho around the axis.
    EXPECT_NEAR(std::min(ki->k2, ki->k1), std::min(-1 / r, -std::cos(v) / rho), 1e-9);
    EXPECT_NEAR(std::max(ki->k2, ki->k1), std::max(-1 / r, -std::cos(v) / rho), 1e-9);
  }
}

TEST(Curvature, ImplicitSphereInEveryTangentDirection) {
  const double r = 1.7;
  const Surface s = Sphere(kC, r, kAxis);
  const Vec3 p = point(s, 0.8, 0.3);
  for (const Vec3& w : {Vec3(1, 0, 0), Vec3(0.3, -2, 1), Vec3(0, 0, 1)})
    EXPECT_NEAR(*normal_curvature(s, p, w), -1 / r, 1e-14);
  // w along the normal has no tangential part.
  EXPECT_FALSE(normal_curvature(s, p, p - kC));
}

TEST(Curvature, ParaboloidAtTheVertexHasOppositeSignsInTheTwoForms) {
  // Parametric normal points to the focus, grad f away from it (paraboloid.hpp).
  const Surface s = Paraboloid(kC, kAxis, 0.7, 1.3);
  const auto ff = fundamental_forms(s, 0, 0);
  ASSERT_TRUE(ff);
  expect_forms(*ff, {1, 0, 1, 1 / 1.4, 0, 1 / 2.6}, 1e-14);
  const auto F = parametric_jet<1>(s, 0, 0);
  EXPECT_NEAR(*normal_curvature(s, kC, partial(F, 1, 0)), -1 / 1.4, 1e-14);
  EXPECT_NEAR(*normal_curvature(s, kC, partial(F, 0, 1)), -1 / 2.6, 1e-14);
}

TEST(Derivatives, SphereJetOfOrderSixMatchesClosedForms) {
  const double r = 1.7, u = 0.9, v = -0.4;
  const Sphere sp(kC, r, kAxis);
  const auto F = parametric_jet<6>(Surface(sp), u, v);
  const Frame& fr = sp.frame();
  // d^a/du^a d^b/dv^b of r (cos v cos u, cos v sin u, sin v) in the frame.
  auto dcos = [](double x, int k) { return std::cos(x + k * kPi / 2); };
  auto dsin = [](double x, int k) { return std::sin(x + k * kPi / 2); };
  for (int a = 0; a <= 6; ++a)
    for (int b = 0; a + b <= 6; ++b) {
      const double x = r * dcos(v, b) * dcos(u, a), y = r * dcos(v, b) * dsin(u, a);
      const double z = a == 0 ? r * dsin(v, b) : 0.0;
      const Vec3 want = (a + b == 0 ? kC : Vec3::Zero()) + x * fr.e0 + y * fr.e1 + z * fr.e2;
      EXPECT_THAT(partial(F, a, b), testing::IsNear(want, 1e-12)) << "a=" << a << " b=" << b;
    }
}

// A polynomial of degree d equals its Taylor polynomial of order d: the jet reproduces it
// exactly away from the expansion point.
template <int K>
double taylor_at(const Jet<3, K>& j, const Vec3& h) {
  const auto& layout = Jet<3, K>::Layout::get();
  double s = 0;
  for (int i = 0; i < Jet<3, K>::kSize; ++i) {
    double t = j[i];
    for (int v = 0; v < 3; ++v) t *= std::pow(h[v], layout.exponents[static_cast<std::size_t>(i)][static_cast<std::size_t>(v)]);
    s += t;
  }
  return s;
}

TEST(Derivatives, ImplicitJetsReproducePolynomialPrimitivesExactly) {
  const Vec3 p(0.4, -0.9, 1.7), h(0.6, -1.1, 0.35);
  const Surface quadrics[] = {Sphere(kC, 1.7, kAxis), Cylinder(kC, kAxis, 0.8, {-1, 2}), Cone(kC, kAxis, 0.4, {-1, 2}),
                              Ellipsoid(kC, {1.5, 0.9, 2.2}, kAxis), Paraboloid(kC, kAxis, 0.7, 1.3),
                              Plane(kC, kAxis)};
  for (const Surface& s : quadrics) {
    const double want = s.value<double>(Vec3T<double>(Vec3(p + h)));
    EXPECT_NEAR(taylor_at(implicit_jet<2>(s, p), h), want, 1e-13) << s.type_name();
  }
  const Surface torus = Torus(kC, kAxis, 2.0, 0.6);
  EXPECT_NEAR(taylor_at(implicit_jet<4>(torus, p), h), torus.value<double>(Vec3T<double>(Vec3(p + h))), 1e-12);
}

TEST(Degenerate, ParametricPointsAreReported) {
  const Surface sphere = Sphere(kC, 1.7, kAxis);
  EXPECT_FALSE(unit_normal(sphere, 0.3, kPi / 2));
  EXPECT_FALSE(unit_normal(sphere, 0.3, -kPi / 2));
  EXPECT_FALSE(fundamental_forms(sphere, 0.3, kPi / 2));
  EXPECT_TRUE(unit_normal(sphere, 0.3, kPi / 2 - 1e-3));
  const Surface cone = Cone(kC, kAxis, 0.4, {-1, 1});
  EXPECT_FALSE(unit_normal(cone, 1.0, 0.0));
  EXPECT_FALSE(fundamental_forms(cone, 1.0, 0.0));
  // Fu parallel to Fv: a surface folded onto a curve.
  const Surface folded = ExprParametric::compile({"u+v", "(u+v)^2", "0"}, {{0, 1}, {0, 1}}, {});
  EXPECT_FALSE(unit_normal(folded, 0.3, 0.4));
  // A non-finite derivative: sqrt at 0.
  const Surface cusp = ExprParametric::compile({"u", "v", "sqrt(u)"}, {{0, 1}, {0, 1}}, {});
  EXPECT_FALSE(unit_normal(cusp, 0.0, 0.5));
  EXPECT_TRUE(unit_normal(cusp, 0.25, 0.5));
}

TEST(Degenerate, ImplicitPointsAreReported) {
  const Surface sphere = Sphere(kC, 1.7, kAxis);
  EXPECT_FALSE(unit_normal(sphere, kC));  // grad f = 0 at the centre
  const Surface cone = ExprImplicit::compile("x^2+y^2-z^2", {{-1, 1}, {-1, 1}, {-1, 1}}, {});
  EXPECT_FALSE(unit_normal(cone, Vec3::Zero()));
  EXPECT_FALSE(implicit_curvatures(cone, Vec3::Zero()));
  EXPECT_FALSE(normal_curvature(cone, Vec3::Zero(), Vec3(1, 0, 0)));
  ASSERT_TRUE(unit_normal(cone, Vec3(1, 0, 1)));
  EXPECT_THAT(*unit_normal(cone, Vec3(1, 0, 1)), testing::IsNear(Vec3(1, 0, -1).normalized(), 1e-15));
  const Surface root = ExprImplicit::compile("sqrt(x) - y", {{-1, 1}, {-1, 1}, {-1, 1}}, {});
  EXPECT_FALSE(unit_normal(root, Vec3(0, 0, 0)));  // infinite derivative
  // A custom threshold.
  const Surface flat = ExprImplicit::compile("1e-9*(x - 0.5)", {{-1, 1}, {-1, 1}, {-1, 1}}, {});
  EXPECT_TRUE(unit_normal(flat, Vec3(0.5, 0, 0)));
  EXPECT_FALSE(unit_normal(flat, Vec3(0.5, 0, 0), 1e-6));
}

TEST(Derivatives, MissingFormsThrowLogicError) {
  const Surface implicit = ExprImplicit::compile("x+y+z", {{-1, 1}, {-1, 1}, {-1, 1}}, {});
  EXPECT_THROW(parametric_jet<2>(implicit, 0, 0), std::logic_error);
  EXPECT_THROW(unit_normal(implicit, 0.0, 0.0), std::logic_error);
  const Surface patch = BezierPatch({{Vec3(0, 0, 0), Vec3(0, 1, 0)}, {Vec3(1, 0, 0), Vec3(1, 1, 0)}});
  EXPECT_THROW(implicit_jet<2>(patch, Vec3::Zero()), std::logic_error);
  EXPECT_THROW(gradient(patch, Vec3::Zero()), std::logic_error);
}

}  // namespace
}  // namespace ssimarch
