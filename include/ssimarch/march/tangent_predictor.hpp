// The tangent step P + L t (Barnhill, Farin, Jordan & Piper, as in thesis §4.1.1), taken in
// parameter space, x + h x'(0), where it needs no 3D-to-parameter map.
#pragma once

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

struct TangentPredictor {
  static constexpr int kContactOrder = 1;
  int jet_order() const { return 1; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
