// Closed-form intersection geometry (ye-maekawa, stoyanov, willmore, tangential formulas)
// against the exact Frenet values of curves with known parameterisations.
#include "ssimarch/geometry/intersection_formulas.hpp"

#include <gtest/gtest.h>
#include "testing/matchers.hpp"

#include <random>
#include <string>

#include "geometry/test_curves.hpp"

namespace ssimarch {
namespace {

using namespace testing;

void expect_geometry(const CurveGeometry& got, const CurveGeometry& want, double tol, const std::string& what,
                     bool third_order = true) {
  EXPECT_NEAR(got.kappa, want.kappa, tol) << what;
  EXPECT_THAT(got.t, testing::IsNear(want.t, tol))
      << what << " t=" << got.t.transpose() << " want " << want.t.transpose();
  EXPECT_THAT(got.n, testing::IsNear(want.n, tol))
      << what << " n=" << got.n.transpose() << " want " << want.n.transpose();
  EXPECT_THAT(got.b, testing::IsNear(want.b, tol)) << what;
  if (third_order) {
    EXPECT_NEAR(got.tau, want.tau, tol) << what;
    EXPECT_NEAR(got.kappa_prime, want.kappa_prime, tol) << what;
  }
}

// --- seed 004 §6: Viviani's curve at P = (1/2, 1/2, sqrt2/2) --------------------------------------

const double kS2 = std::sqrt(2.0), kS3 = std::sqrt(3.0), kS6 = std::sqrt(6.0);
const Vec3 kP(0.5, 0.5, kS2 / 2);
const Vec3 kSeedT(-kS6 / 3, 0, kS3 / 3);  // the seed's orientation of t (oracle s004.tangent)

CurveGeometry viviani_truth() {
  CurveGeometry g;
  g.t = kSeedT;
  g.kappa = 2 * std::sqrt(39.0) / 9;
  g.tau = 6 * kS2 / 13;
  g.kappa_prime = 20 * std::sqrt(26.0) / 117;  // oracle s004.kappa_prime (seed orientation)
  g.n = Vec3(-std::sqrt(39.0) / 39, -2 * std::sqrt(39.0) / 13, -std::sqrt(78.0) / 39);
  g.b = Vec3(2 * std::sqrt(13.0) / 13, -std::sqrt(13.0) / 13, 2 * std::sqrt(26.0) / 13);
  return g;
}

TEST(FrenetFromDerivatives, ClosedFormsOfHelixAndViviani) {
  // Helix (a cos t, a sin t, c t): kappa = a/(a^2+c^2), tau = c/(a^2+c^2) (right-handed: > 0).
  for (double t0 : {0.0, 0.7, -2.1}) {
    CurveGeometry h = exact_frenet(Helix{}, t0);
    double a = HelixData::a, c = HelixData::c;
    ASSERT_EQ(h.status, GeometryStatus::kOk);
    EXPECT_NEAR(h.kappa, a / (a * a + c * c), 1e-15);
    EXPECT_NEAR(h.tau, c / (a * a + c * c), 1e-15);
    EXPECT_NEAR(h.kappa_prime, 0.0, 1e-15);
  }
  CurveGeometry v = exact_frenet(Viviani{}, std::numbers::pi / 2);
  EXPECT_THAT(v.point, testing::IsNear(kP, 1e-15));
  expect_geometry(v, viviani_truth(), 1e-14, "viviani closed form");
  // A straight line has no frame: status, not zeros.
  CurveGeometry line = frenet_from_derivatives(Vec3(1, 2, 3), Vec3(2, 4, 6), Vec3(0, 0, 0));
  EXPECT_EQ(line.status, GeometryStatus::kZeroCurvature);
  EXPECT_TRUE(std::isnan(line.tau));
  EXPECT_TRUE(std::isnan(line.n.x()));
  EXPECT_EQ(frenet_from_derivatives(Vec3::Zero(), Vec3(1, 0, 0), Vec3::Zero()).status, GeometryStatus::kNonFinite);
}

TEST(Viviani, SeedValuesByEveryClosedFormMethod) {
  const CurveGeometry want = viviani_truth();
  const SurfaceLocal f = implicit_local(UnitSphereImplicit{}, kP);
  const SurfaceLocal g = implicit_local(VivianiCylinderImplicit{}, kP);
  const double pi = std::numbers::pi;
  const SurfaceLocal fp = parametric_local(UnitSphereParametric{}, pi / 4, pi / 4);
  const SurfaceLocal gp = parametric_local(VivianiCylinderParametric{}, pi / 2, kS2 / 2);
  ASSERT_THAT(local_point(fp), testing::IsNear(kP, 1e-15));
  ASSERT_THAT(local_point(gp), testing::IsNear(kP, 1e-15));

  // Intermediate values of seed 004 (oracle s004.normal_curvatures, s004.lambda_third, s004.alpha3).
  const Vec3 nf = unit_normal(f), ng = unit_normal(g);
  EXPECT_NEAR(normal_curvature(f, kSeedT, nf), -1.0, 1e-14);
  EXPECT_NEAR(normal_curvature(g, kSeedT, ng), -4.0 / 3.0, 1e-14);
  const Vec3 c2 = want.kappa * want.n;
  EXPECT_THAT(c2, testing::IsNear(Vec3(-2.0 / 9, -4.0 / 3, -2 * kS2 / 9), 1e-14));
  EXPECT_NEAR(third_normal(f, kSeedT, c2, nf), 0.0, 1e-14);
  EXPECT_NEAR(third_normal(g, kSeedT, c2, ng), -4 * kS6 / 9, 1e-14);
  // The same projections on the parametric forms.
  EXPECT_NEAR(normal_curvature(fp, kSeedT, nf), -1.0, 1e-14);
  EXPECT_NEAR(normal_curvature(gp, kSeedT, ng), -4.0 / 3.0, 1e-14);
  EXPECT_NEAR(third_normal(gp, kSeedT, c2, ng), -4 * kS6 / 9, 1e-14);

  const double tol = 1e-12;
  for (auto [name, a, b] : {std::tuple{"implicit-implicit", f, g}, std::tuple{"parametric-implicit", fp, g},
                            std::tuple{"parametric-parametric", fp, gp}, std::tuple{"implicit-parametric", f, gp}}) {
    CurveGeometry ym = ye_maekawa_transversal(a, b, &kSeedT, {});
    ASSERT_EQ(ym.status, GeometryStatus::kOk) << name;
    expect_geometry(ym, want, tol, std::string("ye-maekawa ") + name);
    EXPECT_NEAR(ym.theta, std::acos(0.5), 1e-14);  // oracle s004.cos_theta
    CurveGeometry st = stoyanov(a, b, &kSeedT, {});
    ASSERT_EQ(st.status, GeometryStatus::kOk) << name;
    expect_geometry(st, want, tol, std::string("stoyanov ") + name);
    EXPECT_EQ(ye_maekawa(a, b, &kSeedT, {}).status, GeometryStatus::kOk);
  }
  CurveGeometry w = willmore(std::get<ImplicitLocal>(f), std::get<ImplicitLocal>(g), &kSeedT, {});
  ASSERT_EQ(w.status, GeometryStatus::kOk);
  expect_geometry(w, want, tol, "willmore");
  // Reversing the orientation flips b and kappa' only.
  const Vec3 minus_t = -kSeedT;
  CurveGeometry wr = willmore(std::get<ImplicitLocal>(f), std::get<ImplicitLocal>(g), &minus_t, {});
  CurveGeometry yr = ye_maekawa_transversal(f, g, &minus_t, {});
  for (const CurveGeometry& r : {wr, yr}) {
    EXPECT_NEAR(r.kappa_prime, -want.kappa_prime, tol);
    EXPECT_NEAR(r.tau, want.tau, tol);
    EXPECT_THAT(r.n, testing::IsNear(want.n, tol));
    EXPECT_LT((r.b + want.b).norm(), tol);
  }
}

// --- random points on curves with known parameterisations ---------------------------------------

struct PairAtPoint {
  std::string name;
  SurfaceLocal first, second;
  CurveGeometry truth;
};

// Every pair kind the closed-form curves allow, at curve parameter s.
std::vector<PairAtPoint> pairs_at(double s) {
  std::vector<PairAtPoint> r;
  const double pi = std::numbers::pi;
  {  // torus knot = ruled surface F1 cap torus G1 (thesis pair 1)
    CurveGeometry truth = exact_frenet(TorusKnot{}, s);
    r.push_back({"torus-knot", parametric_local(RuledF1{}, s, 0.0), parametric_local(TorusG1{}, 4 * s, pi / 2 - s), truth});
  }
  {  // Viviani
    CurveGeometry truth = exact_frenet(Viviani{}, s);
    Vec3 p = truth.point;
    auto sp = parametric_local(UnitSphereParametric{}, viviani_sphere_u(s), viviani_sphere_v(s));
    auto cp = parametric_local(VivianiCylinderParametric{}, s, std::sin(s / 2));
    auto si = implicit_local(UnitSphereImplicit{}, p);
    auto ci = implicit_local(VivianiCylinderImplicit{}, p);
    r.push_back({"viviani ii", si, ci, truth});
    r.push_back({"viviani pi", sp, ci, truth});
    r.push_back({"viviani pp", sp, cp, truth});
  }
  {  // plane cap ellipsoid
    Ellipse e;
    CurveGeometry truth = exact_frenet(e, s);
    Vec3 p = truth.point;
    double sv = std::asin(EllipseData::h / EllipseData::c);
    auto pp = parametric_local(PlaneParametric{}, EllipseData::A() * std::cos(s), EllipseData::B() * std::sin(s));
    auto ep = parametric_local(EllipsoidParametric{}, s, sv);
    auto pi_ = implicit_local(PlaneImplicit{}, p);
    auto ei = implicit_local(EllipsoidImplicit{}, p);
    r.push_back({"ellipse ii", pi_, ei, truth});
    r.push_back({"ellipse pi", pp, ei, truth});
    r.push_back({"ellipse pp", pp, ep, truth});
    r.push_back({"ellipse ip", ep, pi_, truth});
  }
  {  // cylinder cap helicoid
    CurveGeometry truth = exact_frenet(Helix{}, s);
    auto cyl = parametric_local(HelixCylinderParametric{}, s, HelixData::c * s);
    auto hel = parametric_local(Helicoid{}, s, HelixData::a);
    auto cyli = implicit_local(HelixCylinderImplicit{}, truth.point);
    r.push_back({"helix pp", cyl, hel, truth});
    r.push_back({"helix pi", hel, cyli, truth});
  }
  for (auto& pr : r)
    EXPECT_THAT(local_point(pr.first), testing::IsNear(local_point(pr.second), 1e-13)) << pr.name << " s=" << s;
  return r;
}

TEST(RandomCurvePoints, ClosedFormMethodsAgreeWithExactFrenet) {
  std::mt19937 rng(20240504);
  std::uniform_real_distribution<double> param(-3.0, 3.0);
  int checked = 0;
  double min_sin = 1;
  for (int trial = 0; trial < 60; ++trial) {
    double s = param(rng);
    for (const PairAtPoint& pr : pairs_at(s)) {
      double sin_theta = unit_normal(pr.first).cross(unit_normal(pr.second)).norm();
      if (sin_theta < 0.02) continue;  // the neighbourhood of Viviani's double point: see the singular tests
      min_sin = std::min(min_sin, sin_theta);
      const Vec3& o = pr.truth.t;
      std::string what = pr.name + " s=" + std::to_string(s);
      CurveGeometry ym = ye_maekawa_transversal(pr.first, pr.second, &o, {});
      ASSERT_EQ(ym.status, GeometryStatus::kOk) << what;
      expect_geometry(ym, pr.truth, 1e-9, "ye-maekawa " + what);
      CurveGeometry st = stoyanov(pr.first, pr.second, &o, {});
      ASSERT_EQ(st.status, GeometryStatus::kOk) << what;
      expect_geometry(st, pr.truth, 1e-9, "stoyanov " + what);
      if (std::holds_alternative<ImplicitLocal>(pr.first) && std::holds_alternative<ImplicitLocal>(pr.second)) {
        CurveGeometry w = willmore(std::get<ImplicitLocal>(pr.first), std::get<ImplicitLocal>(pr.second), &o, {});
        ASSERT_EQ(w.status, GeometryStatus::kOk) << what;
        expect_geometry(w, pr.truth, 1e-9, "willmore " + what);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
  EXPECT_LT(min_sin, 0.2);  // the sample does reach fairly small angles
}

TEST(Thesis, YeMaekawaReproducesTheOracleOnPairs1And2) {
  // oracle s003.eq3.14-3.25.C1 (s = 0), .C1_s0.3 and .C2_s0.7: thesis-sign tau, tangent along
  // the parameterisation.
  struct Case {
    double s;
    bool c1;
    double kappa, tau_thesis, kappa_prime;
  };
  const double pi = std::numbers::pi;
  for (Case c : {Case{0.0, true, 0.5121951219512195, 0.12543554006968635, 0.0},
                 Case{0.3, true, 0.5518179814230774, 0.3044603598204498, 0.03157105814390908},
                 Case{0.7, false, 0.5353623855077453, -0.36851328835125413, 0.07550017733487413}}) {
    SurfaceLocal a, b;
    Vec3 o;
    if (c.c1) {
      a = parametric_local(RuledF1{}, c.s, 0.0);
      b = parametric_local(TorusG1{}, 4 * c.s, pi / 2 - c.s);
      o = curve_tangent(TorusKnot{}, c.s);
    } else {
      a = parametric_local(CylinderF2{}, c.s, 2 * std::sin(c.s / 2));
      b = parametric_local(SphereG2{}, c.s / 2, c.s / 2);
      o = curve_tangent(CurveC2{}, c.s);
    }
    CurveGeometry g = ye_maekawa_transversal(a, b, &o, {});
    ASSERT_EQ(g.status, GeometryStatus::kOk);
    EXPECT_NEAR(g.kappa, c.kappa, 1e-12);
    EXPECT_NEAR(g.tau_do_carmo(), c.tau_thesis, 1e-12);
    EXPECT_NEAR(g.kappa_prime, c.kappa_prime, 1e-12);
  }
}

// --- tangential points ----------------------------------------------------------------------------

TEST(Tangential, SphereCylinderDoublePointC2) {
  // C2(0) = (1,-1,0): cylinder and sphere tangent; two branches C2(s) and its mirror z -> -z.
  const CurveGeometry b1 = exact_frenet(CurveC2{}, 0.0);
  auto mirror = [](const auto& s) {
    auto q = CurveC2{}(s);
    q.z = -q.z;
    return q;
  };
  const CurveGeometry b2 = exact_frenet(mirror, 0.0);
  const Vec3 p(1, -1, 0);
  const SurfaceLocal fp = parametric_local(CylinderF2{}, 0.0, 0.0), gp = parametric_local(SphereG2{}, 0.0, 0.0);
  const SurfaceLocal fi = implicit_local(CylinderF2Implicit{}, p), gi = implicit_local(SphereG2Implicit{}, p);
  EXPECT_EQ(ye_maekawa_transversal(fp, gp, nullptr, {}).status, GeometryStatus::kSingular);
  EXPECT_EQ(willmore(std::get<ImplicitLocal>(fi), std::get<ImplicitLocal>(gi), nullptr, {}).status,
            GeometryStatus::kSingular);
  for (auto [name, a, b] : {std::tuple{"pp thesis", fp, gp}, std::tuple{"ii", fi, gi}, std::tuple{"pi", fp, gi},
                            std::tuple{"ip", fi, gp}}) {
    for (const CurveGeometry* want : {&b1, &b2}) {
      CurveGeometry g = ye_maekawa(a, b, &want->t, {});
      ASSERT_EQ(g.status, GeometryStatus::kTangentialSecondOrder) << name;
      expect_geometry(g, *want, 1e-12, std::string("tangential ") + name, false);
      EXPECT_NEAR(g.kappa, 0.5, 1e-12);
      EXPECT_TRUE(std::isnan(g.tau));
      EXPECT_TRUE(std::isnan(g.kappa_prime));
      EXPECT_NEAR(std::sin(g.theta), 0.0, 1e-15);
    }
    std::vector<CurveGeometry> branches = ye_maekawa_tangential(a, b, nullptr, {});
    EXPECT_EQ(branches.size(), 2u) << name;
    Vec3 t = intersection_tangent(a, b, &b1.t, {});
    EXPECT_THAT(t, testing::IsNear(b1.t, 1e-12)) << name;
  }
}

// The oracle's tangential test pair (s003.eq3.5.b12_factor, s003.eq3.18-3.22.a13_sign): graphs of
// f, g over sheared parameterisations, tangent at the origin; exact branch curvatures from series.
struct GraphF {
  template <class T>
  T height(const T& x, const T& y) const {
    return 2.0 * x * x - y * y + x * x * x + 0.5 * x * y * y + 0.3 * x * y;
  }
  template <class T>
  Vec3T<T> operator()(const T& u, const T& v) const {
    T x = u + 0.1 * v * v, y = v + 0.2 * u * u + 0.1 * u * v;
    return {x, y, height(x, y)};
  }
};
struct GraphG {
  template <class T>
  T height(const T& x, const T& y) const {
    return 0.5 * x * x + 0.3 * x * y + 0.3 * y * y + 0.2 * x * x * x;
  }
  template <class T>
  Vec3T<T> operator()(const T& p, const T& q) const {
    T x = p + 0.3 * q + 0.2 * p * p, y = q - 0.2 * p + 0.1 * p * q;
    return {x, y, height(x, y)};
  }
};
struct GraphFImplicit {
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return p.z - GraphF{}.height(p.x, p.y);
  }
};
struct GraphGImplicit {
  template <class T>
  T operator()(const Vec3T<T>& p) const {
    return GraphG{}.height(p.x, p.y) - p.z;  // opposite normal on purpose
  }
};

TEST(Tangential, OraclePairBothFormsMatchTheExactBranches) {
  const std::array<double, 2> exact{0.57790102041, 1.12890141672};  // oracle, 11 digits
  const SurfaceLocal fp = parametric_local(GraphF{}, 0.0, 0.0), gp = parametric_local(GraphG{}, 0.0, 0.0);
  const SurfaceLocal fi = implicit_local(GraphFImplicit{}, Vec3::Zero()),
                     gi = implicit_local(GraphGImplicit{}, Vec3::Zero());
  std::vector<std::vector<CurveGeometry>> results{ye_maekawa_tangential_thesis(std::get<ParametricLocal>(fp),
                                                                               std::get<ParametricLocal>(gp), nullptr, {}),
                                                  ye_maekawa_tangential(fi, gi, nullptr, {}),
                                                  ye_maekawa_tangential(fp, gi, nullptr, {}),
                                                  ye_maekawa_tangential(fi, gp, nullptr, {})};
  for (const auto& branches : results) {
    ASSERT_EQ(branches.size(), 2u);
    std::array<double, 2> k{branches[0].kappa, branches[1].kappa};
    std::sort(k.begin(), k.end());
    EXPECT_NEAR(k[0], exact[0], 1e-10);
    EXPECT_NEAR(k[1], exact[1], 1e-10);
  }
  // The thesis form and the parameter-free form give the same curvature vectors.
  for (const CurveGeometry& a : results[0]) {
    bool found = false;
    for (const CurveGeometry& b : results[1])
      if (std::fabs(std::fabs(a.t.dot(b.t)) - 1) < 1e-12) {
        found = true;
        EXPECT_THAT(a.kappa * a.n, testing::IsNear(b.kappa * b.n, 1e-12));
      }
    EXPECT_TRUE(found);
  }
}

TEST(Tangential, IsolatedPointAndHigherContact) {
  // Sphere touching a plane from one side: II_F - II_G definite -> isolated point.
  auto plane = [](const auto& p) { return p.z - 1.0; };
  const SurfaceLocal s = implicit_local(UnitSphereImplicit{}, Vec3(0, 0, 1)), pl = implicit_local(plane, Vec3(0, 0, 1));
  auto r = ye_maekawa_tangential(s, pl, nullptr, {});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].status, GeometryStatus::kIsolatedPoint);
  EXPECT_FALSE(r[0].has_tangent());
  // A surface against itself: II_F = II_G.
  auto same = ye_maekawa_tangential(s, s, nullptr, {});
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].status, GeometryStatus::kHigherOrderContact);
  EXPECT_EQ(ye_maekawa(s, s, nullptr, {}).status, GeometryStatus::kHigherOrderContact);
  EXPECT_FALSE(intersection_tangent(s, pl, nullptr, {}).allFinite());
}

