// Predictors guess the next point of the curve a step h ahead (spec/marching-directions.md,
// spec/circular-step.md; formulas, sources and orders in docs/marching.md). Each is a small value
// with `predict`, its contact order with the curve and the jet order it needs; the tracer picks
// one at run time through AnyPredictor.
//
// Parameter-space predictors (tangent, taylor) return unknowns directly. The 3D predictors
// (circle, circle-wu-andrade, parabola, polynomial, helix) build a 3D point Q and map it to
// unknowns with map_to_unknowns: the first-order map through the pseudo-inverse of each
// surface's point map, then Gauss-Newton foot-point iterations (projection of Q onto each
// parametric surface), so that the mapped guess keeps the predictor's order.
#pragma once

#include <variant>

#include "ssimarch/geometry/curve_jet.hpp"
#include "ssimarch/march/options.hpp"
#include "ssimarch/march/problem.hpp"

namespace ssimarch {

/// What a predictor may use: the curve's jet at the current point (oriented along the
/// direction of travel) and, when there is one, the previous accepted point and its tangent.
struct MarchState {
  DynamicCurveJet here;
  bool has_previous = false;
  VecX previous_x;
  Vec3 previous_p = Vec3::Zero();
  Vec3 previous_t = Vec3::Zero();
  // Seed 000's "reuse t from the previous step" (b = 0): the line parameter of the last circle
  // centre and the coordinate it was measured along; axis -1 when there is none.
  double circle_line_parameter = 0;
  int circle_line_axis = -1;
  // The 3D-to-parameter map stops its foot-point iterations when an update moves the point by
  // <= map_tolerance (model units); the tracer sets it to the corrector tolerance.
  double map_tolerance = 1e-12;
};

/// A guess for the corrector.
struct Prediction {
  VecX x;                 // unknowns to start the corrector from
  Vec3 point = Vec3::Zero();  // the predicted 3D point (point(x) for parameter-space predictors)
  double arc = 0;         // arc length the prediction advances (h, except under the Wu-Andrade angle heuristic)
  bool fallback = false;  // fell back to the tangent step (no previous point, parallel tangents, ...)
  double circle_line_parameter = 0;  // seed 000 circle: the line parameter used (see MarchState)
  int circle_line_axis = -1;
  std::array<long, 2> evaluations{};  // surface calls spent (first, second)
};

/// Frenet data of the curve at a point from its exact jet (spec/curve-geometry.md §1):
/// kappa = |alpha''|, n = alpha''/kappa, b = t x n, kappa' = alpha'''.n, tau_std = alpha'''.b/kappa.
/// Standard torsion sign (the thesis' tau_dC = -tau). Where kappa is ~0 (relative to the
/// problem scale), n and b are undefined: has_normal = false, tau = 0.
struct CurveFrame {
  Vec3 p, t, n, b;
  double kappa = 0, kappa_prime = 0, tau = 0;
  bool has_normal = false;
  Vec3 alpha2 = Vec3::Zero(), alpha3 = Vec3::Zero();  // d^2 alpha/ds^2, d^3 alpha/ds^3
};
CurveFrame curve_frame(const DynamicCurveJet& jet, double scale);

/// The unknowns whose 3D point(s) are the feet of Q on the surfaces, starting from the current
/// unknowns x0: per parametric surface, Gauss-Newton foot-point iterations from x0 (the first is
/// the first-order map dx = D^+ (Q - S(x0))), at most 8, stopping once an update moves the point
/// by <= stop (model units). Implicit-implicit: Q itself. Adds the surface calls to *evaluations.
VecX map_to_unknowns(const Problem& problem, const VecX& x0, const Vec3& Q, double stop, std::array<long, 2>* evaluations);

// --- seed 000's circular step, as the paper constructs it (spec/circular-step.md §3) ---------------

enum class CircleStatus {
  kOk,
  kParallelTangents,  // |u x v| <= kParallelTolerance |u||v|: the two normal planes do not meet in a line
  kNoEquidistantPoint,  // b = 0 and neither a previous t nor the third-plane fallback gives a point
};

struct Seed000Circle {
  CircleStatus status = CircleStatus::kParallelTangents;
  Vec3 centre = Vec3::Zero();
  double radius = 0;
  Vec3 R = Vec3::Zero(), S = Vec3::Zero();  // points of the line at coordinate `axis` = 0 and 1
  int axis = -1;                 // coordinate fixed to get R and S (largest |(u x v)_k|)
  double line_parameter = 0;     // t with centre = R + t (S - R)
  double b = 0;                  // 2 (P - Q).(S - R)
  enum class Equidistant { kSolved, kReusedPrevious, kThirdPlane } how = Equidistant::kSolved;
};

/// Steps 1-4: the planes through P and Q with normals u and v, their line r(t) = R + t (S - R),
/// the point equidistant from P and Q (a = |P|^2 - |Q|^2 - 2 (P - Q).R, with R, not the
/// paper's S), its radius. The construction runs in coordinates centred at `origin` (a
/// translation, which it commutes with; pass the zero vector for the paper's literal numbers).
/// b = 0: reuse `previous_t` (on the same axis) when given, else Wu-Andrade's third plane.
Seed000Circle seed000_circle(const Vec3& P, const Vec3& Q, const Vec3& u, const Vec3& v, const Vec3& origin,
                             const double* previous_t = nullptr, int previous_axis = -1);

/// Step 6: the row-vector rotation [R] with n [R] = (0, 0, |n|) (and its lambda = 0 case).
Eigen::Matrix3d seed000_rotation(const Vec3& n);

/// Steps 5-9: the point at arc length L from Q along the circle (centre C, radius rho) through
/// P and Q, continuing the sense P -> Q: translate, rotate with [R], walk theta = L/rho, rotate back.
Vec3 seed000_arc_point(const Vec3& P, const Vec3& Q, const Vec3& C, double rho, double L);

/// Wu-Andrade's centre: the intersection of the planes through P with normal tP, through Q with
/// normal tQ, and through P with normal tP x tQ (spec/curve-geometry.md §3.2 item 3, geometric
/// plane assignment). False when tP and tQ are (nearly) parallel.
bool wu_andrade_centre(const Vec3& P, const Vec3& Q, const Vec3& tP, const Vec3& tQ, Vec3* centre);

/// The thesis' angle heuristic (spec/marching-directions.md §3.2): theta = L if R <= 1 else L/R.
inline double wu_andrade_angle(double L, double R) { return R <= 1 ? L : L / R; }

// --- the predictors ----------------------------------------------------------------------------

/// x + h x'(0): the tangent step P + L t of Barnhill et al. (spec/marching-directions.md §2),
/// taken in parameter space where it needs no 3D-to-parameter map.
struct TangentPredictor {
  static constexpr int kContactOrder = 1;
  int jet_order() const { return 1; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

/// Seed 000's circular step (spec/circular-step.md §2-3): circle through the previous point P
/// and the current point Q tangent to the normal planes there, arc h from Q. Falls back to the
/// tangent step at the first point and when the tangents are (nearly) parallel.
struct CirclePredictor {
  static constexpr int kContactOrder = 1;  // 2 where kappa' = 0 (docs/marching.md)
  int jet_order() const { return 1; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

/// The thesis' Wu-Andrade circular step (spec/marching-directions.md §3.2): centre from three
/// planes, Q_i = C + R (cos theta e1 + sin theta t), theta by the angle heuristic.
struct WuAndradePredictor {
  static constexpr int kContactOrder = 2;
  int jet_order() const { return 1; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

/// Stoyanov's parabola P + L t + (L^2/2) kappa n (spec/marching-directions.md §3.1).
struct ParabolaPredictor {
  static constexpr int kContactOrder = 2;
  int jet_order() const { return 2; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

/// The thesis' order-3 polynomial, from the local canonical form eq 2.7
/// (spec/marching-directions.md §4.1).
struct PolynomialPredictor {
  static constexpr int kContactOrder = 3;
  int jet_order() const { return 3; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

/// The thesis' osculating helix eq 2.9 with the corrected last coefficient (a b/c^2) L
/// (spec/marching-directions.md §4.2). Contact order 3 where kappa' = 0, 2 elsewhere.
struct HelixPredictor {
  static constexpr int kContactOrder = 3;
  int jet_order() const { return 3; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

/// sum_k x_k h^k: the Taylor polynomial of the solution curve in parameter space, with
/// coefficients from the implicit function theorem (seed 004's method for every pair kind;
/// geometry/curve_jet.hpp). Contact order = `order`.
struct TaylorPredictor {
  int order = 4;
  int jet_order() const { return order; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

using AnyPredictor = std::variant<TangentPredictor, CirclePredictor, WuAndradePredictor, ParabolaPredictor,
                                  PolynomialPredictor, HelixPredictor, TaylorPredictor>;

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
