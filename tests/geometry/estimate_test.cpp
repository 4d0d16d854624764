// Tangent-only estimates (Wu-Andrade, Barnhill-Kersey, binormal turning, eq 3.27) against the
// thesis' Table 3.3 as recomputed in the oracle, and their convergence to the exact values.
#include "ssimarch/geometry/estimate.hpp"

#include <gtest/gtest.h>
#include "testing/matchers.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "geometry/test_curves.hpp"

namespace ssimarch {
namespace {

using namespace testing;

nlohmann::json oracle_entry(const std::string& id) {
  std::ifstream in(SSIMARCH_SOURCE_DIR "/tests/reference/oracle.json");
  EXPECT_TRUE(in.good());
  nlohmann::json all = nlohmann::json::parse(in);
  for (const auto& e : all)
    if (e.at("id") == id) return e;
  ADD_FAILURE() << "oracle entry " << id << " missing";
  return {};
}

template <class Curve>
std::vector<CurveSample> samples_of(const Curve& c, double s0, double ds, int before = 1, int after = 1) {
  std::vector<CurveSample> out;
  for (int k = -before; k <= after; ++k) out.push_back({curve_point(c, s0 + k * ds), curve_tangent(c, s0 + k * ds)});
  return out;
}

TEST(Circles, OracleConstructions) {
  // s003.eq3.10.literal_vs_geometric: unit circle, P at angle 0, Q at angle 0.3.
  nlohmann::json e = oracle_entry("s003.eq3.10.literal_vs_geometric");
  const double phi = 0.3;
  Vec3 p(1, 0, 0), q(std::cos(phi), std::sin(phi), 0), tp(0, 1, 0), tq(-std::sin(phi), std::cos(phi), 0);
  Circle geo = wu_andrade_circle(p, tp, q, tq, false), lit = wu_andrade_circle(p, tp, q, tq, true);
  ASSERT_TRUE(geo.valid && lit.valid);
  auto lit_want = e["value"]["literal"].get<std::vector<double>>();
  EXPECT_THAT(lit.center, testing::IsNear(Vec3(lit_want[0], lit_want[1], lit_want[2]), 1e-11));
  EXPECT_LT(geo.center.norm(), 1e-15);
  EXPECT_NEAR(geo.radius, 1.0, 1e-15);
  EXPECT_NEAR(lit.radius, 1.0, 1e-15);
  // s003.eq3.7.circumradius: Barnhill-Kersey's rho equals the circumradius.
  nlohmann::json bk = oracle_entry("s003.eq3.7.circumradius");
  auto P = bk["inputs"]["P"].get<std::vector<double>>(), Q = bk["inputs"]["Q"].get<std::vector<double>>(),
       R = bk["inputs"]["R"].get<std::vector<double>>();
  Vec3 a(P[0], P[1], P[2]), b(Q[0], Q[1], Q[2]), c(R[0], R[1], R[2]);
  Circle three = three_point_circle(a, b, c);
  ASSERT_TRUE(three.valid);
  for (const Vec3& x : {a, b, c}) EXPECT_NEAR((x - three.center).norm(), three.radius, 1e-14);
  EXPECT_NEAR(barnhill_kersey_radius(a, b, c), three.radius, 1e-14);
  // Degenerate inputs: no circle, no NaN centre reported as valid.
  EXPECT_FALSE(wu_andrade_circle(p, tp, p + tp, tp).valid);
  EXPECT_FALSE(three_point_circle(a, a + Vec3(1, 1, 1), a + Vec3(2, 2, 2)).valid);
}

TEST(Table33, LiteralWuAndradeReproducesEveryEstimatedEntry) {
  // oracle s003.t33.{C1,C2}.ds*: (kappa, tau in the thesis' sign, kappa').
  for (const char* curve : {"C1", "C2"}) {
    for (const char* ds_name : {"0.2", "0.1", "0.01", "0.001"}) {
      nlohmann::json e = oracle_entry(std::string("s003.t33.") + curve + ".ds" + ds_name);
      auto want = e["value"].get<std::vector<double>>();
      double ds = std::stod(ds_name);
      std::vector<CurveSample> s =
          std::string(curve) == "C1" ? samples_of(TorusKnot{}, 0.0, ds) : samples_of(CurveC2{}, 0.0, ds);
      CurveGeometry g = estimate_from_samples(s, 1, EstimateCircle::kWuAndradeLiteral);
      ASSERT_EQ(g.status, GeometryStatus::kOk) << curve << " " << ds;
      EXPECT_NEAR(g.kappa, want[0], 1e-10) << curve << " " << ds;
      EXPECT_NEAR(g.tau_do_carmo(), want[1], 1e-10) << curve << " " << ds;
      EXPECT_NEAR(g.kappa_prime, want[2], 1e-10) << curve << " " << ds;
    }
  }
}

template <class Curve>
void expect_convergence(const Curve& c, double s0, EstimateCircle kind, double final_tol, const std::string& what,
                        std::vector<double> steps = {0.2, 0.1, 0.01, 0.001}) {
  SCOPED_TRACE(what + " circle " + std::to_string(static_cast<int>(kind)));
  CurveGeometry exact = exact_frenet(c, s0);
  double last_k = 1e300, last_t = 1e300;
  for (double ds : steps) {
    std::vector<CurveSample> s = samples_of(c, s0, ds, 2, 1);
    CurveGeometry g = estimate_from_samples(s, 2, kind);
    ASSERT_EQ(g.status, GeometryStatus::kOk);
    double ek = std::fabs(g.kappa - exact.kappa), et = std::fabs(g.tau - exact.tau);
    // Errors shrink with the step until they reach rounding (about 1e-16 / ds^2 for tau).
    EXPECT_LT(ek, std::max(last_k, 1e-9)) << "kappa error must shrink with ds=" << ds;
    EXPECT_LT(et, std::max(last_t, 1e-9)) << "tau error must shrink with ds=" << ds;
    last_k = ek;
    last_t = et;
    if (ds == 0.001) {
      EXPECT_LT(ek, final_tol);
      EXPECT_LT(et, final_tol);
      EXPECT_LT(std::fabs(g.kappa_prime - exact.kappa_prime), final_tol);
      EXPECT_THAT(g.n, testing::IsNear(exact.n, 10 * final_tol));
      EXPECT_THAT(g.b, testing::IsNear(exact.b, 10 * final_tol));
      EXPECT_GT(g.tau * exact.tau, 0.0) << "torsion sign";
    }
  }
}

TEST(Estimate, ConvergesOnTable33CurvesAndKnownCurves) {
  for (EstimateCircle kind : {EstimateCircle::kWuAndrade, EstimateCircle::kThreePoint}) {
    expect_convergence(TorusKnot{}, 0.0, kind, 1e-4, "C1(0)");
    expect_convergence(CurveC2{}, 0.0, kind, 1e-4, "C2(0)");
    // kappa' != 0 at C1(0.3): the Wu-Andrade kappa is that of the arc ahead, first-order error
    // kappa' ds / 2, which at ds = 0.2 is partly cancelled by the second-order terms.
    expect_convergence(TorusKnot{}, 0.3, kind, 1e-3, "C1(0.3)", {0.1, 0.01, 0.001});
    expect_convergence(Viviani{}, 1.2, kind, 1e-3, "Viviani(1.2)");
    expect_convergence(Helix{}, 0.4, kind, 1e-4, "helix");
  }
}

TEST(Estimate, UnequalStepsAsATracerTakesThem) {
  // Viviani at P with the backward step half the forward one (a tracer's closing step): the
  // torsion divides the binormal turning by the distance between the arcs' midpoints.
  const double s0 = std::numbers::pi / 2, h = 0.01;
  const CurveGeometry exact = exact_frenet(Viviani{}, s0);
  std::vector<CurveSample> s;
  for (double ds : {-1.5 * h, -0.5 * h, 0.0, h}) s.push_back({curve_point(Viviani{}, s0 + ds), curve_tangent(Viviani{}, s0 + ds)});
  for (EstimateCircle kind : {EstimateCircle::kWuAndrade, EstimateCircle::kThreePoint}) {
    CurveGeometry g = estimate_from_samples(s, 2, kind);
    ASSERT_EQ(g.status, GeometryStatus::kOk);
    EXPECT_NEAR(g.tau, exact.tau, 5 * h);
    EXPECT_NEAR(g.kappa_prime, exact.kappa_prime, 5 * h);
    EXPECT_NEAR(g.kappa, exact.kappa, 5 * h);
  }
}

TEST(Estimate, TorsionSignFollowsHandedness) {
  auto left = [](const auto& t) {
    auto p = Helix{}(t);
    p.z = -p.z;
    return p;
  };
  for (EstimateCircle kind : {EstimateCircle::kWuAndrade, EstimateCircle::kThreePoint, EstimateCircle::kWuAndradeLiteral}) {
    CurveGeometry r = estimate_from_samples(samples_of(Helix{}, 0.0, 0.05, 2, 1), 2, kind);
    CurveGeometry l = estimate_from_samples(samples_of(left, 0.0, 0.05, 2, 1), 2, kind);
    EXPECT_GT(r.tau, 0.0);
    EXPECT_LT(l.tau, 0.0);
    // n points to the axis (the centre of curvature) in every variant.
    EXPECT_THAT(r.n, testing::IsNear(Vec3(-1, 0, 0), 0.01));
  }
}

TEST(Estimate, ReportsMissingSamplesAndStraightLines) {
  std::vector<CurveSample> s = samples_of(Helix{}, 0.0, 0.1, 0, 1);  // P and its forward neighbour
  CurveGeometry one = estimate_from_samples(s, 0, EstimateCircle::kWuAndrade);
  EXPECT_EQ(one.status, GeometryStatus::kInsufficientSamples);
  EXPECT_TRUE(std::isfinite(one.kappa));
  EXPECT_TRUE(std::isnan(one.tau));
  EXPECT_TRUE(std::isnan(one.kappa_prime));
  CurveGeometry none = estimate_from_samples(std::span<const CurveSample>(s.data(), 1), 0, EstimateCircle::kWuAndrade);
  EXPECT_EQ(none.status, GeometryStatus::kInsufficientSamples);
  EXPECT_TRUE(none.has_tangent());
  EXPECT_TRUE(std::isnan(none.kappa));
  EXPECT_EQ(estimate_from_samples(s, 5, EstimateCircle::kWuAndrade).status, GeometryStatus::kInsufficientSamples);
  // A neighbour without a tangent (e.g. an isolated tangential point) is a missing sample.
  std::vector<CurveSample> holes = samples_of(Helix{}, 0.0, 0.1, 1, 1);
  holes[2].tangent = Vec3::Constant(kNaN);
  CurveGeometry h = estimate_from_samples(holes, 1, EstimateCircle::kWuAndrade);
  EXPECT_EQ(h.status, GeometryStatus::kInsufficientSamples);
  EXPECT_TRUE(std::isfinite(h.kappa));  // from the frame one step back
  EXPECT_TRUE(std::isnan(h.tau));
  std::vector<CurveSample> line;
  for (int k = 0; k < 3; ++k) line.push_back({Vec3(k, 2 * k, 0), Vec3(1, 2, 0).normalized()});
  for (EstimateCircle kind : {EstimateCircle::kWuAndrade, EstimateCircle::kThreePoint}) {
    CurveGeometry g = estimate_from_samples(line, 1, kind);
    EXPECT_EQ(g.status, GeometryStatus::kZeroCurvature);
    EXPECT_NEAR(g.kappa, 0.0, 1e-15);
    EXPECT_FALSE(g.has_frame());
    EXPECT_TRUE(std::isnan(g.tau));
  }
}

}  // namespace
}  // namespace ssimarch
