#include "ssimarch/singular/puiseux.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace ssimarch {

namespace {

// Truncated power series in tau = X^(1/Q): enough orders for the whole jet, (kLocalOrder + 1) Q,
// with Q up to kMaxDenominator. core/jet.hpp stops at order 12, so a plain coefficient array here.
constexpr int kMaxDenominator = 6;
constexpr int kSeriesOrder = (kLocalOrder + 1) * kMaxDenominator + 2;
struct PuiseuxSeries {
  std::array<double, kSeriesOrder + 1> c{};
  double& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  double operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
};
PuiseuxSeries operator*(const PuiseuxSeries& a, const PuiseuxSeries& b) {
  PuiseuxSeries r;
  for (int i = 0; i <= kSeriesOrder; ++i)
    if (a[i] != 0.0)
      for (int j = 0; i + j <= kSeriesOrder; ++j) r[i + j] += a[i] * b[j];
  return r;
}

// The lowest order of s with a coefficient above tol (or -1).
int order_of(const PuiseuxSeries& s, double tol) {
  for (int i = 0; i <= kSeriesOrder; ++i)
    if (std::fabs(s[i]) > tol) return i;
  return -1;
}

// g_k(tau), the coefficient of V^k in H(tau^Q, W(tau) + V) = sum c_ij X^i (W + V)^j, k = 0..K:
// g_k = sum_(i, j >= k) c_ij binom(j, k) tau^(Q i) W^(j-k) (X = tau^Q is a shift).
std::array<PuiseuxSeries, kLocalOrder + 1> shifted_coefficients(const LocalJet& H, int Q, const PuiseuxSeries& W) {
  std::array<PuiseuxSeries, kLocalOrder + 1> wp{}, g{};
  wp[0][0] = 1.0;
  for (std::size_t j = 1; j <= kLocalOrder; ++j) wp[j] = wp[j - 1] * W;
  for (int d = 0; d <= kLocalOrder; ++d)
    for (int j = 0; j <= d; ++j) {
      const double c = coef(H, d - j, j);
      const int shift = Q * (d - j);
      if (c == 0.0 || shift > kSeriesOrder) continue;
      double binom = 1;  // binom(j, k), k = 0..j
      for (int k = 0; k <= j; ++k) {
        const PuiseuxSeries& w = wp[static_cast<std::size_t>(j - k)];
        PuiseuxSeries& out = g[static_cast<std::size_t>(k)];
        for (int i = 0; i + shift <= kSeriesOrder; ++i) out[i + shift] += c * binom * w[i];
        binom = binom * (j - k) / (k + 1);
      }
    }
  return g;
}

// P^(n)(c) / n! and its derivative for P(c) = sum p_k c^k.
std::pair<double, double> poly_derivative(const std::vector<double>& p, int n, double c) {
  double v = 0, dv = 0;
  for (int k = static_cast<int>(p.size()) - 1; k >= n; --k) {
    double f = 1;  // k! / ((k - n)! n!)
    for (int i = 1; i <= n; ++i) f = f * (k - n + i) / i;
    dv = dv * c + v;
    v = v * c + p[static_cast<std::size_t>(k)] * f;
  }
  return {v, dv};
}

// The non-zero real roots of P(c) = sum p_k c^k, each refined as a simple root of P^(m-1) where
// it has multiplicity m (a multiple root from the companion matrix is only good to eps^(1/m);
// the branches sharing it are separated at a later term, which that error would swamp).
std::vector<double> real_roots(const std::vector<double>& p) {
  int n = static_cast<int>(p.size()) - 1;
  while (n > 0 && p[static_cast<std::size_t>(n)] == 0.0) --n;
  std::vector<double> out;
  if (n < 1) return out;
  std::vector<double> form(p.begin(), p.begin() + n + 1);  // sum p_k s^(n-k) t^k: roots t/s = c
  for (const FormRoot& r : binary_form_roots(form)) {
    if (!(std::fabs(r.direction[0]) > 1e-12)) continue;
    double c = r.direction[1] / r.direction[0];
    for (int it = 0; it < 60; ++it) {
      const auto [v, dv] = poly_derivative(p, r.multiplicity - 1, c);
      if (!(std::fabs(dv) > 0)) break;
      const double step = v / dv;
      c -= step;
      if (std::fabs(step) <= 1e-16 * (1 + std::fabs(c))) break;
    }
    if (c != 0.0 && std::isfinite(c)) out.push_back(c);
  }
  return out;
}

// One candidate for the next term c tau^a of W (a in units of 1/Q): an edge of the Newton
// polygon of G(tau, V) = H(tau^Q, W + V) with slope a above the last exponent, and a real root.
struct NextTerm {
  int a = 0, den = 1;  // exponent a / den in units of tau (den > 1: Q must grow first)
  double c = 0;
  int balance = 0;     // tau-order L at which the edge's terms cancel
};

// The Newton polygon's edges of slope above `top` (lower hull of the points (k, ord g_k) from
// k = 0), with the real roots of each edge polynomial.
std::vector<NextTerm> next_terms(const std::array<PuiseuxSeries, kLocalOrder + 1>& g, int top, double tol) {
  std::array<int, kLocalOrder + 1> ord{};
  for (std::size_t k = 0; k <= kLocalOrder; ++k) ord[k] = order_of(g[k], tol);
  std::vector<NextTerm> out;
  int kc = 0;
  while (kc < kLocalOrder) {
    int best = -1;  // the next hull vertex: the least slope, the farthest k on ties
    for (int k = kc + 1; k <= kLocalOrder; ++k) {
      if (ord[static_cast<std::size_t>(k)] < 0) continue;
      if (best < 0) { best = k; continue; }
      const long lhs = static_cast<long>(ord[static_cast<std::size_t>(k)] - ord[static_cast<std::size_t>(kc)]) * (best - kc);
      const long rhs = static_cast<long>(ord[static_cast<std::size_t>(best)] - ord[static_cast<std::size_t>(kc)]) * (k - kc);
      if (lhs <= rhs) best = k;
    }
    if (best < 0) break;
    const int num = ord[static_cast<std::size_t>(kc)] - ord[static_cast<std::size_t>(best)], den = best - kc;
    if (num <= static_cast<long>(top) * den) break;  // this and every later edge: V no smaller than the last term
    const int gcd = std::gcd(num, den);
    NextTerm t{num / gcd, den / gcd, 0, 0};
    if (t.den == 1) {  // the edge polynomial sum over the edge's points of g_k[L - k a] c^k
      t.balance = ord[static_cast<std::size_t>(kc)] + kc * t.a;
      std::vector<double> P(static_cast<std::size_t>(best + 1), 0.0);
      for (int k = kc; k <= best; ++k) {
        const int i = t.balance - k * t.a;
        if (ord[static_cast<std::size_t>(k)] >= 0 && i >= 0 && i <= kSeriesOrder) P[static_cast<std::size_t>(k)] = g[static_cast<std::size_t>(k)][i];
      }
      for (double c : real_roots(P)) out.push_back({t.a, 1, c, t.balance});
    } else {
      out.push_back(t);
    }
    kc = best;
  }
  return out;
}

// The value of the partial sum W(tau) at X (tau = X^(1/Q)).
double value_at(const PuiseuxSeries& W, int Q, double X) {
  double v = 0;
  for (int i = 0; i <= kSeriesOrder; ++i)
    if (W[i] != 0.0) v += W[i] * std::pow(X, static_cast<double>(i) / Q);
  return v;
}

// W with tau replaced by tau^m (the denominator Q grows to m Q).
PuiseuxSeries refine_denominator(const PuiseuxSeries& W, int m) {
  PuiseuxSeries r;
  for (int i = 0; i * m <= kSeriesOrder; ++i) r[i * m] = W[i];
  return r;
}

}  // namespace

