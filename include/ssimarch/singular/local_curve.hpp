// The local algebraic curve of an intersection at a point: a bivariate function h(s, t) on the
// tangent plane whose zero set is the intersection curve near the point (thesis ch. 5 §5.2.3,
// eq 5.16, generalised to the three pair kinds; derivation in docs/math/singular_local_curve.md).
//
//   pair kind               h(s, t)                                   unknowns x(s, t)
//   parametric-implicit     g(F(u(s,t), v(s,t))) / |grad g(P0)|       (u, v): linear in (s, t)
//   parametric-parametric   (F(u,v) - G(p,q)) . N, with (p,q)(s,t)    (u, v) linear, (p, q) series
//                           solving (F - G) . e_i = 0 (i = 1, 2)
//   implicit-implicit       g(P(s,t)) / |grad g(P0)|, P(s,t) = P0 + s e1 + t e2 + w(s,t) N
//                           the graph of f = 0 over its tangent plane  P(s, t)
//
// (s, t) are orthonormal coordinates of the tangent plane of the first surface at the base
// point P0 (model units); h is a signed gap in model units along N to first order. The base
// point need not lie on the curve: h(0,0) is then the gap. At a singular point of the curve
// h(0,0) = 0 and grad h(0,0) = 0, and the lowest non-zero homogeneous part of h is the thesis'
// local algebraic curve f(x, y) up to a linear change of coordinates.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/local_jet.hpp"

namespace ssimarch {

enum class LocalCurveStatus {
  kOk,
  // A surface is degenerate at the base point (F_u x F_v = 0, grad f = 0 or grad g = 0), or the
  // second parametric surface is tangent-plane singular there (G_p, G_q do not span the plane).
  kDegenerate,
  // Some derivative is not finite at the base point.
  kNonFinite,
};

struct LocalCurve {
  LocalCurveStatus status = LocalCurveStatus::kDegenerate;
  PairKind kind = PairKind::kParametricImplicit;
  VecX base;                        // the unknowns at (s, t) = (0, 0)
  Vec3 origin = Vec3::Zero();       // P0, the 3D point at (0, 0)
  Vec3 e1 = Vec3::Zero(), e2 = Vec3::Zero(), normal = Vec3::Zero();  // orthonormal frame, normal of the first surface
  LocalJet h;                       // the local curve h(s, t) = 0 (model units)
  int gap_degree = 1;               // h is a product of this many gaps (units length^gap_degree)
  double germ_length = 1.0;         // model units: the germ's own length (germ_length(h, ...)) at most
                                    // kGermLengthRatio x the model size, over which h's degrees
                                    // are weighed (classify, puiseux, locate, half-branches)
  std::vector<LocalJet> unknowns;   // x(s, t), one jet per unknown of the problem
  std::array<LocalJet, 3> point;    // the 3D point P(s, t) of x(s, t) (on the chart's surface)
  // Set where a parametric surface of the pair is degenerate at the base point (a cone's apex, a
  // sphere's pole: its parameters are not coordinates of the surface there) and the local curve
  // was built over another chart instead (§6, §7): the unknowns of that surface are constant jets (the
  // base), and `lift` replaces them at a 3D point P(s, t) by the surface's nearest parameters.
  std::function<VecX(const Vec3& point, VecX unknowns)> lift;

  /// The unknowns at (s, t) from the jets (accurate to O(|(s,t)|^(kLocalOrder+1))).
  VecX unknowns_at(const Vec2& st) const;
  /// The 3D point P(s, t) from the jets.
  Vec3 point_at(const Vec2& st) const;
  /// d x / d(s, t) at the base point: n x 2 (rows of lifted unknowns are zero: no derivative exists).
  MatX unknowns_jacobian() const;
  /// Whether the unknowns of a degenerate parametrisation are lifted (see `lift`).
  bool lifted() const { return static_cast<bool>(lift); }
  /// The 3D direction of a tangent-plane direction (s, t).
  Vec3 direction_3d(const Vec2& st) const { return st[0] * e1 + st[1] * e2; }
};

/// The local curve of `problem` at the unknowns `x`. For parametric-parametric pairs (p, q) of x
/// are first moved (Newton) so that G(p,q) - F(u,v) is normal to F; for implicit-implicit pairs
/// x is first moved onto f = 0 along grad f. Where a parametric chart of the pair is degenerate
/// at x (problem/singular_tolerances.hpp kDegenerateChartRatio) the curve is built over the
/// other surface's regular chart, or over implicit forms, with that surface's implicit form as
/// the equation (docs/math/singular_local_curve.md §6); a degenerate surface without an implicit
/// form, at a collapsed row of its rectangle lying on the other surface, gets the other surface's
/// chart with h the product of the branches' equations (§7), and otherwise keeps its own chart.
/// Never throws for numeric trouble: see status.
LocalCurve local_curve(const Problem& problem, const VecX& x);

}  // namespace ssimarch
