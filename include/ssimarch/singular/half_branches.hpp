// The half-branches at a singular point and how they continue through it (thesis ch. 6: a curve
// is a branch; issue 10 "Tracing through"; docs/math/singular_local_curve.md §5).
//
// Each real branch through the point, parametrised by t, splits into the half-branches t > 0
// and t < 0. They are found where the local curve h = 0 crosses a small circle of radius epsilon
// about the point in the tangent plane (for epsilon below the conic-structure radius every
// half-branch crosses it exactly once; Milnor, "Singular points of complex hypersurfaces", §2).
// Per half-branch: its tangent (the tangent-cone line it leaves along), the leading term of its
// offset from that line, w = c X^gamma (X the distance along the tangent: gamma = 2 for a
// smooth curved branch, 3/2 for a cusp, 5/2 for a ramphoid cusp, ...), and a regular point on
// it at distance ~epsilon, Newton-corrected onto H = 0, with the direction to march from there.
//
// Pairing (which half-branch continues which analytically): on one tangent line, the halves of
// a smooth branch Y = a X^g + ... leave along +d and -d with offsets w+ = a r^g and
// w- = (-1)^g a r^g: straight across a node, each on its own side at a tacnode, by curvature at
// the 4-petal rose's quadruple point. Half-branches leaving along the same direction with no
// partner on the opposite side are the two halves of a cusp-like branch (A2, A4, ...): the
// curve goes over the tangent reversal.
#pragma once

#include <vector>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/classify.hpp"
#include "ssimarch/singular/local_curve.hpp"
#include "ssimarch/singular/puiseux.hpp"

namespace ssimarch {

struct HalfBranchOptions {
  double epsilon = 1e-2;        // radius of the circle in the tangent plane, times the germ length
                                // (LocalCurve::germ_length: 1e-3 of the model size); doubled (up
                                // to 3 times) while an exit point is not regular enough
  int samples = 8192;           // sign samples on the circle
  double newton_tolerance = 1e-14;  // |H| (model units, times the model size) of the exit point
  double min_rank_ratio = 1e-7;     // the exit point must be a regular point of the curve: the sine of
                                    // the angle between the normals (Problem::rank_ratio where a
                                    // normal is undefined) at least this
};

struct HalfBranch {
  Vec2 tangent = Vec2::Zero();        // unit, in (s, t), pointing away from the singular point
  Vec3 tangent_3d = Vec3::Zero();     // unit 3D tangent at the singular point
  VecX param_tangent;                 // d(unknowns) along the tangent per unit length (first order)
  int line = -1;                      // index of its line in Classification::tangent_cone
  // The leading term of the offset in the chart (s, t) of the local curve, measured at the circle
  // (offset_term in half_branches.cpp): internal (pairing, arriving half-branches), since the
  // chart of a parametric surface is the tangent plane only to first order.
  double offset_coefficient = 0;      // c of w = c X^gamma (sign w.r.t. the line's normal rot90(d))
  double offset_exponent = 0;         // gamma; 0 where the offset is below resolution (straight)
  // The Puiseux expansion in the chart, in the half-branch's frame (X along the tangent d, W along
  // rot90(d)), up to exponent 6 (singular/puiseux.hpp): pairing by expansions and the geometry of
  // the branch lifted by the chart's 3D jet (pipeline/branch_geometry.cpp) use this one.
  PuiseuxExpansion chart_expansion;
  // Reported (JSON `expansion`): the same half-branch over the common tangent plane, in every pair
  // kind alike (singular/tangent_plane_expansion.hpp; docs/math/singular_local_curve.md §4):
  // X = (P - P0) . tangent_3d >= 0, W = (P - P0) . normal_3d, normal_3d = N x tangent_3d.
  // `leading_coefficient` X^`leading_exponent` is the leading term measured on 3D points of the
  // half-branch at the circle (O(epsilon) relative; exponent 0: straight within resolution),
  // `expansion` the series W(X) = sum b_j X^(j/q) to exponent 6, whose first term is it refined.
  double leading_coefficient = 0;
  double leading_exponent = 0;
  PuiseuxExpansion expansion;
  Vec3 normal_3d = Vec3::Zero();
  int branch = -1;                    // index of the real branch it belongs to
  int continuation = -1;              // the half-branch a curve arriving along this one leaves by
  bool exit_ok = false;               // exit point found, on H = 0 and regular
  VecX exit_x;                        // unknowns of the exit point
  Vec3 exit_point = Vec3::Zero();
  Vec3 direction = Vec3::Zero();      // unit 3D direction to march from the exit point (outwards)
  VecX direction_x;                   // the same in the unknowns (unit 3D speed)
};

/// The half-branches at the singular point `at` (unknowns; a located singular point) of `problem`.
/// `curve` and `kind` are the local curve there and its classification.
std::vector<HalfBranch> half_branches(const Problem& problem, const LocalCurve& curve, const Classification& kind,
                                      const HalfBranchOptions& options = {});

/// Points (s, t) where h = 0 crosses the circle of radius r (sign changes of h on `samples`
/// equally spaced angles, refined by bisection; a local minimum of |h| without a sign change is
/// searched for a pair of crossings closer than the sampling), in increasing angle.
std::vector<Vec2> circle_crossings(const LocalJet& h, double r, int samples);

}  // namespace ssimarch
