#include "ssimarch/march/tangent_predictor.hpp"

namespace ssimarch {

Prediction TangentPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  return internal::tangent_step(problem, s, h);
}

}  // namespace ssimarch
