// Real trigonometric polynomials of low degree and their real roots on the circle
// (docs/math/closed_form_quadrics.md, "Along the rulings": the discriminant Delta(theta) of the
// quadratic along the rulings, its derivatives, and the coefficients a, b, c whose products give
// it). A trigonometric polynomial of degree n is z^-n P(z) on the unit circle z = e^{i theta},
// P of degree 2n, so its real roots are the roots of P of modulus 1; they are located by the
// eigenvalues of P's companion matrix (Edelman & Murakami, "Polynomial roots from companion
// matrix eigenvalues", Math. Comp. 64, 1995: backward stable) and refined on f itself by a
// bracketed Newton iteration.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Dense>

namespace ssimarch {

/// f(theta) = c0 + sum_{m=1..n} (cos_m cos(m theta) + sin_m sin(m theta)), n <= kMaxDegree.
struct TrigPolynomial {
  static constexpr int kMaxDegree = 4;
  double constant = 0;
  std::array<double, kMaxDegree> cos_coeff{}, sin_coeff{};  // index m - 1

  /// The largest m with a nonzero coefficient (0 for a constant).
  int degree() const;
  double operator()(double theta) const;
  TrigPolynomial derivative() const;
  /// The largest absolute coefficient.
  double magnitude() const;
};

TrigPolynomial operator+(const TrigPolynomial& f, const TrigPolynomial& g);
TrigPolynomial operator-(const TrigPolynomial& f, const TrigPolynomial& g);
TrigPolynomial operator*(double s, const TrigPolynomial& f);
/// The product; the degrees must add up to at most kMaxDegree (throws std::invalid_argument).
TrigPolynomial operator*(const TrigPolynomial& f, const TrigPolynomial& g);

/// u(theta)^T Q v(theta) with u = u0 + cos(theta) u1 + sin(theta) u2 and v likewise (degree 2).
TrigPolynomial bilinear_form(const std::array<Eigen::Vector4d, 3>& u, const Eigen::Matrix4d& q,
                             const std::array<Eigen::Vector4d, 3>& v);

/// The angles in [0, 2 pi) where f changes sign (its real roots of odd multiplicity), sorted, each
/// to within a few units in the last place. Roots closer together than the companion
/// eigenvalues' error (~ eps^(1/m) at a root of multiplicity m) count as one cluster, whose sign
/// change (odd or even) is what is found (kTrigRootCluster). Empty for a constant.
std::vector<double> trig_sign_changes(const TrigPolynomial& f);

/// A root of f in [lo, hi], where f(lo) and f(hi) lie on either side of 0 (f < 0 at one end
/// only): Newton's steps kept inside the shrinking bracket, bisection where a step leaves it or
/// does not halve it; to a few units in the last place of the root.
double trig_root_in(const TrigPolynomial& f, double lo, double hi);

}  // namespace ssimarch
