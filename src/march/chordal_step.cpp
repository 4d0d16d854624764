#include "ssimarch/march/chordal_step.hpp"

#include <cmath>

namespace ssimarch {

namespace {
// Proposals aim at 0.9 of the largest admissible step, so that small changes of curvature along
// the step rarely cause a rejection.
constexpr double kChordalSafety = 0.9;
// The step grows by at most this factor per accepted step.
constexpr double kMaxGrowth = 2.0;
}  // namespace

double chordal_step_length(double delta, double kappa, const StepBounds& b) {
  if (!(kappa > 0)) return b.max_step;
  return clamp_step(std::sqrt(8 * delta / kappa), b);
}

void ChordalStep::start(const CurveGeometry& f) { h = kChordalSafety * chordal_step_length(delta, f.kappa, bounds); }

void ChordalStep::accepted(const StepReport& r, const CurveGeometry& f) {
  double kappa = f.kappa;
  if (r.chord > 0) kappa = std::max(kappa, 8 * r.sagitta / (r.chord * r.chord));
  // kappa' is NaN where undetermined (straight, or a jet of order 2): no extrapolation then.
  if (f.has_frame() && std::isfinite(f.kappa_prime)) kappa = std::max(kappa, f.kappa + f.kappa_prime * r.h / 2);
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

}  // namespace ssimarch
