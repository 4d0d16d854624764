// Seed 000's circular step ("Um Passo Circular", seed 000 §3): the next point is predicted on
// an approximate osculating circle through the last two points P and Q, tangent there to the
// curve's tangents u and v, walking an arc of length L from Q in the sense P -> Q. The same
// idea as Wu & Andrade's circle (wu_andrade_circle.hpp), built differently: the paper's
// plane / line / equidistant-point construction and its rotation-matrix walk, step by step.
#pragma once

#include <Eigen/Dense>

#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

enum class CircleStatus {
  kOk,
  kParallelTangents,    // |u x v| <= kParallelTangentsSine |u||v|: the two normal planes do not meet in a line
  kNoEquidistantPoint,  // b = 0 and neither a previous t nor the third-plane fallback gives a point
};

/// The circle of seed 000 §3, steps 1-4.
struct OsculatingCircle {
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
OsculatingCircle osculating_circle(const Vec3& P, const Vec3& Q, const Vec3& u, const Vec3& v, const Vec3& origin,
                                   const double* previous_t = nullptr, int previous_axis = -1);

/// Step 6: the row-vector rotation [R] with n [R] = (0, 0, |n|) (and its lambda = 0 case).
Eigen::Matrix3d osculating_circle_rotation(const Vec3& n);

/// Steps 5-9: the point at arc length L from Q along the circle (centre C, radius rho) through
/// P and Q, continuing the sense P -> Q: translate, rotate with [R], walk theta = L/rho, rotate back.
Vec3 osculating_circle_arc_point(const Vec3& P, const Vec3& Q, const Vec3& C, double rho, double L);

/// The predictor: circle through the previous point P and the current point Q, arc h from Q.
/// Falls back to the tangent step at the first point and when the tangents are (nearly) parallel.
struct OsculatingCirclePredictor {
  static constexpr int kContactOrder = 1;  // 2 where kappa' = 0 (docs/marching.md)
  int jet_order() const { return 1; }
  Prediction predict(const Problem& problem, const MarchState& s, double h) const;
};

}  // namespace ssimarch
