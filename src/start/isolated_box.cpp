#include "ssimarch/start/isolated_box.hpp"
#include "ssimarch/start/interval_forms.hpp"
#include "ssimarch/start/interval_hessian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace ssimarch {

namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSystemDimension, kMaxSystemDimension>;

// Q = sigma l.H + c |H|^2 (see the header), over any scalar of H.
struct Convexifier {
  VecX l;
  double sigma = 1, c = 0;
  Matrix V;  // eigenvectors of Hess Q(x0): the rotation that makes the interval Hessian nearly diagonal
  bool ok = false;

  template <class T>
  T operator()(const T* h, int m) const {
    T q(0.0);
    for (int r = 0; r < m; ++r) q = q + (sigma * l[r]) * h[r] + c * (h[r] * h[r]);
    return q;
  }
};

// sigma, l, c and V from H's derivatives at x0 (docs/math/isolated_box.md §2): with K the kernel
// of J_H(x0) (two-dimensional at a point where the rank drops by one) and A = sum l_r Hess H_r,
// sigma A must be definite on K (an elliptic tangency); J^T J >= beta on the complement of K, and
// 2 c beta >= |A| + alpha / 2 + 2 |A|^2 / alpha (alpha = the smaller |eigenvalue| of A on K) makes
// Hess Q(x0) >= alpha / 2; c is twice that.
Convexifier choose(const Problem& P, const VecX& x0) {
  const int n = P.dim(), m = n - 1;
  IntervalBox point;
  for (int i = 0; i < n; ++i) point.emplace_back(x0[i]);
  IntervalSecond h[kMaxSystemDimension - 1];
  interval_second_derivatives(P, point, h);
  Matrix J(m, n);
  std::vector<Matrix> hess(static_cast<std::size_t>(m), Matrix(n, n));
  for (int r = 0; r < m; ++r)
    for (int i = 0; i < n; ++i) {
      J(r, i) = h[r].d[static_cast<std::size_t>(i)].v.mid();
      for (int j = 0; j < n; ++j)
        hess[static_cast<std::size_t>(r)](i, j) =
            h[r].d[static_cast<std::size_t>(i)].d[static_cast<std::size_t>(j)].mid();
    }
  Convexifier q;
  if (!J.allFinite()) return q;
  Eigen::JacobiSVD<Matrix> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  q.l = svd.matrixU().col(m - 1);
  const Matrix K = svd.matrixV().rightCols(2);
  Matrix A = Matrix::Zero(n, n);
  for (int r = 0; r < m; ++r) A += q.l[r] * hess[static_cast<std::size_t>(r)];
  if (!A.allFinite()) return q;
  const Eigen::Vector2d e =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(Eigen::Matrix2d(K.transpose() * A * K)).eigenvalues();
  if (!(e[0] * e[1] > 0)) return q;  // saddle or degenerate on the kernel: not an isolated point
  q.sigma = e[0] > 0 ? 1.0 : -1.0;
  const double alpha = std::min(std::abs(e[0]), std::abs(e[1]));
  const double a = Eigen::SelfAdjointEigenSolver<Matrix>(A).eigenvalues().cwiseAbs().maxCoeff();
  if (m >= 2) {
    const double s = svd.singularValues()[m - 2];
    if (!(s > 0)) return q;
    q.c = 2 * (a + 0.5 * alpha + 2 * a * a / alpha) / (2 * s * s);
  }
  const Matrix M = q.sigma * A + 2 * q.c * J.transpose() * J;
  Eigen::SelfAdjointEigenSolver<Matrix> es(M);
  if (!(es.eigenvalues()[0] > 0)) return q;
  q.V = es.eigenvectors();
  q.ok = true;
  return q;
}

// A lower bound of the eigenvalues of every symmetric matrix in the interval matrix H (n x n):
// Gershgorin's discs of R = V^T H V, divided by |V|^2 <= the largest Gershgorin bound of V^T V
// (for d = V z: d^T H d = z^T R z >= lambda' |z|^2 >= lambda' |d|^2 / |V|^2; V is invertible
// when V^T V's discs exclude 0). Returns 0 or less where nothing positive is proven.
double least_eigenvalue(const IntervalNumber (&H)[kMaxSystemDimension][kMaxSystemDimension], const Matrix& V, int n) {
  IntervalNumber R[kMaxSystemDimension][kMaxSystemDimension], W[kMaxSystemDimension][kMaxSystemDimension];
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      IntervalNumber r(0.0), w(0.0);
      for (int i = 0; i < n; ++i) {
        w = w + IntervalNumber(V(i, a)) * IntervalNumber(V(i, b));
        for (int j = 0; j < n; ++j) r = r + IntervalNumber(V(i, a)) * H[i][j] * IntervalNumber(V(j, b));
      }
      R[a][b] = r;
      W[a][b] = w;
    }
  double lower = std::numeric_limits<double>::infinity(), w_min = lower, w_max = 0;
  for (int a = 0; a < n; ++a) {
    IntervalNumber off(0.0), w_off(0.0);
    for (int b = 0; b < n; ++b)
      if (b != a) {
        off = off + IntervalNumber(R[a][b].magnitude());
        w_off = w_off + IntervalNumber(W[a][b].magnitude());
      }
    lower = std::min(lower, (R[a][a] - off).lo());
    w_min = std::min(w_min, (W[a][a] - w_off).lo());
    w_max = std::max(w_max, (W[a][a] + w_off).hi());
  }
  if (!(lower > 0) || !(w_min > 0)) return 0;
  return (IntervalNumber(lower) / IntervalNumber(w_max)).lo();
}

