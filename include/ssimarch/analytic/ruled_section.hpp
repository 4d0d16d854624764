// The intersection of a cylinder or cone with any quadric, along the rulings of the first
// (docs/math/closed_form_quadrics.md, "Along the rulings"). Levin's idea (J. Z. Levin, "A
// parametric algorithm for drawing pictures of solid objects composed of quadric surfaces",
// CACM 19(10), 1976; Wang, Goldman & Tu, "Enhancing Levin's method for computing quadric-surface
// intersections", CAGD 20, 2003): on a ruled quadric of the pencil the curve is the pair of roots
// of a quadratic along each ruling. When one surface is a cylinder or cone it is that ruled
// quadric itself, with the rulings
//   X(theta, t) = A(theta) + t D(theta)   (homogeneous, w = 1),
//   A, D = V0 + cos(theta) V1 + sin(theta) V2,
// and X lies on Q (X^T Q X = 0) where a t^2 + b t + c = 0 with a = D^T Q D, b = 2 D^T Q A,
// c = A^T Q A: the discriminant Delta(theta) = b^2 - 4 a c is a trigonometric polynomial of
// degree 2 for both (a constant, c of degree 2 on a cylinder; c constant, a of degree 2 on a
// cone). Its simple roots are where the curve turns on a ruling, its double roots where two
// branches meet (the surfaces touch: a singular point of the curve) or an isolated point.
// Each closed curve is parametrised analytically by phi (RuledLoop): between two simple roots
// theta = mid - half cos(phi), so that sqrt(Delta) ~ |sin(phi)| and the signed root
// sign(sin phi) sqrt(Delta) is smooth; across a double root the signed root changes sign (the
// branch continues smoothly onto the other sheet).
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/march/result.hpp"
#include "ssimarch/surface/surface.hpp"
#include "ssimarch/surface/trims.hpp"

namespace ssimarch {

/// The rulings of a cylinder or cone: X(theta, t) = A(theta) + t D(theta), homogeneous, with
/// A = a[0] + cos(theta) a[1] + sin(theta) a[2] and D likewise; t is the primitive's axial
/// parameter (its v), so the axial trim is a range of t.
struct Rulings {
  std::array<Eigen::Vector4d, 3> a, d;
  bool cone = false;
  bool homogeneous = false;  // w of A + t D is not 1: the 3D point is (A + t D).xyz / w
};
/// The rulings of a cylinder or cone; nullopt for every other surface.
std::optional<Rulings> rulings_of(const Surface& surface);

/// One closed curve of the section, parametrised by phi in [0, period()).
struct RuledLoop {
  bool arc = true;      // true: theta in [lo, hi] between two simple roots of Delta; false: all theta
  double lo = 0, hi = 0;  // arc: the two roots (hi > lo); circle: theta = lo + phi
  int turns = 1;        // circle: 2 when the curve goes round twice before closing
  double sign = 1;      // circle: which root at phi = 0
  std::vector<double> switches;  // theta of the double roots of Delta at which the root changes sheet
  double period() const;
};

/// The section of the rulings with a quadric Q.
struct RuledSection {
  std::vector<RuledLoop> loops;
  std::vector<double> crossings;  // theta of the double roots of Delta inside the curve (singular points)
  std::vector<double> isolated;   // theta of the isolated real points (double roots of Delta at a maximum)
  double scale = 0;               // of Delta: max over theta of b^2 + 4 |a c|
  double zero = 0;                // |Delta| at or below this is zero (kClosedFormDegeneracy x scale)
};

class RuledCurves {
 public:
  RuledCurves(const Rulings& rulings, const Eigen::Matrix4d& q) : r_(rulings), q_(q) {}

  /// The section's loops and special points; nullopt where the method does not apply: the
  /// rulings meet Q in one point or none at some angle (a ruling along an asymptotic direction of
  /// Q; parallel cylinders), a cone's apex lies on Q, or Delta vanishes identically (the surfaces
  /// touch along a curve).
  std::optional<RuledSection> section() const;

  /// The point of `loop` at phi (double or jets in phi: exact derivatives where Delta > 0).
  template <class T>
  Vec3T<T> point(const RuledLoop& loop, const T& phi) const;
  /// The point on the ruling at theta where the two roots meet (a crossing or isolated point).
  Vec3 double_root_point(double theta) const;
  /// d point / d phi (exact; at a crossing where the loop changes sheet, from the slope of the
  /// signed root there; a central difference at the other roots of Delta, where the jet is not finite).
  Vec3 derivative(const RuledLoop& loop, double phi) const;
  /// The sign of the root sqrt(Delta) that `loop` takes at phi (ruled_section.hpp, top).
  double root_sign(const RuledLoop& loop, double phi) const;
  /// The point at phi and d point / d phi from one evaluation (as point and derivative).
  std::pair<Vec3, Vec3> point_and_derivative(const RuledLoop& loop, double phi) const;