std::pair<int, int> exponent_fraction(double gamma) {
  if (!(gamma > 0)) return {2, 1};
  for (int q = 1; q <= 4; ++q)
    if (std::fabs(gamma * q - std::round(gamma * q)) <= 1e-6 * q) return {static_cast<int>(std::round(gamma * q)), q};
  return {static_cast<int>(std::round(gamma * 4)), 4};
}

namespace {

// The expansion of h as it is: its coefficients of every degree compared at the unit length.
PuiseuxExpansion expansion_at_unit_length(const LocalJet& h, const Vec2& d, double leading, int p, int q, double order,
                                          const Vec2* through) {
  PuiseuxExpansion out;
  Eigen::Matrix2d frame;
  frame.col(0) = d;
  frame.col(1) = Vec2(-d[1], d[0]);
  const LocalJet H = linear_substitution(h, frame);
  const double tol = 1e-10 * std::max(1e-300, germ_scale(H));
  int Q = 1, top = 1;  // W = o(X): the first exponent exceeds 1
  PuiseuxSeries W;
  bool first = true;
  out.complete = false;
  while (true) {
    const auto g = shifted_coefficients(H, Q, W);
    if (order_of(g[0], tol) < 0) {  // W solves H = 0 to the jet's order: nothing more to add
      out.complete = true;
      break;
    }
    const std::vector<NextTerm> cand = next_terms(g, top, tol);
    if (cand.empty()) break;
    // A fractional exponent among the candidates: refine tau first (tau -> tau^m), so that every
    // candidate has an integer exponent and a coefficient to compare.
    int m = 1;
    for (const NextTerm& c : cand) m = std::lcm(m, c.den);
    if (m > 1) {
      if (Q * m > kMaxDenominator) break;
      W = refine_denominator(W, m);
      Q *= m, top *= m;
      continue;
    }
    // The candidate this half-branch follows: through its own point where given (branches that
    // share the terms so far separate here), else the measured leading term for the first one.
    std::size_t pick = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < cand.size(); ++i) {
      const double e = static_cast<double>(cand[i].a) / Q;
      double miss = 0;
      if (through)
        miss = std::fabs((*through)[1] - value_at(W, Q, (*through)[0]) - cand[i].c * std::pow((*through)[0], e));
      else if (first)
        miss = 1e3 * std::fabs(e - static_cast<double>(p) / q) + std::fabs(cand[i].c - leading);
      if (miss < best) best = miss, pick = i;
    }
    const NextTerm& t = cand[pick];
    if (static_cast<double>(t.a) / Q > order + 1e-9) {
      out.complete = true;
      break;
    }
    if (t.balance >= (kLocalOrder + 1) * Q) break;  // decided by monomials beyond the jet
    W[t.a] = t.c;
    top = t.a;
    first = false;
  }
  out.denominator = Q;
  for (int i = 0; i <= kSeriesOrder; ++i)
    if (W[i] != 0.0 && static_cast<double>(i) / Q <= order + 1e-9) out.terms.push_back({static_cast<double>(i) / Q, W[i]});
  out.max_exponent = out.complete ? order : (out.terms.empty() ? 0.0 : out.terms.back().exponent);
  return out;
}

}  // namespace

PuiseuxExpansion puiseux_expansion(const LocalJet& h, const Vec2& d, double leading, int p, int q, double order,
                                   const Vec2* through, double length) {
  if (length == 1.0) return expansion_at_unit_length(h, d, leading, p, q, order, through);
  // In units of the germ length, W = b X^e becomes W~ = b length^(e - 1) X~^e.
  const Vec2 scaled_through = through ? Vec2(*through / length) : Vec2::Zero();
  const double scaled_leading = leading * std::pow(length, static_cast<double>(p) / q - 1.0);
  PuiseuxExpansion out = expansion_at_unit_length(in_germ_units(h, length), d, scaled_leading, p, q, order,
                                                  through ? &scaled_through : nullptr);
  for (PuiseuxTerm& t : out.terms) t.coefficient *= std::pow(length, 1.0 - t.exponent);
  return out;
}

}  // namespace ssimarch
