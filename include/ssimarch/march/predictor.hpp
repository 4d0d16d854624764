// Predictors guess the next point of the curve a step h ahead (spec/marching-directions.md).
// Each is a small value with `predict` and its contact order with the curve; the tracer picks
// one at run time through AnyPredictor.
#pragma once

#include <variant>

#include "ssimarch/geometry/curve_jet.hpp"
#include "ssimarch/march/options.hpp"
#include "ssimarch/march/problem.hpp"

namespace ssimarch {

/// What a predictor may use: the curve's jet at the current point (oriented along the
/// direction of travel) and, when there is one, the previous accepted point.
struct MarchState {
  DynamicCurveJet here;
  bool has_previous = false;
  VecX previous_x;
  Vec3 previous_p = Vec3::Zero();
  Vec3 previous_t = Vec3::Zero();
};

/// x + h x'(0): the tangent step P + L t of Barnhill et al. (spec/marching-directions.md §2),
/// taken in parameter space where it needs no 3D-to-parameter map.
struct TangentPredictor {
  static constexpr int kContactOrder = 1;
  int jet_order() const { return 1; }
  VecX predict(const Problem&, const MarchState& s, double h) const {
    return s.here.x[0] + h * s.here.x[1];
  }
};

/// sum_k x_k h^k: the Taylor polynomial of the solution curve in parameter space, with
/// coefficients from the implicit function theorem (seed 004's method for every pair kind;
/// geometry/curve_jet.hpp). Contact order = `order`.
struct TaylorPredictor {
  int order = 4;
  int jet_order() const { return order; }
  VecX predict(const Problem&, const MarchState& s, double h) const { return s.here.x_at(h); }
};

using AnyPredictor = std::variant<TangentPredictor, TaylorPredictor>;

AnyPredictor make_predictor(const TraceOptions& options);
int jet_order(const AnyPredictor& p);
VecX predict(const AnyPredictor& p, const Problem& problem, const MarchState& s, double h);

}  // namespace ssimarch
