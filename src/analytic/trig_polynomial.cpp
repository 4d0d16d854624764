// Trigonometric polynomials and their real roots: see the header and
// docs/math/closed_form_quadrics.md, "Along the rulings".
#include "ssimarch/analytic/trig_polynomial.hpp"

#include <numbers>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "ssimarch/core/contract.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

constexpr int kMaxRoots = 2 * TrigPolynomial::kMaxDegree;
// A root is refined until Newton's step or the bracket is within a few units in the last place.
constexpr double kRootResolution = 4 * std::numeric_limits<double>::epsilon();

using Complex = std::complex<double>;

// The coefficients F_m, m = -n..n, of f = sum F_m e^{i m theta} (F_-m = conj F_m), at index m + n.
std::array<Complex, kMaxRoots + 1> exponential_coefficients(const TrigPolynomial& f, int n) {
  std::array<Complex, kMaxRoots + 1> F{};
  F[static_cast<std::size_t>(n)] = f.constant;
  for (int m = 1; m <= n; ++m) {
    const Complex Fm(0.5 * f.cos_coeff[static_cast<std::size_t>(m - 1)], -0.5 * f.sin_coeff[static_cast<std::size_t>(m - 1)]);
    F[static_cast<std::size_t>(n + m)] = Fm;
    F[static_cast<std::size_t>(n - m)] = std::conj(Fm);
  }
  return F;
}

double wrap(double theta) { return theta - (2 * std::numbers::pi) * std::floor(theta / (2 * std::numbers::pi)); }

}  // namespace

int TrigPolynomial::degree() const {
  for (int m = kMaxDegree; m >= 1; --m)
    if (cos_coeff[static_cast<std::size_t>(m - 1)] != 0 || sin_coeff[static_cast<std::size_t>(m - 1)] != 0) return m;
  return 0;
}

double TrigPolynomial::operator()(double theta) const {
  // cos(m theta), sin(m theta) by the Chebyshev recurrence from one sine and cosine.
  const double c1 = std::cos(theta), s1 = std::sin(theta);
  double cm = c1, sm = s1, cprev = 1, sprev = 0;
  double sum = constant;
  const int n = degree();
  for (int m = 1; m <= n; ++m) {
    sum += cos_coeff[static_cast<std::size_t>(m - 1)] * cm + sin_coeff[static_cast<std::size_t>(m - 1)] * sm;
    const double cn = 2 * c1 * cm - cprev, sn = 2 * c1 * sm - sprev;
    cprev = cm, sprev = sm, cm = cn, sm = sn;
  }
  return sum;
}

TrigPolynomial TrigPolynomial::derivative() const {
  TrigPolynomial d;
  for (int m = 1; m <= kMaxDegree; ++m) {
    const auto i = static_cast<std::size_t>(m - 1);
    d.cos_coeff[i] = m * sin_coeff[i];
    d.sin_coeff[i] = -m * cos_coeff[i];
  }
  return d;
}

double TrigPolynomial::magnitude() const {
  double m = std::fabs(constant);
  for (int i = 0; i < kMaxDegree; ++i)
    m = std::max({m, std::fabs(cos_coeff[static_cast<std::size_t>(i)]), std::fabs(sin_coeff[static_cast<std::size_t>(i)])});
  return m;
}

TrigPolynomial operator+(const TrigPolynomial& f, const TrigPolynomial& g) {
  TrigPolynomial h = f;
  h.constant += g.constant;
  for (std::size_t i = 0; i < h.cos_coeff.size(); ++i) {
    h.cos_coeff[i] += g.cos_coeff[i];
    h.sin_coeff[i] += g.sin_coeff[i];
  }
  return h;
}

TrigPolynomial operator*(double s, const TrigPolynomial& f) {
  TrigPolynomial h = f;
  h.constant *= s;
  for (std::size_t i = 0; i < h.cos_coeff.size(); ++i) {
    h.cos_coeff[i] *= s;
    h.sin_coeff[i] *= s;
  }
  return h;
}

TrigPolynomial operator-(const TrigPolynomial& f, const TrigPolynomial& g) { return f + (-1.0) * g; }

TrigPolynomial operator*(const TrigPolynomial& f, const TrigPolynomial& g) {
  // The product's exponential coefficients are the convolution of the factors'.
  const int nf = f.degree(), ng = g.degree();
  SSIMARCH_EXPECTS(nf + ng <= TrigPolynomial::kMaxDegree, "trigonometric polynomial product above degree 4");
  const auto F = exponential_coefficients(f, nf), G = exponential_coefficients(g, ng);
  TrigPolynomial h;
  for (int m = 0; m <= nf + ng; ++m) {
    Complex Hm = 0;
    for (int j = -nf; j <= nf; ++j)
      if (std::abs(m - j) <= ng) Hm += F[static_cast<std::size_t>(j + nf)] * G[static_cast<std::size_t>(m - j + ng)];
    if (m == 0) {
      h.constant = Hm.real();
    } else {
      h.cos_coeff[static_cast<std::size_t>(m - 1)] = 2 * Hm.real();
      h.sin_coeff[static_cast<std::size_t>(m - 1)] = -2 * Hm.imag();
    }
  }
  return h;
}

