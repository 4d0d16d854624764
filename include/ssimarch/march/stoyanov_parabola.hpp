// Stoyanov's parabola P + L t + (L^2/2) kappa n (Stoyanov, as in thesis §4.1.2).
#pragma once

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

struct StoyanovParabolaPredictor {
  static constexpr int kContactOrder = 2;
  int jet_order() const { return 2; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
