// Shared GoogleMock matchers for points, vectors and traced curves, so that a failure says how far
// off a value is and not only that it is: EXPECT_THAT(p, IsNear(Vec3(0, -2, 0), 1e-10)) prints
// both points and their distance. Tolerances are the caller's, with their units (model length for
// points, dimensionless for unit vectors and sines).
#pragma once

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <sstream>
#include <string>

#include <Eigen/Core>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/march/result.hpp"

namespace ssimarch::testing {

/// A vector or matrix (any Eigen expression) in full precision: "(1, 2, 3)", rows separated by ";".
template <class Derived>
std::string text_of(const Eigen::MatrixBase<Derived>& m) {
  std::ostringstream o;
  o << m.eval().format(Eigen::IOFormat(17, Eigen::DontAlignCols, ", ", "; ", "", "", "(", ")"));
  return o.str();
}

/// A point, vector or matrix within `tolerance` (Euclidean / Frobenius distance) of `expected`.
MATCHER_P2(IsNear, expected, tolerance,
           "is within " + ::testing::PrintToString(tolerance) + " of " + text_of(expected)) {
  const double d = (arg - expected).norm();
  *result_listener << "which is " << text_of(arg) << ", at distance " << d;
  return d <= tolerance;
}

/// A direction parallel to `direction`, either orientation: the sine of the angle between them
/// is at most `sine_tolerance`.
MATCHER_P2(IsParallelTo, direction, sine_tolerance,
           "is parallel to " + text_of(Vec3(direction)) + " (sine <= " + ::testing::PrintToString(sine_tolerance) +
               ")") {
  const Vec3 a(arg), b(direction);
  const double sine = a.cross(b).norm() / (a.norm() * b.norm());
  *result_listener << "which is " << text_of(a) << ", sine of the angle " << sine;
  return sine <= sine_tolerance;
}

/// A vector of length 1 within `tolerance`.
MATCHER_P(IsUnit, tolerance, "is a unit vector to " + ::testing::PrintToString(tolerance)) {
  const double n = Vec3(arg).norm();
  *result_listener << "whose length is " << n;
  return std::fabs(n - 1) <= tolerance;
}

/// A traced curve whose length is within `tolerance` of `expected` (model length).
MATCHER_P2(HasLength, expected, tolerance,
           "has length " + ::testing::PrintToString(expected) + " +- " + ::testing::PrintToString(tolerance)) {
  const TracedCurve& c = arg;
  *result_listener << "whose length is " << ::testing::PrintToString(c.length) << " (off by " << c.length - expected
                   << "), " << c.points.size() << " points, " << (c.closed ? "closed" : "open");
  return std::fabs(c.length - expected) <= tolerance;
}

/// A traced curve every point of which has |residual(p)| <= tolerance: e.g. the distance from a
/// surface known in closed form. A failure names the worst point.
MATCHER_P2(HasEveryPointWithin, residual, tolerance,
           "has every point within " + ::testing::PrintToString(tolerance) + " of the reference") {
  const TracedCurve& c = arg;
  const std::function<double(const Vec3&)> f = residual;
  double worst = 0;
  Vec3 at = Vec3::Zero();
  for (const CurvePoint& p : c.points) {
    const double r = std::fabs(f(p.p));
    if (!(r <= worst)) {
      worst = r;
      at = p.p;
    }
  }
  *result_listener << "whose worst point " << text_of(at) << " is " << worst << " off";
  return worst <= tolerance;
}

}  // namespace ssimarch::testing
