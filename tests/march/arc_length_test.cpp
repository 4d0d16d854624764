// The arc-length shortfall of the circular-arc estimate (march/arc_length.hpp; derivation in
// docs/marching.md, "Length."): zero on circles, and on sampled curves with exact points and
// tangents it recovers the exact length far below the estimate's own error.
#include "ssimarch/march/arc_length.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "ssimarch/march/tracer.hpp"

namespace ssimarch {
namespace {

// Points and unit tangents of r(t) at the given parameters (tangent = r'(t) normalised).
std::vector<CurvePoint> sample(const std::function<Vec3(double)>& r, const std::function<Vec3(double)>& dr,
                               const std::vector<double>& ts) {
  std::vector<CurvePoint> pts;
  for (double t : ts) pts.push_back(CurvePoint{UnknownVec::Zero(2), r(t), dr(t).normalized()});
  return pts;
}

double estimate(const std::vector<CurvePoint>& p, bool closed) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) s += arc_length_estimate(p[i].p, p[i].t, p[i + 1].p, p[i + 1].t);
  if (closed) s += arc_length_estimate(p.back().p, p.back().t, p.front().p, p.front().t);
  return s;
}

TEST(ArcLengthShortfall, VanishesOnACircleWithUnequalSteps) {
  std::vector<double> ts;
  for (double t = 0; t < 2 * std::numbers::pi - 0.05; t += 0.05 + 0.04 * std::sin(3 * t) * std::sin(3 * t)) ts.push_back(t);
  const auto pts = sample([](double t) { return Vec3(3 * std::cos(t), 3 * std::sin(t), 1); },
                          [](double t) { return Vec3(-std::sin(t), std::cos(t), 0); }, ts);
  EXPECT_NEAR(arc_length_shortfall(pts, true), 0.0, 1e-14 * 6 * std::numbers::pi);
  EXPECT_NEAR(estimate(pts, true), 6 * std::numbers::pi, 1e-13);
}

TEST(ArcLengthShortfall, RecoversABernoulliLemniscateThroughItsInflection) {
  // (a cos t, a sin t cos t) / (1 + sin^2 t): the curvature 3 rho / a^2 changes sign at the node,
  // where it is 0 and the steps below are longest. Length 2 varpi a, varpi = Gamma(1/4)^2 / (2 sqrt(2 pi)).
  const double a = 2 * std::sqrt(2.0), varpi = std::pow(std::tgamma(0.25), 2) / (2 * std::sqrt(2 * std::numbers::pi));
  auto r = [a](double t) { const double d = 1 + std::sin(t) * std::sin(t); return Vec3(a * std::cos(t) / d, a * std::sin(t) * std::cos(t) / d, 0); };
  auto dr = [a](double t) {
    const double s = std::sin(t), c = std::cos(t), d = 1 + s * s;
    return Vec3(-a * s * (d + 2 * c * c) / (d * d), a * (std::cos(2 * t) * d - 2 * s * s * c * c) / (d * d), 0);
  };
  std::vector<double> ts;
  for (double t = 0.01; t < 2 * std::numbers::pi; t += 0.06 + 0.03 * std::cos(t) * std::cos(t)) ts.push_back(t);
  const auto pts = sample(r, dr, ts);
  const double exact = 2 * varpi * a, est = estimate(pts, true);
  const double corrected = est + arc_length_shortfall(pts, true);
  EXPECT_GT(std::fabs(est - exact), 1e-8 * exact);  // the estimate alone is off
  // Steps up to 0.25 with the curvature 0 .. 1.06: the leading term is 99% of the estimate's error.
  EXPECT_NEAR(corrected, exact, 2e-2 * std::fabs(est - exact));
}

TEST(ArcLengthShortfall, RecoversAHelixOpenAtBothEnds) {
  // Constant curvature and torsion: the shortfall is all torsion, 3 kappa^2 tau^2 h^5 / 1440.
  const double A = 1, B = 0.5, c = std::sqrt(A * A + B * B), L = 6;
  std::vector<double> ts;
  for (double s = 0; s <= L + 1e-12; s += 0.2) ts.push_back(s / c);
  const auto pts = sample([&](double t) { return Vec3(A * std::cos(t), A * std::sin(t), B * t); },
                          [&](double t) { return Vec3(-A * std::sin(t), A * std::cos(t), B); }, ts);
  const double est = estimate(pts, false);
  EXPECT_GT(L - est, 1e-7);
  EXPECT_NEAR(est + arc_length_shortfall(pts, false), L, 1e-2 * (L - est));
}

}  // namespace
}  // namespace ssimarch
