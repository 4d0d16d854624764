// Curve jets of orders 5 and 6 compiled once (problem/curve_jet.hpp); the orders are split over three files
// so that a parallel build compiles them side by side.
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

SSIMARCH_CURVE_JET_ORDER(template, 5);
SSIMARCH_CURVE_JET_ORDER(template, 6);

}  // namespace ssimarch
