// Primitives: frames, documented formulas at known points, gradient scalings, boxes, input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "testing/matchers.hpp"
#include "ssimarch/core/error.hpp"
#include "ssimarch/surface/derivatives.hpp"
#include "ssimarch/surface/primitives.hpp"

namespace ssimarch {
namespace {

constexpr double kPi = std::numbers::pi;
const Vec3 kC(0.3, -1.2, 2.1);
const Vec3 kAxis(1.0, 2.0, -0.5);

double f(const Surface& s, const Vec3& p) { return s.value<double>(Vec3T<double>(p)); }

void expect_vec(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_THAT(a, testing::IsNear(b, tol)) << "got " << a.transpose() << ", expected " << b.transpose();
}

TEST(Frame, DefaultsToTheCoordinateFrameForZ) {
  const Frame z = Frame::from_axis(Vec3::Zero(), Vec3(0, 0, 3));
  expect_vec(z.e0, Vec3::UnitX(), 0);
  expect_vec(z.e1, Vec3::UnitY(), 0);
  expect_vec(z.e2, Vec3::UnitZ(), 0);
  const Frame mz = Frame::from_axis(Vec3::Zero(), Vec3(0, 0, -1));
  expect_vec(mz.e0, Vec3::UnitX(), 0);
  expect_vec(mz.e1, -Vec3::UnitY(), 0);
}

TEST(Frame, IsRightHandedOrthonormalAndHonoursTheReference) {
  for (const Vec3& a : {kAxis, Vec3(1, 0, 0), Vec3(0, 1, 1e-12), Vec3(-3, 0.1, 7)}) {
    const Frame fr = Frame::from_axis(kC, a, Vec3(0.2, 1, 0.4));
    EXPECT_NEAR(fr.e0.norm(), 1, 1e-15);
    EXPECT_NEAR(fr.e1.norm(), 1, 1e-15);
    EXPECT_NEAR(fr.e0.dot(fr.e1), 0, 1e-15);
    EXPECT_NEAR(fr.e0.dot(fr.e2), 0, 1e-15);
    expect_vec(fr.e0.cross(fr.e1), fr.e2, 1e-15);
    expect_vec(fr.e2, a.normalized(), 1e-15);
    // e0 is the reference's part orthogonal to the axis.
    const Vec3 r = Vec3(0.2, 1, 0.4) - fr.e2 * fr.e2.dot(Vec3(0.2, 1, 0.4));
    expect_vec(fr.e0, r.normalized(), 1e-15);
    auto q = fr.to_local(Vec3T<double>(fr.to_world(0.5, -0.25, 2.0)));
    EXPECT_NEAR(q[0], 0.5, 1e-14);
    EXPECT_NEAR(q[1], -0.25, 1e-14);
    EXPECT_NEAR(q[2], 2.0, 1e-14);
  }
}

TEST(Frame, RejectsBadAxes) {
  EXPECT_THROW(Frame::from_axis(kC, Vec3::Zero()), InputError);
  EXPECT_THROW(Frame::from_axis(kC, Vec3(0, NAN, 1)), InputError);
  EXPECT_THROW(Frame::from_axis(Vec3(INFINITY, 0, 0), kAxis), InputError);
  EXPECT_THROW(Frame::from_axis(kC, kAxis, -2 * kAxis), InputError);
  EXPECT_THROW(Frame::from_axis(kC, kAxis, Vec3::Zero()), InputError);
}

TEST(Sphere, MatchesItsFormulas) {
  const Sphere sp(kC, 1.7, kAxis);
  const Surface s = sp;
  const Frame& fr = sp.frame();
  expect_vec(point(s, 0, 0), kC + 1.7 * fr.e0, 1e-15);
  expect_vec(point(s, kPi / 2, 0), kC + 1.7 * fr.e1, 1e-15);
  expect_vec(point(s, 0.4, kPi / 2), kC + 1.7 * fr.e2, 1e-15);
  EXPECT_NEAR(f(s, kC), -1.7 / 2, 1e-15);
  EXPECT_NEAR(f(s, kC + 3.4 * kAxis.normalized()), (3.4 * 3.4 - 1.7 * 1.7) / 3.4, 1e-14);
  EXPECT_EQ(s.type_name(), "sphere");
  EXPECT_TRUE(s.domain().periodic_u);
  EXPECT_FALSE(s.domain().periodic_v);
  // Box: centre +- r, each side moved out by 5 % of the side 2r.
  EXPECT_NEAR(s.box().x.lo, kC.x() - 1.7 * 1.1, 1e-14);
  EXPECT_NEAR(s.box().z.hi, kC.z() + 1.7 * 1.1, 1e-14);
}

TEST(Cylinder, MatchesItsFormulas) {
  const Cylinder cy(kC, kAxis, 0.8, {-1, 2});
  const Surface s = cy;
  const Frame& fr = cy.frame();
  expect_vec(point(s, kPi / 2, 0.5), kC + 0.8 * fr.e1 + 0.5 * fr.e2, 1e-15);
  EXPECT_NEAR(f(s, kC + 7 * fr.e2), -0.4, 1e-14);
  EXPECT_NEAR(f(s, kC + 2 * fr.e0 - 5 * fr.e2), (4 - 0.64) / 1.6, 1e-14);
  EXPECT_EQ(s.domain().v.lo, -1);
  EXPECT_EQ(s.domain().v.hi, 2);
  // Box of the axis-z cylinder: x, y in [-r, r] and z in the range, inflated by 5 % of 3.
  const Surface z = Cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.8, {-1, 2});
  EXPECT_NEAR(z.box().x.hi, 0.8 + 0.15, 1e-15);
  EXPECT_NEAR(z.box().z.lo, -1 - 0.15, 1e-15);
  EXPECT_NEAR(z.box().z.hi, 2 + 0.15, 1e-15);
}

TEST(Cone, GradientScalesWithAxialDistance) {
  const Cone co(kC, kAxis, 0.4, {-1.5, 2});
  const Surface s = co;
  const Frame& fr = co.frame();
  expect_vec(point(s, 0, 2), kC + 2 * std::tan(0.4) * fr.e0 + 2 * fr.e2, 1e-14);
  for (double v : {-1.4, -0.3, 0.7, 2.0}) {
    const Vec3 p = point(s, 1.1, v);
    EXPECT_NEAR(gradient(s, p).norm(), std::fabs(v) / 2.0, 1e-13) << v;  // |h| / max(|h0|, |h1|)
  }
  EXPECT_LT(f(s, kC + 1.0 * fr.e2), 0);   // inside the upper nappe
  EXPECT_LT(f(s, kC - 1.0 * fr.e2), 0);   // inside the lower nappe
  EXPECT_GT(f(s, kC + 1.0 * fr.e0), 0);   // outside
  EXPECT_FALSE(unit_normal(s, 0.3, 0.0));  // apex
}

TEST(Torus, MatchesItsFormulasAndGradientScaling) {
  const double R = 2.0, r = 0.6;
  const Torus to(kC, kAxis, R, r);
  const Surface s = to;
  const Frame& fr = to.frame();
  expect_vec(point(s, 0, 0), kC + (R + r) * fr.e0, 1e-14);
  expect_vec(point(s, kPi / 2, kPi / 2), kC + R * fr.e1 + r * fr.e2, 1e-14);
  EXPECT_NEAR(f(s, kC + R * fr.e0), (std::pow(2 * R * R - r * r, 2) - 4 * R * R * R * R) / (8 * R * R * r), 1e-14);
  for (double v : {0.0, 1.0, 2.5, kPi, 4.0}) {
    const Vec3 p = point(s, 0.7, v);
    EXPECT_NEAR(gradient(s, p).norm(), (R + r * std::cos(v)) / R, 1e-13) << v;
  }
  EXPECT_TRUE(s.domain().periodic_u && s.domain().periodic_v);
  // Box of the axis-z torus: x in +-(R + r) inflated by 5 % of 2 (R + r).
  const Surface z = Torus(Vec3::Zero(), Vec3::UnitZ(), R, r);
  EXPECT_NEAR(z.box().x.hi, (R + r) * 1.1, 1e-14);
  EXPECT_NEAR(z.box().z.hi, r + 0.1 * (R + r), 1e-14);
}

TEST(Ellipsoid, GradientIsOneAtTheShortestSemiAxis) {
  const Ellipsoid el(kC, {1.5, 0.9, 2.2}, kAxis);
  const Surface s = el;
  const Frame& fr = el.frame();
  EXPECT_NEAR(f(s, kC + 0.9 * fr.e1), 0, 1e-15);
  EXPECT_NEAR(gradient(s, kC + 0.9 * fr.e1).norm(), 1.0, 1e-14);
  EXPECT_NEAR(gradient(s, kC - 2.2 * fr.e2).norm(), 0.9 / 2.2, 1e-14);
  EXPECT_NEAR(f(s, kC), -0.45, 1e-15);
  // A round ellipsoid is the sphere.
  const Surface round = Ellipsoid(kC, {1.3, 1.3, 1.3}, kAxis);
  const Surface sphere = Sphere(kC, 1.3, kAxis);
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-0.5, 0.1, 2)}) EXPECT_NEAR(f(round, p), f(sphere, p), 1e-14);
}

