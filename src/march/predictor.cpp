#include "ssimarch/march/predictor.hpp"

#include <algorithm>
#include <type_traits>

namespace ssimarch {

AnyPredictor make_predictor(const TraceOptions& options) {
  switch (options.predictor) {
    case PredictorKind::kTangent: return TangentPredictor{};
    case PredictorKind::kCircle: return OsculatingCirclePredictor{};
    case PredictorKind::kCircleWuAndrade: return WuAndradeCirclePredictor{};
    case PredictorKind::kParabola: return StoyanovParabolaPredictor{};
    case PredictorKind::kPolynomial: return Order3PolynomialPredictor{};
    case PredictorKind::kHelix: return OsculatingHelixPredictor{};
    case PredictorKind::kTaylor: return TaylorPredictor{options.taylor_order};
  }
  return TangentPredictor{};
}

int jet_order(const AnyPredictor& p) {
  return std::visit([](const auto& x) { return x.jet_order(); }, p);
}

int contact_order(const AnyPredictor& p) {
  return std::visit(
      [](const auto& x) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, TaylorPredictor>)
          return x.order;
        else
          return std::decay_t<decltype(x)>::kContactOrder;
      },
      p);
}

Prediction predict(const AnyPredictor& p, const Problem& problem, const MarchState& s, double h) {
  return std::visit([&](const auto& x) { return x.predict(problem, s, h); }, p);
}

std::array<long, 2> jet_evaluation_cost(const Problem& problem, int order) {
  // curve_jet_start: J, D and the point from one call of each surface (raw_jacobians), then per
  // order k = 2..K one Taylor residual and point; a parametric-implicit pair also linearises
  // for the rank ratio (src/problem/curve_jet_start.cpp, raw_rank_ratio).
  const long K = std::max(order, 1);
  if (problem.kind() == PairKind::kParametricImplicit) return {K + 1, K + 1};
  return {K, K};
}

std::array<long, 2> linearize_evaluation_cost(const Problem&) { return {1, 1}; }

}  // namespace ssimarch