TEST(Transversal, PlanarCurveHasZeroTorsionAndStraightLineReportsZeroCurvature) {
  // Two planes: a straight line, kappa = 0 -> kZeroCurvature with NaN frame, never zeros.
  auto p1 = [](const auto& p) { return p.z; };
  auto p2 = [](const auto& p) { return p.x + p.y; };
  const SurfaceLocal a = implicit_local(p1, Vec3::Zero()), b = implicit_local(p2, Vec3::Zero());
  for (const CurveGeometry& g : {ye_maekawa_transversal(a, b, nullptr, {}), stoyanov(a, b, nullptr, {}),
                                 willmore(std::get<ImplicitLocal>(a), std::get<ImplicitLocal>(b), nullptr, {})}) {
    EXPECT_EQ(g.status, GeometryStatus::kZeroCurvature);
    EXPECT_NEAR(g.kappa, 0.0, 1e-15);
    EXPECT_TRUE(g.has_tangent());
    EXPECT_FALSE(g.has_frame());
    EXPECT_TRUE(std::isnan(g.tau));
  }
  // Non-finite input data.
  ImplicitLocal bad = std::get<ImplicitLocal>(a);
  bad.hess(0, 0) = kNaN;
  EXPECT_EQ(ye_maekawa_transversal(bad, b, nullptr, {}).status, GeometryStatus::kNonFinite);
}

TEST(Methods, NamesRoundTrip) {
  for (GeometryMethod m : {GeometryMethod::kExact, GeometryMethod::kYeMaekawa, GeometryMethod::kWillmore,
                           GeometryMethod::kStoyanov, GeometryMethod::kEstimate, GeometryMethod::kBarnhillKersey,
                           GeometryMethod::kMixed}) {
    GeometryMethod back = GeometryMethod::kExact;
    ASSERT_TRUE(parse(to_string(m), &back));
    EXPECT_EQ(back, m);
  }
  GeometryMethod m = GeometryMethod::kMixed;
  EXPECT_FALSE(parse("yemaekawa", &m));
  EXPECT_EQ(m, GeometryMethod::kMixed);
}

}  // namespace
}  // namespace ssimarch