TEST(Paraboloid, MatchesItsFormulas) {
  const Paraboloid pa(kC, kAxis, 0.7, 1.3, {{-1.5, 1}, {-1, 2}});
  const Surface s = pa;
  const Frame& fr = pa.frame();
  expect_vec(point(s, 1, -1), kC + fr.e0 - fr.e1 + (1 / 2.8 + 1 / 5.2) * fr.e2, 1e-14);
  for (auto [u, v] : {std::array{0.0, 0.0}, {0.8, -0.6}, {-1.2, 1.9}}) {
    const Vec3 g = gradient(s, point(s, u, v));
    EXPECT_NEAR(g.norm(), std::sqrt(1 + std::pow(u / 1.4, 2) + std::pow(v / 2.6, 2)), 1e-14);
  }
  const Surface round = Paraboloid(Vec3::Zero(), Vec3::UnitZ(), 0.5, 0.5);
  EXPECT_NEAR(f(round, Vec3(0, 0, 0.5)), -0.5, 1e-15);  // the focus is inside
  // Box of the axis-z graph over [-1,1]^2 with f = 0.5: z in [0, 1], inflated by 0.1.
  EXPECT_NEAR(round.box().z.lo, -0.1, 1e-15);
  EXPECT_NEAR(round.box().z.hi, 1.1, 1e-15);
  EXPECT_NEAR(round.box().x.hi, 1.1, 1e-15);
}