  /// a, b, c of the quadratic on the ruling at theta.
  template <class T>
  std::array<T, 3> quadratic(const T& theta) const;
  /// The point at parameter t on the ruling at theta: A(theta) + t D(theta), divided by its w
  /// (1 for a cylinder's or cone's own rulings; the rulings of a cone of a pencil through a
  /// homogeneous apex, quadric_pencil.hpp, have w = 1 + t D_w).
  template <class T>
  Vec3T<T> on_ruling(const T& theta, const T& t) const;

 private:
  const Rulings r_;
  const Eigen::Matrix4d q_;
};

// --- templates -------------------------------------------------------------------------------

template <class T>
std::array<T, 3> RuledCurves::quadratic(const T& theta) const {
  using std::cos;
  using std::sin;
  const T c = cos(theta), s = sin(theta);
  std::array<T, 4> A, D, QA, QD;
  for (int i = 0; i < 4; ++i) {
    A[static_cast<std::size_t>(i)] = r_.a[0][i] + c * r_.a[1][i] + s * r_.a[2][i];
    D[static_cast<std::size_t>(i)] = r_.d[0][i] + c * r_.d[1][i] + s * r_.d[2][i];
  }
  for (int i = 0; i < 4; ++i) {
    QA[static_cast<std::size_t>(i)] = T(0.0);
    QD[static_cast<std::size_t>(i)] = T(0.0);
    for (int j = 0; j < 4; ++j) {
      QA[static_cast<std::size_t>(i)] += q_(i, j) * A[static_cast<std::size_t>(j)];
      QD[static_cast<std::size_t>(i)] += q_(i, j) * D[static_cast<std::size_t>(j)];
    }
  }
  T a(0.0), b(0.0), cc(0.0);
  for (std::size_t i = 0; i < 4; ++i) {
    a += D[i] * QD[i];
    b += 2.0 * D[i] * QA[i];
    cc += A[i] * QA[i];
  }
  return {a, b, cc};
}

template <class T>
Vec3T<T> RuledCurves::point(const RuledLoop& loop, const T& phi) const {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T theta = loop.arc ? T(0.5 * (loop.lo + loop.hi) - 0.5 * (loop.hi - loop.lo) * cos(phi)) : T(loop.lo + phi);
  const double sign = root_sign(loop, primal(phi));
  const auto [a, b, c] = quadratic(theta);
  const T disc = b * b - 4.0 * a * c;
  // The root (-b + S) / 2a without cancellation: 2c / (-b - S) where b and S have one sign. At a
  // double root (Delta <= 0 to rounding: S = 0) the root is -b / 2a itself; 2c / -b would be two
  // rounding errors' ratio where the double root lies at t = 0 (b = c = 0).
  if (!(primal(disc) > 0)) return on_ruling(theta, T(-b / (2.0 * a)));
  const T root = sign * sqrt(disc);
  const T t = primal(b) * sign > 0 ? T(2.0 * c / (-b - root)) : T((-b + root) / (2.0 * a));
  return on_ruling(theta, t);
}

template <class T>
Vec3T<T> RuledCurves::on_ruling(const T& theta, const T& t) const {
  using std::cos;
  using std::sin;
  const T cs = cos(theta), sn = sin(theta);
  std::array<T, 4> x;
  for (int i = 0; i < 4; ++i) {
    const T A = r_.a[0][i] + cs * r_.a[1][i] + sn * r_.a[2][i];
    const T D = r_.d[0][i] + cs * r_.d[1][i] + sn * r_.d[2][i];
    x[static_cast<std::size_t>(i)] = A + t * D;
  }
  if (r_.homogeneous) return Vec3T<T>(x[0] / x[3], x[1] / x[3], x[2] / x[3]);
  return Vec3T<T>(x[0], x[1], x[2]);
}

}  // namespace ssimarch

namespace ssimarch {

/// The section's curves inside the region (every slab), as traced curves (x = the 3D point):
/// a loop wholly inside comes back closed (its last point repeats the first), the parts of the
/// others inside as open curves ending on the region's faces (kLeftDomain, ends found by
/// bisection). Chords within `deviation` of the curve and at most `max_chord` long; lengths of
/// |d point / d phi| (analytic in phi) by the trapezoidal rule on the loop's uniform coarse samples
/// (a closed loop: geometric convergence, checked by halving) or Romberg-extrapolated chord sums of
/// exact points (an open piece, or a loop where the trapezoidal rule has not converged). nullopt when a loop would need
/// more than 100000 samples (it runs far outside the region): the caller traces instead.
std::optional<std::vector<TracedCurve>> ruled_curves_in(const RuledCurves& curves, const RuledSection& section,
                                                        const std::vector<Slab>& region, double deviation,
                                                        double max_chord);

}  // namespace ssimarch
