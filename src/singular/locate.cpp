#include "ssimarch/singular/locate.hpp"

#include "ssimarch/singular/classify.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace ssimarch {

std::string_view to_string(LocateStatus s) {
  switch (s) {
    case LocateStatus::kConverged: return "converged";
    case LocateStatus::kNotSingular: return "not_singular";
    case LocateStatus::kFailed: return "failed";
  }
  return "?";
}

namespace {

struct Residual {
  Eigen::Vector3d r;
  Eigen::Matrix<double, 3, 2> J;
  double cost() const { return r.squaredNorm(); }
};

Residual augmented(const LocalJet& h, const Vec2& z) {
  LocalValue v = evaluate(h, z);
  // Third derivatives enter J only through the Hessian rows: d(h_s)/d(s,t) = Hess row 0, etc.
  Residual R;
  R.r << v.value, v.gradient[0], v.gradient[1];
  R.J.row(0) = v.gradient.transpose();
  R.J.row(1) = v.hessian.row(0);
  R.J.row(2) = v.hessian.row(1);
  return R;
}

// Gauss-Newton step with the columns scaled to unit norm: at A_k the kernel column is O(t^(k-1))
// while the other is O(1); scaling keeps the 3 x 2 least-squares problem well conditioned.
Vec2 gauss_newton_step(const Residual& R) {
  Vec2 scale(R.J.col(0).norm(), R.J.col(1).norm());
  Eigen::Matrix<double, 3, 2> A = R.J;
  for (int c = 0; c < 2; ++c) {
    if (scale[c] > 0)
      A.col(c) /= scale[c];
    else
      scale[c] = 1.0, A.col(c).setZero();
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 3, 2>> cod;
  cod.setThreshold(1e-12);
  cod.compute(A);
  Vec2 y = cod.solve(-R.r);
  return Vec2(y[0] / scale[0], y[1] / scale[1]);
}

// Where the Taylor polynomial is a faithful model: the root test on its coefficients, with the
// quadratic and cubic parts (one of which is O(1) at any singular point of multiplicity <= 3)
// as reference: rho = min_d (M / |h_d|)^(1/(d-2)) (Cauchy-Hadamard, one term at a time).
double model_radius(const LocalJet& h) {
  auto degree_max = [&](int d) {
    double m = 0;
    for (int j = 0; j <= d; ++j) m = std::max(m, std::fabs(coef(h, d - j, j)));
    return m;
  };
  const double M = std::max(degree_max(2), degree_max(3));
  double rho = std::numeric_limits<double>::infinity();
  if (!(M > 0)) return rho;
  for (int d = 3; d <= kLocalOrder; ++d) {
    const double c = degree_max(d);
    if (c > 0) rho = std::min(rho, std::pow(M / c, 1.0 / (d - 2)));
  }
  return rho;
}

// Value and derivative of the n-th derivative of the univariate polynomial p at y.
std::pair<double, double> derivative_at(const Taylor<kLocalOrder>& p, int n, double y) {
  double v = 0, dv = 0;
  for (int j = kLocalOrder; j >= n; --j) {
    double f = 1;  // j! / (j - n)!
    for (int i = j - n + 1; i <= j; ++i) f *= i;
    dv = dv * y + v;
    v = v * y + p[j] * f;
  }
  return {v, dv};
}

// At a corank-1 point the solutions of grad h = 0 near z form a cluster of mu roots along a
// curved valley where Gauss-Newton crawls. Straighten it with the splitting lemma at z:
// h(X(Y), Y) = phi(Y) has a root of multiplicity m = k+1 at the singular point, which is a
// simple root of phi^(m-1) (docs/math/singular_local_curve.md §3). m is read off the jet as the
// index maximising |phi_j| rho^j (the Newton polygon's break for a cluster closer than rho).
Vec2 refine_corank_one(const LocalJet& h, const Vec2& z, double radius) {
  LocalJet g = shifted(h, z);
  Eigen::Matrix2d H;
  H << 2 * coef(g, 2, 0), coef(g, 1, 1), coef(g, 1, 1), 2 * coef(g, 0, 2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(H);
  const Vec2 ev = es.eigenvalues();
  const int big = std::fabs(ev[1]) >= std::fabs(ev[0]) ? 1 : 0;
  // Corank 1 for sure: one Hessian eigenvalue is small, the other is not (near a corank-2 point
  // both are O(distance) while the cubic terms are O(1)).
  double cubic_and_up = 0;
  for (int i = 6; i < LocalJet::kSize; ++i) cubic_and_up = std::max(cubic_and_up, std::fabs(g[i]));
  if (!(std::fabs(ev[1 - big]) <= 0.1 * std::fabs(ev[big])) || !(std::fabs(ev[big]) >= 1e-3 * cubic_and_up)) return z;
  Eigen::Matrix2d axes;
  axes.col(0) = es.eigenvectors().col(big);
  axes.col(1) = es.eigenvectors().col(1 - big);
  g = linear_substitution(g, axes);
  double x0 = 0;  // the valley floor at Y = 0: g_X(x0, 0) = 0
  for (int it = 0; it < 60; ++it) {
    LocalValue v = evaluate(g, Vec2(x0, 0));
    if (!(std::fabs(v.hessian(0, 0)) > 0)) return z;
    const double dx = v.gradient[0] / v.hessian(0, 0);
    x0 -= dx;
    if (std::fabs(dx) <= 1e-17 * (1 + std::fabs(x0))) break;
  }
  if (!(std::fabs(x0) <= radius)) return z;
  g = shifted(g, Vec2(x0, 0));
  const SplittingLemma s = [&] {
    SplittingLemma r = eliminate_first_variable(g);
    r.phi[0] = g[0];
    return r;
  }();
  const double rho = 0.1 * std::min(radius, model_radius(g));
  int m = 1;
  double best = 0;
  for (int j = 1; j <= kLocalOrder; ++j) {
    const double w = std::fabs(s.phi[j]) * std::pow(rho, j);
    if (w > best) best = w, m = j;
  }
  if (m < 2) return z;
  double y = 0;
  for (int it = 0; it < 60; ++it) {
    auto [v, dv] = derivative_at(s.phi, m - 1, y);
    if (!(std::fabs(dv) > 0)) break;
    const double dy = v / dv;
    y -= dy;
    if (std::fabs(dy) <= 1e-17 * (1 + std::fabs(y))) break;
  }
  if (!(std::fabs(y) <= radius)) return z;
  double X = 0, p = 1;
  for (int j = 0; j <= kLocalOrder; ++j, p *= y) X += s.x_of_y[j] * p;
  return z + axes * Vec2(x0 + X, y);
}

}  // namespace

Vec2 solve_augmented_system(const LocalJet& h, const Vec2& start, double radius, int max_iterations) {
  Vec2 z = start;
  Residual R = augmented(h, z);
  for (int it = 0; it < max_iterations && R.cost() > 0; ++it) {
    Vec2 d = gauss_newton_step(R);
    if (!d.allFinite()) break;
    const double len = d.norm();
    if (len > radius) d *= radius / len;
    bool improved = false;
    for (int halvings = 0; halvings < 40; ++halvings, d *= 0.5) {
      Vec2 zn = z + d;
      if ((zn - start).norm() > radius) continue;
      Residual Rn = augmented(h, zn);
      if (Rn.cost() < R.cost()) {
        z = zn;
        R = Rn;
        improved = true;
        break;
      }
    }
    if (!improved || d.norm() <= 1e-17 * (1 + z.norm())) break;
  }
  return refine_corank_one(h, z, radius);
}

SingularLocation locate_singular_point(const Problem& problem, const VecX& guess, const LocateOptions& options) {
  SingularLocation out;
  out.x = guess;
  const double scale = problem.scale();
  const double radius = options.trust_radius * problem.scale();
  VecX x = guess;
  double previous = std::numeric_limits<double>::infinity();
  LocalCurve c;
  for (int k = 0; k < options.max_expansions; ++k) {
    c = local_curve(problem, x);
    ++out.expansions;
    if (c.status != LocalCurveStatus::kOk) return out;
    // In germ units (LocalCurve::germ_length) h and its gradient are alike in size and the
    // radius tests weigh degrees the same at every model size.
    const LocalJet g = in_germ_units(c.h, c.germ_length);
    const Vec2 z =
        c.germ_length * solve_augmented_system(g, Vec2::Zero(), std::min(radius / c.germ_length, model_radius(g)),
                                               options.max_inner_iterations);
    out.last_step = z.norm();
    x = c.unknowns_at(z);
    // Stop at the rounding floor: the move no longer shrinks (at most once more after that).
    if (z.norm() <= 1e-16 * scale || (k >= 2 && z.norm() >= 0.5 * previous)) break;
    previous = z.norm();
  }
  c = local_curve(problem, problem.wrap(x));
  if (c.status != LocalCurveStatus::kOk) return out;
  out.x = c.base;
  out.point = c.origin;
  LocalValue v = evaluate(c.h, Vec2::Zero());
  out.gap = std::fabs(v.value);
  out.sine = v.gradient.norm();
  const bool meets = out.gap <= options.gap_tolerance * scale;
  out.status = (meets && out.sine <= options.sine_tolerance) ? LocateStatus::kConverged : LocateStatus::kNotSingular;
  return out;
}

}  // namespace ssimarch