TEST(Plane, IsTheSignedDistance) {
  const Surface s = Plane(kC, kAxis, {{-2, 3}, {-1, 1}});
  const Vec3 n = kAxis.normalized();
  EXPECT_NEAR(f(s, kC + 2.5 * n + Vec3(0, 0, 0)), 2.5 + 0 * n.z(), 1e-14);
  const Vec3 q(4, 5, -6);
  EXPECT_NEAR(f(s, q), (q - kC).dot(n), 1e-14);
  expect_vec(*unit_normal(s, 0.1, 0.2), n, 1e-15);
  EXPECT_GT(s.box().z.width(), 0);
}

// Distance from p to the segment c +- (L/2) e2, by projection.
double segment_distance(const Vec3& p, const Vec3& c, const Vec3& e2, double L) {
  const double t = std::clamp((p - c).dot(e2), -L / 2, L / 2);
  return (p - (c + t * e2)).norm();
}

TEST(Capsule, IsTheDistanceToItsSegment) {
  const double r = 0.7, L = 1.5;
  const Capsule ca(kC, kAxis, r, L);
  const Surface s = ca;
  const Vec3 e2 = ca.frame().e2;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, -1, 3), Vec3(0.5, 0.5, 1.5), Vec3(kC + 2 * e2), Vec3(kC - 0.1 * e2)}) {
    const double d = segment_distance(p, kC, e2, L);
    EXPECT_NEAR(f(s, p), (d * d - r * r) / (2 * r), 1e-14);
  }
  const double end = L / 2 + kPi * r / 2;
  EXPECT_NEAR(s.domain().v.hi, end, 1e-15);
  expect_vec(point(s, 0.3, end), kC + (L / 2 + r) * e2, 1e-14);
  expect_vec(point(s, 0.3, -end), kC - (L / 2 + r) * e2, 1e-14);
  EXPECT_FALSE(unit_normal(s, 0.3, end));  // pole
  // C1 at the joins: value and first derivatives continue, second derivatives jump by 1/r.
  for (double join : {-L / 2, L / 2}) {
    const auto a = parametric_jet<2>(s, 1.0, join - 1e-12), b = parametric_jet<2>(s, 1.0, join + 1e-12);
    expect_vec(partial(a, 0, 0), partial(b, 0, 0), 1e-11);
    expect_vec(partial(a, 0, 1), partial(b, 0, 1), 1e-11);
    expect_vec(partial(a, 1, 0), partial(b, 1, 0), 1e-11);
    EXPECT_NEAR((partial(a, 0, 2) - partial(b, 0, 2)).norm(), 1 / r, 1e-9);
  }
  // Arc-length meridian: |Fv| = 1 everywhere.
  for (double v : {-1.8, -1.0, -0.2, 0.5, 1.3}) EXPECT_NEAR(partial(parametric_jet<1>(s, 2.0, v), 0, 1).norm(), 1, 1e-14);
}

