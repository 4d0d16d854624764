// Every predictor x step rule (and both correctors) traces the thesis' torus curve C1 and
// Viviani's figure eight completely: closed, length to 1e-6, no branch jump.
#include <gtest/gtest.h>

#include "testing/surface_pairs.hpp"
#include "ssimarch/trace/trace_all.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/torus.hpp"

namespace ssimarch {
namespace {

constexpr PredictorKind kPredictors[] = {
    PredictorKind::kTangent,    PredictorKind::kCircle, PredictorKind::kCircleWuAndrade, PredictorKind::kParabola,
    PredictorKind::kPolynomial, PredictorKind::kHelix,  PredictorKind::kTaylor};
constexpr StepRule kRules[] = {StepRule::kConstant, StepRule::kAngular, StepRule::kDeviation, StepRule::kOrder3,
                               StepRule::kChordal};

double c1_param(const Vec3& p) { return std::atan2(p.y(), p.x()); }
// The lap (s or s + 2 pi) whose point is nearer: by z's sign, except within rounding of the
// node's height z = 0 where both laps pass.
double viviani_param(const Vec3& p) {
  double s = std::atan2(p.x(), -1 - p.y());
  if (s < 0) s += 2 * M_PI;
  return (testing::viviani(s) - p).norm() <= (testing::viviani(s + 2 * M_PI) - p).norm() ? s : s + 2 * M_PI;
}

// Points where the parameter is defined: not the exact node (0, -2, 0) of Viviani's curve, an
// output point since issue 10, where both laps meet.
bool off_node(const CurvePoint& p) { return (p.p - Vec3(0, -2, 0)).norm() > 1e-9; }

// Total advance of the curve parameter with every step forward (a branch jump or a retraced
// stretch breaks it).
template <class Param>
double total_advance(const TracedCurve& c, Param param, double period) {
  double total = 0, sign = 0;
  std::vector<CurvePoint> pts;
  for (const auto& p : c.points)
    if (off_node(p)) pts.push_back(p);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    double d = param(pts[i].p) - param(pts[i - 1].p);
    d -= period * std::round(d / period);
    if (sign == 0) sign = d > 0 ? 1 : -1;
    if (d * sign <= 0) return -1;
    total += d * sign;
  }
  return total;
}

TraceOptions options_for(PredictorKind p, StepRule s, CorrectorKind c = CorrectorKind::kNewton) {
  TraceOptions o;
  o.predictor = p;
  o.step = s;
  o.corrector = c;
  o.step_length = 0.05;  // L (constant) or L_max (adaptive)
  // Comparable steps: chordal delta = 1e-4 is Stoyanov's D = 4e-4 (kappa L^2/8 vs kappa L^2/2).
  o.deviation = s == StepRule::kDeviation ? 4e-4 : 1e-4;
  o.turn_angle = 0.03;
  return o;
}

template <class Curve, class Param>
void expect_complete(const Problem& P, const TraceOptions& o, const Vec3& start, Curve curve, Param param,
                     double period, double length) {
  SCOPED_TRACE(std::string(to_string(o.predictor)) + " / " + std::string(to_string(o.step)) + " / " +
               std::string(to_string(o.corrector)) + " / " + std::string(to_string(P.kind())));
  TraceResult r = trace_all(P, o, {start});
  ASSERT_EQ(r.curves.size(), 1u);
  const TracedCurve& c = r.curves[0];
  EXPECT_TRUE(c.closed) << to_string(c.end_end) << ": " << c.end_message;
  EXPECT_NEAR(c.length / length - 1, 0.0, 1e-6);
  EXPECT_NEAR(total_advance(c, param, period), period, 1e-12);
  double worst = 0;
  for (const auto& p : c.points) worst = std::max(worst, (curve(param(p.p)) - p.p).norm());
  // 1e-12 from both surfaces is up to 1e-12 / sin(theta) from the curve: 1.6e-10 was seen next
  // to Viviani's node, where the surfaces are tangent.
  EXPECT_LE(worst, 1e-9);
  // Marched points, plus the closing point, plus per pass through a node the node itself and the
  // exit point the march goes on from (trace/through_singular.hpp).
  long passes = 0;
  for (const auto& p : c.points) passes += off_node(p) ? 0 : 1;
  EXPECT_EQ(r.stats.points + 1 + 2 * passes, static_cast<long>(c.points.size()));
  EXPECT_GT(r.stats.surface_evaluations[0], 0);
  EXPECT_GT(r.stats.surface_evaluations[1], 0);
}

TEST(TracerMatrix, TorusCurveEveryPredictorAndStepRule) {
  Problem P(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  for (PredictorKind p : kPredictors)
    for (StepRule s : kRules)
      expect_complete(P, options_for(p, s), testing::c1(0.3), testing::c1, c1_param, 2 * M_PI, testing::kC1Length);
}

TEST(TracerMatrix, VivianiEveryPredictorAndStepRule) {
  Problem P(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0), PairKind::kParametricImplicit);
  for (PredictorKind p : kPredictors)
    for (StepRule s : kRules)
      expect_complete(P, options_for(p, s), testing::viviani(M_PI / 2), testing::viviani, viviani_param, 4 * M_PI,
                      testing::kVivianiLength);
}

TEST(TracerMatrix, ProjectionCorrectorOnEveryPairKind) {
  Problem pp(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  Problem pi(testing::ruled_surface(), Torus(Vec3::Zero(), Vec3::UnitZ(), 4, 1), PairKind::kParametricImplicit);
  Problem ii(testing::sphere_g2_implicit(), testing::cylinder_f2_implicit(), PairKind::kImplicitImplicit);
  for (StepRule s : {StepRule::kConstant, StepRule::kChordal}) {
    TraceOptions o = options_for(PredictorKind::kTaylor, s, CorrectorKind::kProjection);
    expect_complete(pp, o, testing::c1(0.3), testing::c1, c1_param, 2 * M_PI, testing::kC1Length);
    expect_complete(pi, o, testing::c1(0.3), testing::c1, c1_param, 2 * M_PI, testing::kC1Length);
    expect_complete(ii, o, testing::viviani(M_PI / 2), testing::viviani, viviani_param, 4 * M_PI,
                    testing::kVivianiLength);
  }
}

TEST(TracerMatrix, DefaultMeetsTheIterationTarget) {
  // Issue 3: at the default tolerance (automatic since issue 29: 1e-13 times the model size, here
  // 1.2e-12), >= 90% of the points converge in <= 2 corrector iterations.
  Problem P(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric);
  TraceOptions o;
  ASSERT_EQ(o.predictor, PredictorKind::kTaylor);
  ASSERT_EQ(o.step, StepRule::kChordal);
  ASSERT_EQ(o.tolerance, 0.0);  // automatic
  TraceResult r = trace_all(P, o, {testing::c1(0.3)});
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_GE(r.stats.iterations[0] + r.stats.iterations[1], 0.9 * static_cast<double>(r.stats.points));
}

// Seed 000 Examples 4 and 5 as far as their data allow (no start point is given; the reported
// counts, oracle s000.ex4.report / s000.ex5.report, are not reproducible): constant steps 0.001
// and 0.01, 100 points each way from a point of the curve, tangent against circular step.
TEST(Seed000Examples4And5, CircularStepNeedsNoMoreIterationsThanTheTangentStep) {
  Problem ex4(testing::parametric("u", "v", "u-v+1", {-3, 3}, {-3, 3}),
              testing::parametric("cos(v)*cos(u)", "2*sin(v)*cos(u)", "3*sin(u)", {-M_PI / 2, M_PI / 2}, {0, 2 * M_PI},
                                  false, true),
              PairKind::kParametricParametric);
  Problem ex5(testing::parametric("u", "cos(v)", "sin(v)", {-1.5, 1.5}, {0, 2 * M_PI}, false, true),
              testing::parametric("cos(v)", "sin(v)", "u", {-1.5, 1.5}, {0, 2 * M_PI}, false, true),
              PairKind::kParametricParametric);
  struct Run {
    const Problem* P;
    Vec3 start;
    double L;
  };
  for (const Run& run :
       {Run{&ex4, Vec3(0.8, 0, 1.8), 0.001}, Run{&ex5, Vec3(1, 0, 1), 0.01}, Run{&ex5, Vec3(1, 0, 1), 0.001}}) {
    long total[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      TraceOptions o;
      o.predictor = k == 0 ? PredictorKind::kTangent : PredictorKind::kCircle;
      o.step = StepRule::kConstant;
      o.step_length = run.L;
      o.max_points = 100;
      TraceResult r = trace_all(*run.P, o, {run.start});
      ASSERT_EQ(r.curves.size(), 1u);
      const TracedCurve& c = r.curves[0];
      EXPECT_EQ(c.points.size(), 199u);  // 100 points each way, sharing the start
      // Each step advances about L along the curve (the corrector's minimum-norm update shifts
      // the point along the curve by a fraction of the prediction error): 198 L, unlike the
      // seed's reported 0.0016 / 0.1484 (ex. 4) and 0.3646 / 1.0099 (ex. 5, L = 0.01).
      EXPECT_NEAR(c.length / (198 * run.L) - 1, 0.0, 1e-4);
      for (const auto& p : c.points) EXPECT_LE(run.P->linearize(p.x).distance, 1e-12);
      for (std::size_t i = 0; i < r.stats.iterations.size(); ++i)
        total[k] += static_cast<long>(i + 1) * r.stats.iterations[i];
    }
    EXPECT_LE(total[1], total[0]) << "L = " << run.L;
  }
}

TEST(TracerMatrix, EveryOptionNameRoundTrips) {
  for (PredictorKind p : kPredictors) {
    PredictorKind q{};
    EXPECT_TRUE(parse(to_string(p), &q));
    EXPECT_EQ(p, q);
  }
  for (StepRule s : kRules) {
    StepRule q{};
    EXPECT_TRUE(parse(to_string(s), &q));
    EXPECT_EQ(s, q);
  }
  for (CorrectorKind c : {CorrectorKind::kNewton, CorrectorKind::kProjection}) {
    CorrectorKind q{};
    EXPECT_TRUE(parse(to_string(c), &q));
    EXPECT_EQ(c, q);
  }
  PredictorKind p{};
  EXPECT_FALSE(parse("osculating", &p));
  TraceOptions o;
  o.deviation = -1;
  std::string error;
  EXPECT_FALSE(o.is_valid(&error));
  EXPECT_NE(error.find("deviation"), std::string::npos);
}

}  // namespace
}  // namespace ssimarch
