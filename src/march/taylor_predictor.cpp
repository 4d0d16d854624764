#include "ssimarch/march/taylor_predictor.hpp"

#include <algorithm>

namespace ssimarch {

Prediction TaylorPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  Prediction r;
  // Own order, even when the tracer's jet is longer (a step rule may need more terms).
  const int k_max = std::min(order, s.here.order);
  r.x = s.here.x[static_cast<std::size_t>(k_max)];
  for (int k = k_max - 1; k >= 0; --k) r.x = (r.x * h + s.here.x[static_cast<std::size_t>(k)]).eval();
  r.point = problem.point(r.x);
  if (problem.kind() != PairKind::kImplicitImplicit) ++r.evaluations[0];
  r.arc = h;
  return r;
}

}  // namespace ssimarch
