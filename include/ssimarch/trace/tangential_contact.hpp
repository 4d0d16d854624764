// Curves of tangential contact: surfaces touching along a whole curve (a cylinder lying on a
// plane, a sphere inside a cylinder of equal radius, coaxial tori whose tubes touch along a
// circle; issue 10 item 5). Along such a curve every point is singular (J_H has rank n - 2, the
// local curve h has a double zero: h = lambda/2 d^2 + ..., d the distance across the curve),
// so the ordinary tracer cannot march it. It is the curve of critical points of h on its zero
// level, traced here by predictor-corrector continuation on grad h = 0 (derivation:
// docs/math/tangential_contact.md):
//   * corrector: at x build the local curve h(s, t) (singular/local_curve.hpp) and take the
//     minimum-norm Newton step on grad h = 0, Hess h z = -grad h with the Hessian's small
//     eigenvalue (the kernel, along the curve) dropped; re-expand at the new point;
//   * predictor: along the Hessian's kernel direction, on the jet x(s, t) of the unknowns;
//   * a point of the curve where the transversal curvature lambda = trace Hess h changes sign is
//     crossed by a transversal branch (h = d^2 e, e = 0 the branch): a tangent_line_crossing,
//     located by regula falsi on lambda along the curve.
#pragma once

#include <optional>
#include <vector>

#include "ssimarch/march/result.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/analysis.hpp"
#include "ssimarch/singular/locate.hpp"

namespace ssimarch {

struct ContactOptions {
  double step = 0;               // spacing of the points (model units); 0: Problem::scale() / 100
  long max_points = 20000;       // points of the curve
  double gap_tolerance = 1e-10;  // model units (times the model size): |h| where the surfaces meet
  double sine_tolerance = 1e-6;  // |grad h| (sine of the angle between the normals) on the curve
  int max_corrections = 12;      // local curves built per corrected point
};

/// A point of a curve of tangential contact with what the tracer needs there.
struct ContactPoint {
  SingularLocation location;    // status kConverged: h = 0 and grad h = 0 within the tolerances
  double lambda = 0;            // trace of Hess h: the transversal curvature of the gap (model units^-1)
  double kernel_ratio = 1;      // |small| / |large| Hessian eigenvalue: about 0 on a contact curve
  Vec3 tangent = Vec3::Zero();  // unit 3D direction of the Hessian's kernel (along the curve)
  Vec2 kernel = Vec2::Zero();   // the same in the tangent-plane coordinates (s, t) of `curve`
  LocalCurve curve;             // the local curve at the point
};

/// The point of the curve of critical points of h nearest to `guess` (minimum-norm Newton on
/// grad h = 0 with re-expansion). location.status is kConverged when the surfaces meet there
/// with parallel normals, kNotSingular when they do not (a near miss), kFailed when the local
/// curve cannot be built.
ContactPoint correct_onto_contact(const Problem& problem, const VecX& guess, const ContactOptions& options = {});

/// Whether a corrected point lies on a curve of contact (one step of its continuation):
/// converged, and the Hessian of h has rank one (kernel_ratio <= 1e-6).
bool on_contact_curve(const ContactPoint& p);

/// The same, decided by the classification (a start of the continuation): the splitting lemma's
/// phi vanishes to the jet's order (tangential_contact), which an A_k point with its own
/// rank-one Hessian (A2, A4, ...) does not.
bool is_contact_point(const ContactPoint& p);

struct ContactTrace {
  TracedCurve curve;                        // tangential_contact = true; empty when x0 is not on one
  std::vector<SingularLocation> crossings;  // points where a transversal branch crosses it
};

/// The point within arc distance `radius` of x (on a contact curve) where a transversal branch
/// crosses the contact curve (lambda changes sign), if any: the singular point a march along
/// that branch meets (its location converges to the nearest contact point, not to the crossing).
std::optional<SingularLocation> crossing_near(const Problem& problem, const VecX& x, double radius,
                                              const ContactOptions& options = {});

/// The crossing a located node stands for, if it stands for one: a tangent-line crossing located
/// off it (h = u^2 v seen from (u0, 0) has the node's form 2 u0 u v) is where h vanishes to third
/// order within third_order_reach of the node (singular/third_order_point.hpp). The analysis
/// there (with `options`) when `node` is a node, h's Hessian falls there by kThirdOrderHessianFall
/// (trace_tolerances.hpp) and the point has multiplicity 3 or more; none otherwise (a true node).
/// `merge` (model units): the caller's merge distance, the least reach.
std::optional<SingularAnalysis> crossing_behind_node(const Problem& problem, const SingularAnalysis& node, double merge,
                                                     const SingularAnalysisOptions& options = {});

/// The curve of tangential contact through x0 (unknowns near a point of it), marched both ways
/// until it closes, leaves the domain, or the corrector fails.
ContactTrace trace_tangential_contact(const Problem& problem, const VecX& x0, const ContactOptions& options = {});

}  // namespace ssimarch
