// The thesis' osculating helix (thesis §4.2, eq 2.9) with the corrected last coefficient
// (a b/c^2) L. Contact order 3 where kappa' = 0, 2 elsewhere.
#pragma once

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

struct OsculatingHelixPredictor {
  static constexpr int kContactOrder = 3;
  int jet_order() const { return 3; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
