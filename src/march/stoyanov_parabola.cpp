#include "ssimarch/march/stoyanov_parabola.hpp"

namespace ssimarch {

Prediction StoyanovParabolaPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  // kappa n = alpha'' = 2 alpha_2: defined (and zero) where the curve is straight, so the
  // parabola needs no Frenet frame and no fallback.
  const Vec3 alpha2 = s.here.order >= 2 ? Vec3(2.0 * s.here.alpha[2]) : Vec3::Zero();
  return internal::prediction_at(problem, s, s.here.alpha[0] + h * s.here.alpha[1] + (0.5 * h * h) * alpha2, h);
}

}  // namespace ssimarch
