// Adaptive Gauss-Kronrod (7-15) quadrature with an endpoint substitution for square-root behaviour.
//
// Integrands of porosity profiles vanish like sqrt(x - x0) where a circle or line becomes tangent to
// a particle. The substitution x = a + (b - a) (1 - cos(pi t)) / 2 makes such endpoint behaviour
// analytic in t (sqrt(x - a) ~ t), so Gauss-Kronrod converges fast; interior kinks are handled by
// recursive bisection. Error estimate and acceptance as in QUADPACK QK15/QAG (Piessens et al. 1983,
// "QUADPACK", Springer), with the absolute tolerance split evenly between the two halves.
#pragma once

#include <cmath>
#include <numbers>

namespace ssimarch {

enum class QuadStatus {
  kConverged,  ///< estimated |error| <= abs_tol (or at the rounding floor of the rule)
  kMaxDepth,   ///< bisection depth or rule-call budget exhausted; `error` is the remaining estimate
};

struct QuadResult {
  double value = 0.0;
  double error = 0.0;     ///< estimated absolute error (sum over accepted subintervals)
  long evaluations = 0;
  QuadStatus status = QuadStatus::kConverged;
  bool roundoff_limited = false;  ///< the error estimate is the rounding floor of the rule itself

  QuadResult& operator+=(const QuadResult& o) {
    value += o.value;
    error += o.error;
    evaluations += o.evaluations;
    if (o.status != QuadStatus::kConverged) status = o.status;
    return *this;
  }
};

/// Default bisection depth limit of the adaptive integrators (intervals down to 2^-40 of the range).
inline constexpr int kQuadMaxDepth = 40;
/// Default budget of 15-point rule applications per integral: noisy integrands (values known only to
/// a few ulps more than the rule's rounding floor) must not split into 2^depth pieces.
inline constexpr int kQuadMaxRules = 2000;

namespace internal {

// QUADPACK qk15 abscissae (Kronrod) and weights; odd indices are the 7-point Gauss nodes.
inline constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                   0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                   0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                   0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
inline constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                   0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                   0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                   0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
inline constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                  0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <class F>
QuadResult gk15(F& f, double a, double b) {
  const double c = (a + b) / 2, h = (b - a) / 2;
  const double fc = f(c);
  double resk = fc * kWgk[7], resg = fc * kWg[3], resabs = std::abs(resk);
  double fv[15];
  fv[7] = fc;
  for (int j = 0; j < 7; ++j) {
    const double dx = h * kXgk[j];
    const double f1 = f(c - dx), f2 = f(c + dx);
    fv[j] = f1;
    fv[14 - j] = f2;
    resk += kWgk[j] * (f1 + f2);
    resabs += kWgk[j] * (std::abs(f1) + std::abs(f2));
    if (j % 2 == 1) resg += kWg[j / 2] * (f1 + f2);
  }
  const double mean = resk / 2;
  double resasc = kWgk[7] * std::abs(fc - mean);
  for (int j = 0; j < 7; ++j) resasc += kWgk[j] * (std::abs(fv[j] - mean) + std::abs(fv[14 - j] - mean));
  QuadResult r;
  r.value = resk * h;
  resasc *= std::abs(h);
  double err = std::abs((resk - resg) * h);
  if (resasc != 0.0 && err != 0.0) err = resasc * std::min(1.0, std::pow(200.0 * err / resasc, 1.5));
  const double round = 50.0 * 2.220446049250313e-16 * resabs * std::abs(h);
  if (round >= err) {
    err = round;
    r.roundoff_limited = true;  // further bisection cannot improve this interval
  }
  r.error = err;
  r.evaluations = 15;
  return r;
}

template <class F>
QuadResult adapt(F& f, double a, double b, double tol, int depth, const QuadResult& whole, int& budget) {
  if (whole.error <= tol || whole.roundoff_limited) return whole;
  if (depth <= 0 || budget < 2 || !(b - a > 4 * 2.220446049250313e-16 * std::max(std::abs(a), std::abs(b)))) {
    QuadResult r = whole;
    r.status = QuadStatus::kMaxDepth;
    return r;
  }
  const double m = (a + b) / 2;
  const QuadResult left = gk15(f, a, m), right = gk15(f, m, b);
  budget -= 2;
  QuadResult out = adapt(f, a, m, tol / 2, depth - 1, left, budget);
  out += adapt(f, m, b, tol / 2, depth - 1, right, budget);
  out.evaluations += whole.evaluations;
  return out;
}

}  // namespace internal

/// Integral of f over [a, b] to absolute tolerance abs_tol (model units of the integral).
template <class F>
QuadResult integrate(F&& f, double a, double b, double abs_tol, int max_depth = kQuadMaxDepth,
                     int max_rules = kQuadMaxRules) {
  if (!(b > a)) return {};
  const QuadResult whole = internal::gk15(f, a, b);
  int budget = max_rules - 1;
  return internal::adapt(f, a, b, abs_tol, max_depth, whole, budget);
}

/// Integral of f over [a, b] where f may behave like sqrt(x - a) and sqrt(b - x) at the ends
/// (substitution x = a + (b - a)(1 - cos(pi t))/2, t in [0, 1]).
template <class F>
QuadResult integrate_sqrt_ends(F&& f, double a, double b, double abs_tol, int max_depth = kQuadMaxDepth) {
  if (!(b > a)) return {};
  const double pi = std::numbers::pi;
  const double w = b - a;
  auto g = [&](double t) {
    const double x = a + w * (1 - std::cos(pi * t)) / 2;
    return f(x) * w * pi / 2 * std::sin(pi * t);
  };
  return integrate(g, 0.0, 1.0, abs_tol, max_depth);
}

}  // namespace ssimarch
