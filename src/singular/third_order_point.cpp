#include "ssimarch/singular/third_order_point.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/local_curve.hpp"
#include "ssimarch/singular/local_jet.hpp"

namespace ssimarch {

// With h = d^2 g near the crossing, h's Hessian is (2g + 4d g_d + d^2 g_dd, 2d g_s + d^2 g_ds,
// d^2 g_ss), zero where d = g = 0, with derivatives (6 g_d, 2 g_s), (2 g_s, 0), (0, 0) there: rank 2
// where the branch crosses (g_s != 0). The loop goes on while each step at least halves the
// Hessian's norm (quadratic convergence does far better), so at most as often as a double can be
// halved; a step that lowers it less is kept and ends the loop, one that does not lower it is not
// kept.
ThirdOrderPoint third_order_point(const Problem& P, const SingularLocation& guess, double radius) {
  ThirdOrderPoint best{guess, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  VecX x = guess.x;
  for (bool halving = true; halving;) {
    const LocalCurve c = local_curve(P, P.wrap(x));
    if (c.status != LocalCurveStatus::kOk) break;
    const LocalValue v = evaluate(c.h, Vec2::Zero());
    const double size = v.hessian.norm();
    if (!std::isfinite(best.initial_hessian_norm)) best.initial_hessian_norm = size;
    if (!(size < best.hessian_norm) || (c.origin - guess.point).norm() > radius) break;
    halving = size <= 0.5 * best.hessian_norm;
    best.hessian_norm = size;
    best.location.x = c.base;
    best.location.point = c.origin;
    best.location.gap = std::fabs(v.value);
    best.location.sine = v.gradient.norm();
    const double a = coef(c.h, 3, 0), b = coef(c.h, 2, 1), d = coef(c.h, 1, 2), e = coef(c.h, 0, 3);
    Eigen::Matrix<double, 3, 2> J;  // d(h_ss, h_st, h_tt) / d(s, t)
    J << 6 * a, 2 * b, 2 * b, 2 * d, 2 * d, 6 * e;
    const Eigen::Vector3d H(v.hessian(0, 0), v.hessian(0, 1), v.hessian(1, 1));
    const Vec2 z = J.colPivHouseholderQr().solve(-H);
    if (!z.allFinite() || !(z.norm() > 0)) break;
    x = c.unknowns_at(z);
  }
  return best;
}

double third_order_reach(const SingularAnalysis& node, double floor) {
  return std::max(floor, std::sqrt(kLocateSineTolerance) * node.curve.germ_length);
}

}  // namespace ssimarch
