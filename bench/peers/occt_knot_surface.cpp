#include "occt_knot_surface.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <GeomFill.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

namespace peers {

namespace {

constexpr int kDegree = 10, kSegments = 4;

Eigen::Vector3d ruled_point(double u, double v) {
  const double c4 = std::cos(4 * u), s4 = std::sin(4 * u), r = 4 + c4 + v * (c4 + s4);
  return {r * std::cos(u), r * std::sin(u), s4 + v * (s4 - c4)};
}

double bernstein(int i, double t) {
  double b = 1;
  for (int k = 1; k <= i; ++k) b = b * (kDegree - i + k) / k;
  return b * std::pow(t, i) * std::pow(1 - t, kDegree - i);
}

// Homogeneous Bernstein coefficients (w x, w y, w z, w) of one quarter turn, by collocation at
// Chebyshev points (the Bernstein collocation matrix of degree 10 is well conditioned).
Eigen::Matrix<double, kDegree + 1, 4> quarter(int k, double v) {
  Eigen::Matrix<double, kDegree + 1, kDegree + 1> B;
  Eigen::Matrix<double, kDegree + 1, 4> rhs;
  for (int i = 0; i <= kDegree; ++i) {
    const double t = 0.5 - 0.5 * std::cos(M_PI * i / kDegree);
    for (int j = 0; j <= kDegree; ++j) B(i, j) = bernstein(j, t);
    const double w = std::pow(1 + t * t, 5);
    const Eigen::Vector3d p = ruled_point(k * M_PI / 2 + 2 * std::atan(t), v);
    rhs.row(i) << w * p.x(), w * p.y(), w * p.z(), w;
  }
  return B.partialPivLu().solve(rhs);
}

// The quarters share their end poles (C0 joints, knots of multiplicity kDegree), so each quarter's
// homogeneous coefficients are scaled to start with the weight the previous one ends with
// (w = (1 + t^2)^5 runs from 1 to 32 over a quarter): scaling one piece's coefficients keeps its
// curve, while a shared pole with another piece's weight bent quarters 2-4 (the surfaces of this
// case before 2026-12-07 left the knot by up to 1.3 in quarters 2-4).
Handle(Geom_BSplineCurve) knot_curve(double v) {
  TColgp_Array1OfPnt poles(1, kSegments * kDegree + 1);
  TColStd_Array1OfReal weights(1, kSegments * kDegree + 1);
  for (int k = 0; k < kSegments; ++k) {
    Eigen::Matrix<double, kDegree + 1, 4> h = quarter(k, v);
    if (k > 0) h *= weights(k * kDegree + 1) / h(0, 3);
    for (int i = (k == 0 ? 0 : 1); i <= kDegree; ++i) {
      const int index = k * kDegree + i + 1;
      poles(index) = gp_Pnt(h(i, 0) / h(i, 3), h(i, 1) / h(i, 3), h(i, 2) / h(i, 3));
      weights(index) = h(i, 3);
    }
  }
  TColStd_Array1OfReal knots(1, kSegments + 1);
  TColStd_Array1OfInteger mults(1, kSegments + 1);
  for (int k = 0; k <= kSegments; ++k) {
    knots(k + 1) = k;
    mults(k + 1) = (k == 0 || k == kSegments) ? kDegree + 1 : kDegree;
  }
  return new Geom_BSplineCurve(poles, weights, knots, mults, kDegree);
}

}  // namespace

Handle(Geom_Surface) knot_ruled_surface() { return GeomFill::Surface(knot_curve(-0.5), knot_curve(0.5)); }

}  // namespace peers
