#include "ssimarch/singular/local_jet.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace ssimarch {

std::vector<double> homogeneous_part(const LocalJet& h, int d) {
  std::vector<double> c(static_cast<std::size_t>(d + 1));
  for (int j = 0; j <= d; ++j) c[static_cast<std::size_t>(j)] = coef(h, d - j, j);
  return c;
}

LocalValue evaluate(const LocalJet& h, const Vec2& st) {
  // Powers of s and t, then the sum of c_ij s^i t^j and its first and second derivatives.
  std::array<double, kLocalOrder + 1> ps{}, pt{};
  ps[0] = pt[0] = 1.0;
  for (int k = 1; k <= kLocalOrder; ++k) {
    ps[static_cast<std::size_t>(k)] = ps[static_cast<std::size_t>(k - 1)] * st[0];
    pt[static_cast<std::size_t>(k)] = pt[static_cast<std::size_t>(k - 1)] * st[1];
  }
  auto P = [](const std::array<double, kLocalOrder + 1>& p, int k) { return k < 0 ? 0.0 : p[static_cast<std::size_t>(k)]; };
  LocalValue r;
  for (int d = 0; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) {
      const int i = d - j;
      const double c = coef(h, i, j);
      if (c == 0.0) continue;
      r.value += c * P(ps, i) * P(pt, j);
      r.gradient[0] += c * i * P(ps, i - 1) * P(pt, j);
      r.gradient[1] += c * j * P(ps, i) * P(pt, j - 1);
      r.hessian(0, 0) += c * i * (i - 1) * P(ps, i - 2) * P(pt, j);
      r.hessian(0, 1) += c * i * j * P(ps, i - 1) * P(pt, j - 1);
      r.hessian(1, 1) += c * j * (j - 1) * P(ps, i) * P(pt, j - 2);
    }
  r.hessian(1, 0) = r.hessian(0, 1);
  return r;
}

LocalJet partial(const LocalJet& h, int var) {
  LocalJet r;
  for (int d = 1; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) {
      const int i = d - j;
      if (var == 0 && i > 0) set_coef(r, i - 1, j, coef(h, i, j) * i);
      if (var == 1 && j > 0) set_coef(r, i, j - 1, coef(h, i, j) * j);
    }
  return r;
}

LocalJet linear_substitution(const LocalJet& h, const Eigen::Matrix2d& A) {
  const LocalJet S = LocalJet::variable(0, 0.0), T = LocalJet::variable(1, 0.0);
  std::array<LocalJet, 2> st = {A(0, 0) * S + A(0, 1) * T, A(1, 0) * S + A(1, 1) * T};
  LocalJet r = compose<2, 2, kLocalOrder>(h, st);
  r[0] = h[0];
  return r;
}

LocalJet shifted(const LocalJet& h, const Vec2& z) {
  std::array<LocalJet, kLocalOrder + 1> S, T;
  S[0] = T[0] = LocalJet(1.0);
  const LocalJet s = LocalJet::variable(0, z[0]), t = LocalJet::variable(1, z[1]);
  for (int k = 1; k <= kLocalOrder; ++k) {
    S[static_cast<std::size_t>(k)] = S[static_cast<std::size_t>(k - 1)] * s;
    T[static_cast<std::size_t>(k)] = T[static_cast<std::size_t>(k - 1)] * t;
  }
  LocalJet r;
  for (int d = 0; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) {
      const double c = coef(h, d - j, j);
      if (c != 0.0) r += c * (S[static_cast<std::size_t>(d - j)] * T[static_cast<std::size_t>(j)]);
    }
  return r;
}

LocalJet in_germ_units(const LocalJet& h, double length) {
  if (length == 1.0) return h;
  LocalJet r = h;
  double w = 1.0 / length;  // length^(d - 1), d = 0, 1, ...
  for (int d = 0; d <= kLocalOrder; ++d, w *= length)
    for (int j = 0; j <= d; ++j) r[d * (d + 1) / 2 + j] *= w;
  return r;
}

double germ_length(const LocalJet& h, double cap, int gap_degree) {
  double length = cap;
  for (int d = gap_degree + 1; d <= kLocalOrder; ++d) {
    double m = 0;
    for (int j = 0; j <= d; ++j) m = std::max(m, std::fabs(coef(h, d - j, j)));
    if (m > 0) length = std::min(length, std::pow(m, -1.0 / (d - gap_degree)));
  }
  return length;
}

double germ_scale(const LocalJet& h) {
  double m = 0;
  for (int i = 3; i < LocalJet::kSize; ++i) m = std::max(m, std::fabs(h[i]));
  return m;
}

