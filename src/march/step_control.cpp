#include "ssimarch/march/step_control.hpp"

namespace ssimarch {

namespace {

// Proposals of the chordal controller aim at 0.9 of the largest admissible step, so that
// small changes of curvature along the step rarely cause a rejection.
constexpr double kChordalSafety = 0.9;
// Adaptive rules grow the step by at most this factor per accepted step.
constexpr double kMaxGrowth = 2.0;
// The thesis' "tau = 0" (order-3 rule): |tau| <= kPlanarTorsion * (kappa + |kappa'|^(1/2) + 1),
// i.e. torsion at rounding level for the curve's own scales.
constexpr double kPlanarTorsion = 1e-9;

double clamp_step(double L, const StepBounds& b) {
  if (!(L == L)) return b.max_step;  // NaN: no usable geometry, take the largest step (guards follow)
  return std::clamp(L, b.min_rule, b.max_step);
}

}  // namespace

StepReport make_step_report(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, const Vec3& predicted, double h,
                            int iterations) {
  StepReport r;
  r.h = h;
  r.chord = (p1 - p0).norm();
  r.turn = std::atan2(t0.cross(t1).norm(), t0.dot(t1));
  r.correction = (p1 - predicted).norm();
  r.sagitta = 0.5 * r.chord * std::tan(r.turn / 4);
  r.iterations = iterations;
  return r;
}

double angular_step_length(double turn_angle, double kappa, const StepBounds& b) {
  if (!(kappa > 0)) return b.max_step;
  return clamp_step(turn_angle / kappa, b);
}

double stoyanov_step_length(double D, double kappa, const StepBounds& b) {
  if (!(kappa > 0)) return b.max_step;
  const double q = 1.0 / (D * D * kappa * kappa);
  return clamp_step(D * std::sqrt(2 * (1 + std::sqrt(1 + q))), b);
}

double order3_step_length(double delta, double kappa, double kappa_prime, double tau, const StepBounds& b) {
  if (std::fabs(tau) > kPlanarTorsion * (kappa + std::sqrt(std::fabs(kappa_prime)) + 1)) {
    const double a3 = std::sqrt(std::pow(kappa, 4) + kappa_prime * kappa_prime + kappa * kappa * tau * tau);
    return a3 > 0 ? clamp_step(std::cbrt(6 * delta / a3), b) : b.max_step;
  }
  if (!(kappa > 0)) return b.max_step;
  return clamp_step(std::sqrt(2 * delta / kappa), b);
}

double chordal_step_length(double delta, double kappa, const StepBounds& b) {
  if (!(kappa > 0)) return b.max_step;
  return clamp_step(std::sqrt(8 * delta / kappa), b);
}

double FormulaStep::proposal(const CurveFrame& f) const {
  switch (kind) {
    case Kind::kAngular: return angular_step_length(parameter, f.kappa, bounds);
    case Kind::kDeviation: return stoyanov_step_length(parameter, f.kappa, bounds);
    case Kind::kOrder3: return order3_step_length(parameter, f.kappa, f.kappa_prime, f.tau, bounds);
  }
  return bounds.max_step;
}

void ChordalStep::start(const CurveFrame& f) { h = kChordalSafety * chordal_step_length(delta, f.kappa, bounds); }

void ChordalStep::accepted(const StepReport& r, const CurveFrame& f) {
  double kappa = f.kappa;
  if (r.chord > 0) kappa = std::max(kappa, 8 * r.sagitta / (r.chord * r.chord));
  if (f.has_normal) kappa = std::max(kappa, f.kappa + f.kappa_prime * r.h / 2);
  h = std::min(kChordalSafety * chordal_step_length(delta, kappa, bounds), kMaxGrowth * r.h);
  h = std::max(h, std::min(bounds.min_rule, bounds.max_step));
}

bool ChordalStep::rejected(const StepReport* r) {
  if (r && r->sagitta > delta) {
    h *= std::max(0.2, std::min(0.9, kChordalSafety * std::sqrt(delta / r->sagitta)));
  } else {
    h *= 0.5;
  }
  return h >= bounds.min_step;
}

AnyStepControl make_step_control(const TraceOptions& o) {
  StepBounds b{o.step_length, o.min_step_length, o.min_step};
  switch (o.step) {
    case StepRule::kConstant: return ConstantStep{b, o.step_length};
    case StepRule::kAngular: return FormulaStep{FormulaStep::Kind::kAngular, b, o.turn_angle, o.step_length};
    case StepRule::kDeviation: return FormulaStep{FormulaStep::Kind::kDeviation, b, o.deviation, o.step_length};
    case StepRule::kOrder3: return FormulaStep{FormulaStep::Kind::kOrder3, b, o.deviation, o.step_length};
    case StepRule::kChordal: return ChordalStep{b, o.deviation, o.step_length};
  }
  return ConstantStep{b, o.step_length};
}

}  // namespace ssimarch