TEST(Primitives, RejectInvalidParameters) {
  EXPECT_THROW(Sphere(kC, 0.0), InputError);
  EXPECT_THROW(Sphere(kC, -1.0), InputError);
  EXPECT_THROW(Sphere(kC, NAN), InputError);
  EXPECT_THROW(Sphere(kC, 1.0, Vec3::Zero()), InputError);
  EXPECT_THROW(Cylinder(kC, kAxis, 1.0, {2, 2}), InputError);
  EXPECT_THROW(Cylinder(kC, kAxis, 1.0, {3, 2}), InputError);
  EXPECT_THROW(Cylinder(kC, kAxis, INFINITY, {0, 1}), InputError);
  EXPECT_THROW(Cone(kC, kAxis, kPi / 2, {0, 1}), InputError);
  EXPECT_THROW(Cone(kC, kAxis, 0.0, {0, 1}), InputError);
  EXPECT_THROW(Torus(kC, kAxis, 1.0, 0.0), InputError);
  EXPECT_THROW(Torus(kC, kAxis, -1.0, 0.5), InputError);
  EXPECT_THROW(Ellipsoid(kC, {1, 0, 1}), InputError);
  EXPECT_THROW(Paraboloid(kC, kAxis, 0.0, 1.0), InputError);
  EXPECT_THROW(Paraboloid(kC, kAxis, 1.0, 1.0, {{0, 0}, {0, 1}}), InputError);
  EXPECT_THROW(Plane(kC, Vec3::Zero()), InputError);
  EXPECT_THROW(Capsule(kC, kAxis, 1.0, -0.1), InputError);
  EXPECT_THROW(Capsule(kC, kAxis, 0.0, 1.0), InputError);
}

}  // namespace
}  // namespace ssimarch

// Compile-time checks: every kind has the forms its header promises, for every number type.
#include "ssimarch/surface/concepts.hpp"
#include "ssimarch/surface/surface.hpp"
namespace ssimarch {
static_assert(ParametricSurface<Plane> && ImplicitSurface<Plane>);
static_assert(ParametricSurface<Sphere> && ImplicitSurface<Sphere>);
static_assert(ParametricSurface<Cylinder> && ImplicitSurface<Cylinder>);
static_assert(ParametricSurface<Cone> && ImplicitSurface<Cone>);
static_assert(ParametricSurface<Torus> && ImplicitSurface<Torus>);
static_assert(ParametricSurface<Ellipsoid> && ImplicitSurface<Ellipsoid>);
static_assert(ParametricSurface<Paraboloid> && ImplicitSurface<Paraboloid>);
static_assert(ParametricSurface<Capsule> && ImplicitSurface<Capsule>);
static_assert(ParametricSurface<ExprParametric> && !ImplicitSurface<ExprParametric>);
static_assert(!ParametricSurface<ExprImplicit> && ImplicitSurface<ExprImplicit>);
static_assert(ParametricSurface<BezierPatch> && !ImplicitSurface<BezierPatch>);
static_assert(ParametricSurface<BSplineSurface> && !ImplicitSurface<BSplineSurface>);
// Explicit instantiations of Surface's dispatch for the number types the tracer uses.
template Vec3T<double> Surface::point<double>(const double&, const double&) const;
template Vec3T<Jet<4, 1>> Surface::point<Jet<4, 1>>(const Jet<4, 1>&, const Jet<4, 1>&) const;
template Vec3T<Taylor<8>> Surface::point<Taylor<8>>(const Taylor<8>&, const Taylor<8>&) const;
template Jet<3, 4> Surface::value<Jet<3, 4>>(const Vec3T<Jet<3, 4>>&) const;
template Taylor<8> Surface::value<Taylor<8>>(const Vec3T<Taylor<8>>&) const;
}  // namespace ssimarch
