// Curve jets of orders 7 and 8 compiled once (problem/curve_jet.hpp); the orders are split over three files
// so that a parallel build compiles them side by side.
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

SSIMARCH_CURVE_JET_ORDER(template, 7);
SSIMARCH_CURVE_JET_ORDER(template, 8);

}  // namespace ssimarch
