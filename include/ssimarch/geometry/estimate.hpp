// Curvature, torsion and curvature derivative estimated from points and unit tangents only:
// the thesis' technique for singular regions (thesis §2.1, eqs 2.10-2.12, and §3.2, eq 3.27).
//
// A sample is a point of the curve with its unit tangent, oriented along the direction in which
// the samples are ordered. At sample j the estimate builds an osculating-circle estimate
// ("frame") at j and at j-1 and sets
//   kappa  = 1 / R(j),  n = unit(C(j) - P_j) (projected normal to t_j),  b = unit(t_j x n)
//   |tau|  = 2 sin(phi/2) / |P_j - P_{j-1}|,  phi = angle(b(j), b(j-1))                  (eq 2.11)
//   sign   = sign[(P_j - P_{j-1}).b(j)] gives the sign of the standard torsion      (eq 2.12,
//            read with n towards the centre; docs/geometry.md)
//   kappa' = (kappa(j) - kappa(j-1)) / |P_j - P_{j-1}|                                 (eq 3.27)
// (with kWuAndrade the two denominators are the distance between the frames' arc midpoints,
// (|P_j - P_{j-1}| + |P_{j+1} - P_j|) / 2: the chord for equal steps, right for unequal ones;
// with kThreePoint the mean of the three chords from P_{j-2} to P_{j+1}, for the same reason)
// The frame at k is
//   kWuAndrade:        the Wu-Andrade circle through P_k, P_{k+1} with tangents t_k, t_{k+1}
//                      (eq 3.10, geometric plane assignment: plane through P_k with normal t_k,
//                      through P_{k+1} with normal t_{k+1}, through P_k with normal t_k x t_{k+1});
//   kWuAndradeLiteral: the same with the thesis' printed plane assignment (swapped), which
//                      reproduces Table 3.3 digit for digit (its n is reflected back towards the
//                      centre so that the conventions of curve_geometry.hpp hold);
//   kThreePoint:       the Barnhill-Kersey circle through P_{k-1}, P_k, P_{k+1} (eq 3.7).
#pragma once

#include <span>

#include "ssimarch/geometry/curve_geometry.hpp"

namespace ssimarch {

struct CurveSample {
  Vec3 point;
  Vec3 tangent;  // unit, oriented along the order of the samples
};

enum class EstimateCircle { kWuAndrade, kWuAndradeLiteral, kThreePoint };

struct Circle {
  bool valid = false;  // false: tangents parallel / points collinear (no finite circle)
  Vec3 center = Vec3::Constant(kNaN);
  double radius = kNaN;
};

/// Wu-Andrade circle (eq 3.10) from P, Q and their unit tangents (construction: file comment).
Circle wu_andrade_circle(const Vec3& p, const Vec3& tp, const Vec3& q, const Vec3& tq, bool literal = false);
/// Circle through three points; its radius is Barnhill-Kersey's
/// rho = |a| |b| |a - b| / (2 |a x b|), a = Q - P, b = R - P (eq 3.7).
Circle three_point_circle(const Vec3& p, const Vec3& q, const Vec3& r);
/// Barnhill-Kersey's radius formula itself (eq 3.7); infinite for collinear points.
double barnhill_kersey_radius(const Vec3& p, const Vec3& q, const Vec3& r);

/// The estimate at samples[index] (file comment). Needs the frames at index and index-1:
/// samples index-1..index+1 (Wu-Andrade) or index-2..index+1 (three-point). With fewer, the
/// status is kInsufficientSamples and only what one frame gives is filled. theta is left NaN.
/// The estimate sits between samples: with Wu-Andrade, kappa is that of the arc
/// [P_index, P_index+1] and kappa' a centred difference at P_index (error O(step^2)).
CurveGeometry estimate_from_samples(std::span<const CurveSample> samples, std::size_t index, EstimateCircle circle,
                                    const GeometryTolerances& tol = {});

}  // namespace ssimarch
