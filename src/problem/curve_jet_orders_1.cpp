// Curve jets of orders 1 to 4 compiled once (problem/curve_jet.hpp); the orders are split over three files
// so that a parallel build compiles them side by side.
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

SSIMARCH_CURVE_JET_ORDER(template, 1);
SSIMARCH_CURVE_JET_ORDER(template, 2);
SSIMARCH_CURVE_JET_ORDER(template, 3);
SSIMARCH_CURVE_JET_ORDER(template, 4);

DynamicCurveJet curve_jet_dynamic(const Problem& problem, const UnknownVec& x0, int order, const Vec3* hint) {
  const int n = problem.dim();
  switch (order) {
    case 1: return internal::to_dynamic(curve_jet<1>(problem, x0, hint), n);
    case 2: return internal::to_dynamic(curve_jet<2>(problem, x0, hint), n);
    case 3: return internal::to_dynamic(curve_jet<3>(problem, x0, hint), n);
    case 4: return internal::to_dynamic(curve_jet<4>(problem, x0, hint), n);
    case 5: return internal::to_dynamic(curve_jet<5>(problem, x0, hint), n);
    case 6: return internal::to_dynamic(curve_jet<6>(problem, x0, hint), n);
    case 7: return internal::to_dynamic(curve_jet<7>(problem, x0, hint), n);
    case 8: return internal::to_dynamic(curve_jet<8>(problem, x0, hint), n);
  }
  static_assert(kMaxCurveJetOrder == 8, "add the cases above up to kMaxCurveJetOrder");
  throw InputError("curve_jet", "order " + std::to_string(order) + " outside 1.." + std::to_string(kMaxCurveJetOrder));
}
}  // namespace ssimarch