LocalJet clean(const LocalJet& h, double relative) {
  LocalJet r = h;
  const double floor = relative * germ_scale(h);
  for (int i = 0; i < LocalJet::kSize; ++i)
    if (std::fabs(r[i]) <= floor) r[i] = 0.0;
  return r;
}

namespace {

using Poly = std::vector<double>;  // coefficients of z^0, z^1, ...

Poly multiply(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

double form_value(const std::vector<double>& c, double s, double t) {
  const int d = static_cast<int>(c.size()) - 1;
  double v = 0;
  for (int j = 0; j <= d; ++j) v += c[static_cast<std::size_t>(j)] * std::pow(s, d - j) * std::pow(t, j);
  return v;
}

}  // namespace

std::vector<FormRoot> binary_form_roots(const std::vector<double>& c, int* complex_roots, int* distinct_roots) {
  const int d = static_cast<int>(c.size()) - 1;
  std::vector<FormRoot> out;
  if (complex_roots) *complex_roots = 0;
  if (distinct_roots) *distinct_roots = 0;
  if (d < 1) return out;
  // Rotate so that the form is largest along the new s'-axis: then no root lies at infinity and
  // the monic polynomial in z = s'/t' is well scaled (Golub & Van Loan §7.4.6, companion matrix).
  double best = -1, theta = 0;
  for (int k = 0; k < 64; ++k) {
    const double a = M_PI * k / 64.0;
    const double v = std::fabs(form_value(c, std::cos(a), std::sin(a)));
    if (v > best) best = v, theta = a;
  }
  if (best <= 0) return out;
  const double cs = std::cos(theta), sn = std::sin(theta);
  // s = cs z - sn, t = sn z + cs  (t' = 1)
  const Poly sz = {-sn, cs}, tz = {cs, sn};
  Poly g(static_cast<std::size_t>(d + 1), 0.0);
  for (int j = 0; j <= d; ++j) {
    Poly term = {c[static_cast<std::size_t>(j)]};
    for (int k = 0; k < d - j; ++k) term = multiply(term, sz);
    for (int k = 0; k < j; ++k) term = multiply(term, tz);
    for (std::size_t k = 0; k < term.size(); ++k) g[k] += term[k];
  }
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(d, d);
  for (int i = 1; i < d; ++i) C(i, i - 1) = 1.0;
  for (int i = 0; i < d; ++i) C(i, d - 1) = -g[static_cast<std::size_t>(i)] / g[static_cast<std::size_t>(d)];
  Eigen::EigenSolver<Eigen::MatrixXd> es(C, false);
  std::vector<std::complex<double>> z(es.eigenvalues().data(), es.eigenvalues().data() + d);
  // Multiple roots split by rounding by about eps^(1/m); 1e-5 groups them up to m = 3 cleanly.
  const double kCluster = 1e-5;
  std::vector<int> group(static_cast<std::size_t>(d), -1);
  int groups = 0;
  for (int i = 0; i < d; ++i) {
    if (group[static_cast<std::size_t>(i)] >= 0) continue;
    group[static_cast<std::size_t>(i)] = groups;
    for (int j = i + 1; j < d; ++j)
      if (group[static_cast<std::size_t>(j)] < 0 &&
          std::abs(z[static_cast<std::size_t>(i)] - z[static_cast<std::size_t>(j)]) <= kCluster * (1 + std::abs(z[static_cast<std::size_t>(i)])))
        group[static_cast<std::size_t>(j)] = groups;
    ++groups;
  }
  if (distinct_roots) *distinct_roots = groups;
  for (int gi = 0; gi < groups; ++gi) {
    std::complex<double> mean = 0;
    int m = 0;
    for (int i = 0; i < d; ++i)
      if (group[static_cast<std::size_t>(i)] == gi) mean += z[static_cast<std::size_t>(i)], ++m;
    mean /= static_cast<double>(m);
    if (std::fabs(mean.imag()) > kCluster * (1 + std::abs(mean))) {
      if (complex_roots) *complex_roots += m;
      continue;
    }
    // The line's angle in [0, pi), so that each line has one canonical direction.
    double angle = std::atan2(sn * mean.real() + cs, cs * mean.real() - sn);
    if (angle < 0) angle += M_PI;
    if (angle >= M_PI - 1e-14) angle -= M_PI;
    if (std::fabs(angle) < 1e-15) angle = 0;
    out.push_back({Vec2(std::cos(angle), std::sin(angle)), m});
  }
  std::sort(out.begin(), out.end(), [](const FormRoot& a, const FormRoot& b) {
    return std::atan2(a.direction[1], a.direction[0]) < std::atan2(b.direction[1], b.direction[0]);
  });
  return out;
}

}  // namespace ssimarch