// An upper bound of the spectral norm of the point map's Jacobian over the box: sqrt of the
// largest absolute row sum times the largest absolute column sum (|A|_2^2 <= |A|_1 |A|_inf).
double point_lipschitz(const Problem& P, const IntervalBox& box) {
  IntervalGradient x[kMaxSystemDimension];
  for (int i = 0; i < P.dim(); ++i) x[i] = IntervalGradient(box[static_cast<std::size_t>(i)], i);
  const Vec3T<IntervalGradient> p = P.point(x);
  const IntervalGradient* rows[3] = {&p.x, &p.y, &p.z};
  IntervalNumber row_max(0.0), col_max(0.0);
  for (int i = 0; i < P.dim(); ++i) {
    IntervalNumber col(0.0);
    for (const IntervalGradient* r : rows) col = col + IntervalNumber(r->d[static_cast<std::size_t>(i)].magnitude());
    col_max = IntervalNumber(std::max(col_max.hi(), col.hi()));
  }
  for (const IntervalGradient* r : rows) {
    IntervalNumber row(0.0);
    for (int i = 0; i < P.dim(); ++i) row = row + IntervalNumber(r->d[static_cast<std::size_t>(i)].magnitude());
    row_max = IntervalNumber(std::max(row_max.hi(), row.hi()));
  }
  return sqrt(row_max * col_max).hi();
}

// |grad g| at a 3D point of an implicit surface.
double gradient_norm(const Surface& surface, const Vec3& p) {
  const Vec3T<IntervalGradient> x(IntervalGradient(IntervalNumber(p.x()), 0),
                                  IntervalGradient(IntervalNumber(p.y()), 1),
                                  IntervalGradient(IntervalNumber(p.z()), 2));
  const IntervalGradient v = surface.value(x);
  return Vec3(v.d[0].mid(), v.d[1].mid(), v.d[2].mid()).norm();
}

// Units of l.H per model unit at x0: l.H divided by it is, to first order, the distance between
// the surfaces near x0 (docs/math/isolated_box.md §3): |l| = 1 for a parametric pair (H = F - G
// in model units), |grad g| for a parametric-implicit pair, and |l_1 grad f| = |l_2 grad g| for
// an implicit pair (equal at x0, where l^T J_H = 0; their mean is taken).
double model_unit(const Problem& P, const VecX& x0, const VecX& l) {
  switch (P.kind()) {
    case PairKind::kParametricParametric: return l.norm();
    case PairKind::kParametricImplicit: return std::abs(l[0]) * gradient_norm(P.second(), P.point(x0));
    case PairKind::kImplicitImplicit: {
      const Vec3 p(x0[0], x0[1], x0[2]);
      return 0.5 * (std::abs(l[0]) * gradient_norm(P.first(), p) + std::abs(l[1]) * gradient_norm(P.second(), p));
    }
  }
  return 0;
}

}  // namespace

IsolatedBoxResult decide_isolated_box(const Problem& P, const VecX& x0, const IntervalBox& box, double max_radius,
                                      double max_depth) {
  IsolatedBoxResult out;
  const int n = P.dim(), m = n - 1;
  for (int i = 0; i < n; ++i)
    if (!box[static_cast<std::size_t>(i)].contains(x0[i])) return out;  // Taylor's theorem is taken from x0 in the box
  const Convexifier q = choose(P, x0);
  if (!q.ok) return out;
  // Hess Q over the box.
  IntervalSecond h[kMaxSystemDimension - 1];
  interval_second_derivatives(P, box, h);
  const IntervalSecond qs = q(h, m);
  IntervalNumber H[kMaxSystemDimension][kMaxSystemDimension];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) H[i][j] = qs.d[static_cast<std::size_t>(i)].d[static_cast<std::size_t>(j)];
  out.lambda = least_eigenvalue(H, q.V, n);
  if (!(out.lambda > 0)) return out;
  // Q and grad Q at x0, enclosed.
  IntervalGradient x[kMaxSystemDimension], hp[kMaxSystemDimension - 1];
  for (int i = 0; i < n; ++i) x[i] = IntervalGradient(IntervalNumber(x0[i]), i);
  P.residual(x, hp);
  const IntervalGradient q0 = q(hp, m);
  IntervalNumber g2(0.0);
  for (int i = 0; i < n; ++i) {
    const IntervalNumber g(q0.d[static_cast<std::size_t>(i)].magnitude());
    g2 = g2 + g * g;
  }
  const IntervalNumber lambda(out.lambda);
  const IntervalNumber disc = g2 - 2.0 * lambda * IntervalNumber(q0.v.lo());
  if (disc.hi() < 0) {  // Q > 0 on the whole box: no point of the curve in it
    out.decided = true;
    return out;
  }
  // min Q over the box >= q0 - G^2 / (2 lambda) = -depth; in model units through model_unit.
  const double unit = model_unit(P, x0, q.l);
  if (!(unit > 0)) return out;
  out.depth = std::max(0.0, (g2 / (2.0 * lambda) - IntervalNumber(q0.v.lo())).hi()) / unit;
  const IntervalNumber root(std::max(0.0, disc.lo()), disc.hi());
  const double r = ((sqrt(g2) + sqrt(root)) / lambda).hi();
  out.radius = (IntervalNumber(r) * IntervalNumber(point_lipschitz(P, box))).hi();
  out.decided = std::isfinite(out.radius) && out.radius <= max_radius && out.depth <= max_depth;
  return out;
}

}  // namespace ssimarch
