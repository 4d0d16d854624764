// sum_k x_k h^k: the Taylor polynomial of the solution curve in parameter space, with
// coefficients from the implicit function theorem (seed 004 §5's method for every pair kind;
// problem/curve_jet.hpp, docs/math/curve_jet.md). Contact order = `order`.
#pragma once

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

struct TaylorPredictor {
  int order = 4;
  int jet_order() const { return order; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
