// The thesis' polynomial direction of order 3, from the local canonical form (thesis §4.2,
// eq 2.7): P + (L - kappa^2 L^3/6) t + (kappa L^2/2 + kappa' L^3/6) n + (kappa tau L^3/6) b.
#pragma once

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

struct Order3PolynomialPredictor {
  static constexpr int kContactOrder = 3;
  int jet_order() const { return 3; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