TrigPolynomial bilinear_form(const std::array<Eigen::Vector4d, 3>& u, const Eigen::Matrix4d& q,
                             const std::array<Eigen::Vector4d, 3>& v) {
  // u^T Q v = sum_ij (u_i^T Q v_j) e_i e_j with e = (1, cos, sin); cos^2 = (1 + cos 2)/2,
  // sin^2 = (1 - cos 2)/2, cos sin = sin 2 / 2.
  double k[3][3];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) k[i][j] = u[i].dot(q * v[j]);
  TrigPolynomial f;
  f.constant = k[0][0] + 0.5 * (k[1][1] + k[2][2]);
  f.cos_coeff[0] = k[1][0] + k[0][1];
  f.sin_coeff[0] = k[2][0] + k[0][2];
  f.cos_coeff[1] = 0.5 * (k[1][1] - k[2][2]);
  f.sin_coeff[1] = 0.5 * (k[1][2] + k[2][1]);
  return f;
}

double trig_root_in(const TrigPolynomial& f, double lo, double hi) {
  const TrigPolynomial df = f.derivative();
  const bool lo_negative = f(lo) < 0;
  double x = 0.5 * (lo + hi);
  // A pass whose bracket did not halve since the last halving is followed by the midpoint, so
  // the bracket halves at least every second pass: at most 2 log2(width / resolution) passes.
  double halved_at = hi - lo;
  while (hi - lo > kRootResolution * std::max(1.0, std::fabs(x))) {
    const double fx = f(x);
    if (fx == 0) return x;
    ((fx < 0) == lo_negative ? lo : hi) = x;
    const double newton = x - fx / df(x);
    const bool inside = newton > lo && newton < hi;
    if (inside && std::fabs(newton - x) <= kRootResolution * std::max(1.0, std::fabs(x))) return newton;
    if (hi - lo <= 0.5 * halved_at) {
      halved_at = hi - lo;
      x = inside ? newton : 0.5 * (lo + hi);
    } else {
      x = 0.5 * (lo + hi);
    }
    if (!(x > lo && x < hi)) break;  // adjacent doubles
  }
  return x;
}

std::vector<double> trig_sign_changes(const TrigPolynomial& f) {
  // Leading coefficients at rounding level of the largest one are dropped: they would put roots
  // of P near 0 and infinity and scale the companion matrix badly, and change f by less than
  // its rounding error.
  const double negligible = std::numeric_limits<double>::epsilon() * f.magnitude();
  int n = f.degree();
  while (n > 0 && std::fabs(f.cos_coeff[static_cast<std::size_t>(n - 1)]) <= negligible &&
         std::fabs(f.sin_coeff[static_cast<std::size_t>(n - 1)]) <= negligible)
    --n;
  if (n == 0) return {};
  // Roots of P(z) = z^n f: the eigenvalues of its companion matrix (monic: divided by F_n).
  const auto F = exponential_coefficients(f, n);
  const int N = 2 * n;
  using Matrix = Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRoots, kMaxRoots>;
  Matrix C = Matrix::Zero(N, N);
  for (int i = 1; i < N; ++i) C(i, i - 1) = 1;
  for (int i = 0; i < N; ++i) C(i, N - 1) = -F[static_cast<std::size_t>(i)] / F[static_cast<std::size_t>(N)];
  const Eigen::ComplexEigenSolver<Matrix> es(C, false);
  std::vector<double> angles;
  for (int i = 0; i < N; ++i) {
    const Complex z = es.eigenvalues()[i];
    if (std::isfinite(z.real()) && std::isfinite(z.imag())) angles.push_back(wrap(std::arg(z)));
  }
  if (angles.empty()) return {};
  std::sort(angles.begin(), angles.end());
  // Clusters of angles (kTrigRootCluster apart at most, around the circle); the test points lie
  // halfway between consecutive clusters, so every real root lies between the two test points
  // around its cluster.
  std::vector<double> tests;
  const std::size_t m = angles.size();
  for (std::size_t i = 0; i < m; ++i) {
    const double next = i + 1 < m ? angles[i + 1] : angles[0] + (2 * std::numbers::pi);
    if (next - angles[i] > kTrigRootCluster) tests.push_back(0.5 * (angles[i] + next));
  }
  if (tests.size() < 2) return {};  // one cluster: an even number of sign changes in it, or none
  std::sort(tests.begin(), tests.end());
  std::vector<double> roots;
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const double lo = tests[i], hi = i + 1 < tests.size() ? tests[i + 1] : tests[0] + (2 * std::numbers::pi);
    if ((f(lo) < 0) != (f(hi) < 0)) roots.push_back(wrap(trig_root_in(f, lo, hi)));
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace ssimarch
