// evaluate_geometry on Problems (every method, every pair kind), the exact method through
// curve_jet, the estimate from traced samples, projection and sampling along the curve.
#include "ssimarch/geometry/intersection_geometry.hpp"

#include <gtest/gtest.h>

#include <random>

#include "geometry/test_curves.hpp"
#include "testing/matchers.hpp"
#include "ssimarch/surface/expr_surface.hpp"

namespace ssimarch {
namespace {

using namespace testing;

const double kPi = std::numbers::pi;
const Box kBox{{-8, 8}, {-8, 8}, {-8, 8}};

Surface implicit(const std::string& f) { return ExprImplicit::compile(f, kBox, {}); }
Surface parametric(const std::array<std::string, 3>& xyz, ParamDomain d) { return ExprParametric::compile(xyz, d, {}); }

const ParamDomain kSphereDomain{{0, 2 * kPi}, {-kPi / 2, kPi / 2}, true, false};
const ParamDomain kCircleTimesLine{{0, 2 * kPi}, {-3, 3}, true, false};

Problem viviani(PairKind kind) {
  Surface sphere_i = implicit("x^2+y^2+z^2-1"), cyl_i = implicit("x^2+y^2-x");
  Surface sphere_p = parametric({"cos(v)*cos(u)", "cos(v)*sin(u)", "sin(v)"}, kSphereDomain);
  Surface cyl_p = parametric({"0.5+cos(u)/2", "sin(u)/2", "v"}, kCircleTimesLine);
  switch (kind) {
    case PairKind::kImplicitImplicit: return Problem(sphere_i, cyl_i, kind);
    case PairKind::kParametricImplicit: return Problem(sphere_p, cyl_i, kind);
    default: return Problem(sphere_p, cyl_p, kind);
  }
}
VecX viviani_x(PairKind kind, double t) {
  Vec3 p = curve_point(Viviani{}, t);
  VecX x;
  if (kind == PairKind::kImplicitImplicit) return p;
  x.resize(kind == PairKind::kParametricImplicit ? 2 : 4);
  x[0] = viviani_sphere_u(t);
  x[1] = viviani_sphere_v(t);
  if (x.size() == 4) {
    x[2] = t;
    x[3] = std::sin(t / 2);
  }
  return x;
}

// Thesis pair 1 (ruled surface / torus) and pair 2 (cylinder / sphere about (-1,-1,0)).
Problem pair1() {
  Surface f1 = parametric({"(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)",
                           "(4+cos(4*u))*sin(u) + v*(cos(4*u)+sin(4*u))*sin(u)", "sin(4*u) + v*(sin(4*u)-cos(4*u))"},
                          {{0, 2 * kPi}, {-0.5, 0.5}, true, false});
  Surface g1 = parametric({"(4+cos(u))*sin(v)", "(4+cos(u))*cos(v)", "sin(u)"}, {{0, 2 * kPi}, {0, 2 * kPi}, true, true});
  return Problem(f1, g1, PairKind::kParametricParametric);
}
VecX pair1_x(double s) {
  VecX x(4);
  x << s, 0.0, 4 * s, kPi / 2 - s;
  return x;
}
Problem pair2(PairKind kind) {
  if (kind == PairKind::kImplicitImplicit)
    return Problem(implicit("x^2+(y+1)^2-1"), implicit("(x+1)^2+(y+1)^2+z^2-4"), kind);
  Surface f2 = parametric({"cos(u)", "sin(u)-1", "v"}, kCircleTimesLine);
  Surface g2 = parametric({"-1+2*cos(u)*cos(v)", "-1+2*cos(u)*sin(v)", "2*sin(u)"},
                          {{-kPi / 2, kPi / 2}, {-kPi, kPi}, false, true});
  return Problem(f2, g2, kind);
}
VecX pair2_x(PairKind kind, double s) {
  if (kind == PairKind::kImplicitImplicit) return curve_point(CurveC2{}, s);
  VecX x(4);
  x << s, 2 * std::sin(s / 2), s / 2, s / 2;
  return x;
}

void expect_geometry(const CurveGeometry& got, const CurveGeometry& want, double tol, const std::string& what) {
  EXPECT_NEAR(got.kappa, want.kappa, tol) << what;
  EXPECT_NEAR(got.tau, want.tau, tol) << what;
  EXPECT_NEAR(got.kappa_prime, want.kappa_prime, tol) << what;
  EXPECT_THAT(got.t, testing::IsNear(want.t, tol)) << what;
  EXPECT_THAT(got.n, testing::IsNear(want.n, tol)) << what;
  EXPECT_THAT(got.b, testing::IsNear(want.b, tol)) << what;
}

const std::array<GeometryMethod, 3> kClosedForm{GeometryMethod::kExact, GeometryMethod::kYeMaekawa,
                                                GeometryMethod::kStoyanov};

TEST(EvaluateGeometry, SeedVivianiAllMethodsAllPairKinds) {
  const double t0 = kPi / 2;  // P = (1/2, 1/2, sqrt2/2)
  const CurveGeometry want = exact_frenet(Viviani{}, t0);
  ASSERT_NEAR(want.kappa, 2 * std::sqrt(39.0) / 9, 1e-15);
  ASSERT_NEAR(want.tau, 6 * std::sqrt(2.0) / 13, 1e-15);
  for (PairKind kind : {PairKind::kImplicitImplicit, PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
    Problem pb = viviani(kind);
    VecX x = viviani_x(kind, t0);
    ASSERT_THAT(pb.point(x), testing::IsNear(want.point, 1e-15));
    GeometryContext ctx;
    ctx.orientation = want.t;
    for (GeometryMethod m : kClosedForm) {
      CurveGeometry g = evaluate_geometry(pb, x, m, ctx);
      std::string what = std::string(to_string(m)) + " " + std::string(to_string(kind));
      ASSERT_EQ(g.status, GeometryStatus::kOk) << what;
      expect_geometry(g, want, 1e-12, what);
      EXPECT_NEAR(g.theta, kPi / 3, 1e-14) << what;
      EXPECT_THAT(g.point, testing::IsNear(want.point, 1e-15));
    }
    CurveGeometry w = evaluate_geometry(pb, x, GeometryMethod::kWillmore, ctx);
    if (kind == PairKind::kImplicitImplicit) {
      ASSERT_EQ(w.status, GeometryStatus::kOk);
      expect_geometry(w, want, 1e-12, "willmore");
    } else {
      EXPECT_EQ(w.status, GeometryStatus::kNotApplicable);  // expression surfaces: one form each
      EXPECT_TRUE(std::isnan(w.kappa));
    }
    // mixed = ye-maekawa here (sin theta = 0.87 >= 0.1).
    CurveGeometry mixed = evaluate_geometry(pb, x, GeometryMethod::kMixed, ctx);
    expect_geometry(mixed, want, 1e-12, "mixed");
    // The estimate from samples along the curve converges (first order with kappa' != 0).
    double last = 1e300;
    for (double step : {1e-2, 1e-3, 1e-4}) {
      GeometryContext sc = sample_context(pb, x, step, &want.t);
      ASSERT_EQ(sc.previous.size(), 2u);
      ASSERT_EQ(sc.next.size(), 1u);
      for (GeometryMethod m : {GeometryMethod::kEstimate, GeometryMethod::kBarnhillKersey}) {
        CurveGeometry e = evaluate_geometry(pb, x, m, sc);
        ASSERT_EQ(e.status, GeometryStatus::kOk);
        double err = std::max({std::fabs(e.kappa - want.kappa), std::fabs(e.tau - want.tau),
                               std::fabs(e.kappa_prime - want.kappa_prime)});
        EXPECT_LT(err, 5 * step) << to_string(m) << " step " << step;
        EXPECT_THAT(e.t, testing::IsNear(want.t, 1e-12));
        if (m == GeometryMethod::kEstimate) {
          EXPECT_LT(err, last);
          last = err;
        }
      }
    }
  }
}

TEST(EvaluateGeometry, RandomPointsOnTorusKnotAndViviani) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> param(0.0, 2 * kPi);
  Problem p1 = pair1();
  for (int i = 0; i < 25; ++i) {
    double s = param(rng);
    CurveGeometry want = exact_frenet(TorusKnot{}, s);
    GeometryContext ctx;
    ctx.orientation = want.t;
    for (GeometryMethod m : kClosedForm) {
      CurveGeometry g = evaluate_geometry(p1, pair1_x(s), m, ctx);
      ASSERT_EQ(g.status, GeometryStatus::kOk) << to_string(m) << " s=" << s << " theta=" << g.theta;
      expect_geometry(g, want, 1e-9, std::string(to_string(m)) + " torus knot s=" + std::to_string(s));
    }
  }
  for (PairKind kind : {PairKind::kImplicitImplicit, PairKind::kParametricImplicit, PairKind::kParametricParametric}) {
    Problem pb = viviani(kind);
    for (int i = 0; i < 24; ++i) {
      // Away from the double point (t = 0, 2 pi) and from the sphere's parametric pole (t = pi).
      double t = 0.3 + (2 * kPi - 0.6) * (i + 0.5) / 24.0;
      CurveGeometry want = exact_frenet(Viviani{}, t);
      GeometryContext ctx;
      ctx.orientation = want.t;
      for (GeometryMethod m : kClosedForm) {
        CurveGeometry g = evaluate_geometry(pb, viviani_x(kind, t), m, ctx);
        ASSERT_EQ(g.status, GeometryStatus::kOk) << to_string(m) << " " << to_string(kind) << " t=" << t;
        expect_geometry(g, want, 1e-9, std::string(to_string(m)) + " viviani t=" + std::to_string(t));
      }
    }
  }
}

TEST(EvaluateGeometry, HelixAsCylinderAndHelicoid) {
  Problem pb(parametric({"v*cos(u)", "v*sin(u)", "0.4*u"}, {{-10, 10}, {-3, 3}, false, false}),
             implicit("x^2+y^2-2.25"), PairKind::kParametricImplicit);
  for (double t : {-1.0, 0.2, 2.5}) {
    VecX x(2);
    x << t, HelixData::a;
    CurveGeometry want = exact_frenet(Helix{}, t);
    GeometryContext ctx;
    ctx.orientation = want.t;
    for (GeometryMethod m : kClosedForm) expect_geometry(evaluate_geometry(pb, x, m, ctx), want, 1e-9, "helix");
  }
}

// Table 3.3 through the whole pipeline: samples at parameter offsets +-ds as in the thesis,
// tangents from the surfaces (at C2(0) from the tangential formulas).
TEST(Table33, EstimateConvergesAtC1AndAtTheSingularPointC2) {
  struct Case {
    std::string name;
    Problem problem;
    std::function<VecX(double)> x;
    CurveGeometry exact;
  };
  std::vector<Case> cases;
  cases.push_back({"C1(0)", pair1(), pair1_x, exact_frenet(TorusKnot{}, 0.0)});
  for (PairKind kind : {PairKind::kParametricParametric, PairKind::kImplicitImplicit})
    cases.push_back({"C2(0) " + std::string(to_string(kind)), pair2(kind),
                     [kind](double s) { return pair2_x(kind, s); }, exact_frenet(CurveC2{}, 0.0)});
  ASSERT_NEAR(cases[0].exact.kappa, 0.5122, 5e-5);
  ASSERT_NEAR(std::fabs(cases[0].exact.tau), 0.1254, 5e-5);
  ASSERT_NEAR(cases[1].exact.kappa, 0.5, 1e-15);
  ASSERT_NEAR(std::fabs(cases[1].exact.tau), 0.375, 1e-15);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    double last_k = 1e300, last_t = 1e300;
    for (double ds : {0.2, 0.1, 0.01, 0.001}) {
      GeometryContext ctx;
      ctx.previous = {c.x(-ds)};
      ctx.next = {c.x(ds)};
      CurveGeometry g = evaluate_geometry(c.problem, c.x(0.0), GeometryMethod::kEstimate, ctx);
      ASSERT_EQ(g.status, GeometryStatus::kOk) << ds;
      double ek = std::fabs(g.kappa - c.exact.kappa), et = std::fabs(g.tau - c.exact.tau);
      EXPECT_LT(ek, std::max(last_k, 1e-9));
      EXPECT_LT(et, std::max(last_t, 1e-9));
      last_k = ek;
      last_t = et;
      EXPECT_THAT(g.t, testing::IsNear(c.exact.t, 1e-12));
      // mixed = the estimate wherever sin(theta) < 0.1, in particular at C2(0).
      if (c.name != "C1(0)") {
        CurveGeometry m = evaluate_geometry(c.problem, c.x(0.0), GeometryMethod::kMixed, ctx);
        EXPECT_EQ(m.kappa, g.kappa);
        EXPECT_EQ(m.tau, g.tau);
      }
    }
    EXPECT_LT(last_k, 1e-5);
    EXPECT_LT(last_t, 1e-5);
  }
  // At the singular point itself: exact and the transversal formulas report it, Ye-Maekawa's
  // tangential formulas give t, n, b, kappa but no third order.
  Problem p2 = pair2(PairKind::kParametricParametric);
  VecX x0 = pair2_x(PairKind::kParametricParametric, 0.0);
  GeometryContext ctx;
  ctx.orientation = cases[1].exact.t;
  EXPECT_EQ(evaluate_geometry(p2, x0, GeometryMethod::kExact, ctx).status, GeometryStatus::kSingular);
  EXPECT_EQ(evaluate_geometry(p2, x0, GeometryMethod::kStoyanov, ctx).status, GeometryStatus::kSingular);
  CurveGeometry ym = evaluate_geometry(p2, x0, GeometryMethod::kYeMaekawa, ctx);
  EXPECT_EQ(ym.status, GeometryStatus::kTangentialSecondOrder);
  EXPECT_NEAR(ym.kappa, 0.5, 1e-12);
  EXPECT_TRUE(std::isnan(ym.tau));
  EXPECT_THAT(ym.t, testing::IsNear(cases[1].exact.t, 1e-12));
}

TEST(Sampling, ProjectAndWalkAlongTheCurveThroughASingularPoint) {
  Problem pb = viviani(PairKind::kImplicitImplicit);
  const Vec3 P = curve_point(Viviani{}, kPi / 2);
  auto x = project_to_curve(pb, P + Vec3(3e-3, -2e-3, 1e-3));
  ASSERT_TRUE(x.has_value());
  EXPECT_LT(pb.linearize(*x).distance, 1e-12);
  EXPECT_THAT(pb.point(*x), testing::IsNear(P, 1e-2));
  // At the double point C2(0) the samples stay on the branch of the given tangent.
  for (PairKind kind : {PairKind::kParametricParametric, PairKind::kImplicitImplicit}) {
    Problem p2 = pair2(kind);
    const CurveGeometry exact = exact_frenet(CurveC2{}, 0.0);
    // Step 1e-2, not smaller: near a singular point a sample's position error (rounding of
    // Newton) grows by 1/sin(theta) in its tangent, and the torsion divides that by step^2.
    GeometryContext sc = sample_context(p2, pair2_x(kind, 0.0), 1e-2, &exact.t);
    ASSERT_EQ(sc.previous.size(), 2u);
    ASSERT_EQ(sc.next.size(), 1u);
    for (const VecX& xi : sc.previous) {
      Vec3 p = p2.point(xi);
      EXPECT_LT(p.z(), 0.0);  // C2(s<0) has z < 0, its mirror branch z > 0
      EXPECT_THAT(p, testing::IsNear(curve_point(CurveC2{}, 2 * std::asin(p.z() / 2)), 1e-12));
    }
    EXPECT_GT(p2.point(sc.next[0]).z(), 0.0);
    CurveGeometry e = evaluate_geometry(p2, pair2_x(kind, 0.0), GeometryMethod::kEstimate, sc);
    ASSERT_EQ(e.status, GeometryStatus::kOk);
    EXPECT_NEAR(e.kappa, 0.5, 1e-5);
    EXPECT_NEAR(e.tau, 0.375, 1e-5);
    EXPECT_NEAR(e.kappa_prime, 0.0, 1e-5);
  }
  // Causal use (the tracer's): only previous samples; the estimate lags one sample.
  const Vec3 t_here = exact_frenet(Viviani{}, kPi / 2).t;
  GeometryContext causal = sample_context(pb, viviani_x(PairKind::kImplicitImplicit, kPi / 2), 1e-3, &t_here);
  causal.next.clear();
  CurveGeometry lag = evaluate_geometry(pb, viviani_x(PairKind::kImplicitImplicit, kPi / 2), GeometryMethod::kEstimate, causal);
  ASSERT_EQ(lag.status, GeometryStatus::kOk);
  EXPECT_NEAR(lag.kappa, 2 * std::sqrt(39.0) / 9, 5e-3);
  EXPECT_NEAR(lag.tau, 6 * std::sqrt(2.0) / 13, 5e-3);
  // A closed curve's closing point repeats the first: a sample equal to x is ignored.
  GeometryContext dup = sample_context(pb, viviani_x(PairKind::kImplicitImplicit, kPi / 2), 1e-3, &t_here);
  GeometryContext with_dup = dup;
  with_dup.next.insert(with_dup.next.begin(), viviani_x(PairKind::kImplicitImplicit, kPi / 2));
  CurveGeometry a = evaluate_geometry(pb, viviani_x(PairKind::kImplicitImplicit, kPi / 2), GeometryMethod::kEstimate, dup);
  CurveGeometry b = evaluate_geometry(pb, viviani_x(PairKind::kImplicitImplicit, kPi / 2), GeometryMethod::kEstimate, with_dup);
  EXPECT_EQ(b.status, GeometryStatus::kOk);
  EXPECT_EQ(a.kappa, b.kappa);
  EXPECT_EQ(a.tau, b.tau);
  // Malformed x: a status, not a crash.
  EXPECT_EQ(evaluate_geometry(pb, VecX::Zero(2), GeometryMethod::kExact).status, GeometryStatus::kNonFinite);
  VecX nan_x = VecX::Constant(3, kNaN);
  EXPECT_EQ(evaluate_geometry(pb, nan_x, GeometryMethod::kYeMaekawa).status, GeometryStatus::kNonFinite);
}

}  // namespace
}  // namespace ssimarch
