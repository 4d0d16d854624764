// The choice of predictor: every predictor is a small value with `predict`, its contact order
// with the curve and the jet order it needs (one file each; formulas, sources and orders in
// docs/marching.md); the tracer picks one at run time through AnyPredictor.
#pragma once

#include <array>
#include <variant>

#include "ssimarch/march/options.hpp"
#include "ssimarch/march/order3_polynomial.hpp"
#include "ssimarch/march/osculating_circle_step.hpp"
#include "ssimarch/march/osculating_helix.hpp"
#include "ssimarch/march/prediction.hpp"
#include "ssimarch/march/stoyanov_parabola.hpp"
#include "ssimarch/march/tangent_predictor.hpp"
#include "ssimarch/march/taylor_predictor.hpp"
#include "ssimarch/march/wu_andrade_circle.hpp"

namespace ssimarch {

using AnyPredictor = std::variant<TangentPredictor, OsculatingCirclePredictor, WuAndradeCirclePredictor,
                                  StoyanovParabolaPredictor, Order3PolynomialPredictor, OsculatingHelixPredictor,
                                  TaylorPredictor>;

AnyPredictor make_predictor(const TraceOptions& options);
int jet_order(const AnyPredictor& p);
/// Contact order with the curve (point error O(h^(order+1))) where the predictor is at its best.
int contact_order(const AnyPredictor& p);
Prediction predict(const AnyPredictor& p, const Problem& problem, const MarchState& s, double h);

/// Surface calls made by curve_jet_dynamic(problem, x, order) and by Problem::linearize
/// (first, second surface), from the code of those functions: the evaluation counters'
/// cost model (docs/marching.md, "Statistics").
std::array<long, 2> jet_evaluation_cost(const Problem& problem, int order);
std::array<long, 2> linearize_evaluation_cost(const Problem& problem);

}  // namespace ssimarch
