// Taylor coefficients of an intersection curve through a regular point, to any order K, by the
// implicit function theorem (seed 004 §5, generalised to the three pair kinds of
// problem/problem.hpp; derivation in docs/math/curve_jet.md).
//
// Unknown: x(s) = sum_k c_k s^k with s the arc length of the 3D curve alpha(s) = point(x(s)).
// Conditions, coefficient by coefficient:
//   H(x(s)) = 0          ->  J c_k + [H(x(s))]_k |_{c_k = 0} = 0            (n-1 equations)
//   |alpha'(s)|^2 = 1    ->  2k alpha_1 . (D c_k + a_k) + sum_{i+j=k+1; 2<=i,j<=k-1} i j alpha_i.alpha_j = 0
// with J = dH/dx, D = d point/dx and a_k = [point(x(s))]_k |_{c_k = 0}. The k-th coefficient of
// H(x(s)) is linear in c_k with matrix J because c_k first appears at order k; evaluating H on
// Taylor<K> arguments with c_k = 0 gives every other term exactly. Order 1: c_1 spans ker J,
// scaled so that |D c_1| = 1. The n x n matrix [J; alpha_1^T D] is the same at every order and
// is invertible exactly at regular points.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/jet.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch {

enum class CurveJetStatus {
  kOk,
  // rank ratio of J_H <= kCurveJetRankTolerance (problem/singular_tolerances.hpp): the tangent is not determined
  // (a singular point of the curve: surfaces tangent, or a crossing of branches).
  kSingular,
  // Some derivative of the surfaces is not finite at this point.
  kNonFinite,
};

template <int K>
struct CurveJet {
  CurveJetStatus status = CurveJetStatus::kSingular;
  std::array<UnknownVec, K + 1> x;  // x(s) = sum_k x[k] s^k (unknowns of H)
  std::array<Vec3, K + 1> alpha;  // alpha(s) = sum_k alpha[k] s^k (3D curve, unit speed)
  double rank_ratio = 0;          // sigma_min / sigma_max of J_H (0 at a singular point)
  int orientation = 0;            // +1 / -1: x' along / against the cross product of the rows of J_H (0 if not regular)

  /// d^k alpha / ds^k at s = 0.
  Vec3 derivative(int k) const {
    double f = 1;
    for (int i = 2; i <= k; ++i) f *= i;
    return alpha[static_cast<std::size_t>(k)] * f;
  }
  /// Parameter-space point after a step of arc length s (the Taylor polynomial).
  UnknownVec x_at(double s) const {
    UnknownVec r = x[K];
    for (int k = K - 1; k >= 0; --k) r = (r * s + x[static_cast<std::size_t>(k)]).eval();
    return r;
  }
  Vec3 alpha_at(double s) const {
    Vec3 r = alpha[K];
    for (int k = K - 1; k >= 0; --k) r = r * s + alpha[static_cast<std::size_t>(k)];
    return r;
  }
};

namespace internal {

// Unnormalised J_H (the residual functor's own derivative), D and the point, via first-order
// jets. Fixed-size matrices: a curve jet at every accepted point allocates nothing (issue 12).
template <int N>
void raw_jacobians(const Problem& problem, const UnknownVec& x0, Eigen::Matrix<double, N - 1, N>* J,
                   Eigen::Matrix<double, 3, N>* D, Vec3* point) {
  using J1 = Jet<N, 1>;
  // Sized for the largest pair kind (4 unknowns, 3 equations): residual() switches on the
  // problem's kind at run time, so the compiler cannot see that only N entries are touched.
  std::array<J1, 4> x;
  for (int i = 0; i < N; ++i) x[static_cast<std::size_t>(i)] = J1::variable(i, x0[i]);
  std::array<J1, 3> h;
  const Vec3T<J1> p = problem.residual_and_point(x.data(), h.data());
  for (int r = 0; r < N - 1; ++r)
    for (int c = 0; c < N; ++c) (*J)(r, c) = h[static_cast<std::size_t>(r)].d(c);
  for (int r = 0; r < 3; ++r) {
    (*point)[r] = p[r].value();
    for (int c = 0; c < N; ++c) (*D)(r, c) = p[r].d(c);
  }
}

// Problem::rank_ratio at x0 from the raw J_H the jet has already, without evaluating the
// surfaces again: J_H itself for two parametric surfaces (as linearize builds it), its rows
// normalised for two implicit ones. The parametric-implicit ratio needs |grad g|, which
// J_H = grad g^T DF does not hold: there it linearises.
template <int N>
double raw_rank_ratio(const Problem& problem, const UnknownVec& x0, const Eigen::Matrix<double, N - 1, N>& J,
                      const Eigen::JacobiSVD<Eigen::Matrix<double, N - 1, N>>& svd) {
  switch (problem.kind()) {
    case PairKind::kParametricParametric: return Problem::rank_ratio(svd.singularValues());
    case PairKind::kImplicitImplicit: {
      Eigen::Matrix<double, N - 1, N> normalised = J;
      for (int r = 0; r < N - 1; ++r)
        if (const double n = J.row(r).norm(); n > 0) normalised.row(r) /= n;
      const Eigen::JacobiSVD<Eigen::Matrix<double, N - 1, N>> s(normalised);
      return Problem::rank_ratio(s.singularValues());
    }
    case PairKind::kParametricImplicit: break;
  }
  return Problem::rank_ratio(problem.linearize(x0));
}

// Coefficients k..K of x and alpha (coefficients below k known). Coefficient k of H(x(s)) and
// of point(x(s)) with c_k = 0 depends only on c_0..c_{k-1}: truncated series of order k give it
// exactly, and cost less than order K (a pass of order K would carry K - k coefficients that
// this pass never reads).
template <int N, int K, int k>
void higher_coefficients(const Problem& problem, const Eigen::PartialPivLU<Eigen::Matrix<double, N, N>>& lu,
                         const Eigen::Matrix<double, 3, N>& D, CurveJet<K>* jet) {
  std::array<Taylor<k>, 4> xs;  // sized for the largest pair kind, as in raw_jacobians
  std::array<Taylor<k>, 3> h;
  for (int i = 0; i < N; ++i) {
    Taylor<k> t;
    for (int j = 0; j < k; ++j) t[j] = jet->x[static_cast<std::size_t>(j)][i];
    xs[static_cast<std::size_t>(i)] = t;
  }
  const Vec3T<Taylor<k>> a = problem.residual_and_point(xs.data(), h.data());
  Eigen::Matrix<double, N, 1> rhs;
  for (int r = 0; r < N - 1; ++r) rhs[r] = -h[static_cast<std::size_t>(r)][k];
  const Vec3 ak(a.x[k], a.y[k], a.z[k]);
  double rest = 0;
  for (int i = 2; i <= k - 1; ++i) {
    const int j = k + 1 - i;
    if (j < 2 || j > k - 1) continue;
    rest += i * j * jet->alpha[static_cast<std::size_t>(i)].dot(jet->alpha[static_cast<std::size_t>(j)]);
  }
  rhs[N - 1] = -jet->alpha[1].dot(ak) - rest / (2.0 * k);
  jet->x[static_cast<std::size_t>(k)] = lu.solve(rhs);
  jet->alpha[static_cast<std::size_t>(k)] = D * jet->x[static_cast<std::size_t>(k)] + ak;
  if constexpr (k < K) higher_coefficients<N, K, k + 1>(problem, lu, D, jet);
}

template <int N, int K>
CurveJet<K> curve_jet_n(const Problem& problem, const UnknownVec& x0, const Vec3* hint) {
  CurveJet<K> jet;
  for (auto& c : jet.x) c = UnknownVec::Zero(N);
  for (auto& a : jet.alpha) a = Vec3::Zero();
  jet.x[0] = x0;
  Eigen::Matrix<double, N - 1, N> J;
  Eigen::Matrix<double, 3, N> D;
  raw_jacobians<N>(problem, x0, &J, &D, &jet.alpha[0]);
  if (!J.allFinite() || !D.allFinite()) {
    jet.status = CurveJetStatus::kNonFinite;
    return jet;
  }
  const Eigen::JacobiSVD<Eigen::Matrix<double, N - 1, N>> svd(J, Eigen::ComputeFullV);
  jet.rank_ratio = raw_rank_ratio<N>(problem, x0, J, svd);
  const Eigen::Matrix<double, N, 1> null = svd.matrixV().col(N - 1);
  Vec3 speed = D * null;
  if (jet.rank_ratio <= kCurveJetRankTolerance || speed.norm() == 0) {
    jet.status = CurveJetStatus::kSingular;
    return jet;
  }
  double sign = (hint && speed.dot(*hint) < 0) ? -1.0 : 1.0;
  jet.x[1] = null * (sign / speed.norm());
  jet.alpha[1] = D * jet.x[1];
  {
    // The sign of det [J; x'] says whether the tangent runs along the generalised cross product
    // of the rows of J_H, a field that is continuous along the curve and vanishes only at its
    // singular points: it changes between consecutive points exactly when a step passed a
    // crossing of branches (thesis ch. 5 §5.2.1, Fig. 5.3).
    Eigen::Matrix<double, N, N> M;
    M.topRows(N - 1) = J;
    M.row(N - 1) = jet.x[1].transpose();
    jet.orientation = M.determinant() >= 0 ? 1 : -1;
  }
  if constexpr (K >= 2) {
    Eigen::Matrix<double, N, N> A;
    A.topRows(N - 1) = J;
    A.row(N - 1) = jet.alpha[1].transpose() * D;
    const Eigen::PartialPivLU<Eigen::Matrix<double, N, N>> lu(A);
    higher_coefficients<N, K, 2>(problem, lu, D, &jet);
  }
  bool finite = true;
  for (int k = 0; k <= K; ++k)
    finite = finite && jet.x[static_cast<std::size_t>(k)].allFinite() && jet.alpha[static_cast<std::size_t>(k)].allFinite();
  jet.status = finite ? CurveJetStatus::kOk : CurveJetStatus::kNonFinite;
  return jet;
}

}  // namespace internal

/// The curve's Taylor jet of order K at the solution x0 of problem. `hint`, if given, orients
/// the tangent: alpha'(0) . hint >= 0.
/// Requires: x0 on the curve (H(x0) ~ 0); otherwise the coefficients describe the level set of
/// H through x0.
/// Throws InputError when x0 does not have problem.dim() entries.
template <int K>
CurveJet<K> curve_jet(const Problem& problem, const UnknownVec& x0, const Vec3* hint = nullptr) {
  static_assert(K >= 1, "a curve jet has order >= 1");
  if (x0.size() != problem.dim())
    throw InputError("curve_jet", "the point has " + std::to_string(x0.size()) + " unknowns, the problem " +
                                      std::to_string(problem.dim()));
  switch (problem.dim()) {
    case 2: return internal::curve_jet_n<2, K>(problem, x0, hint);
    case 3: return internal::curve_jet_n<3, K>(problem, x0, hint);
    case 4: return internal::curve_jet_n<4, K>(problem, x0, hint);
  }
  // Problem's constructor admits only the three pair kinds (2, 3 or 4 unknowns).
  throw InputError("curve_jet", "a problem with " + std::to_string(problem.dim()) + " unknowns");
}

/// Highest order curve_jet_dynamic supports (TraceOptions::taylor_order is validated against it).
inline constexpr int kMaxCurveJetOrder = 8;

/// A curve jet whose order is chosen at run time (1..kMaxCurveJetOrder); coefficients above
/// `order` are zero.
struct DynamicCurveJet {
  int order = 0;
  CurveJetStatus status = CurveJetStatus::kSingular;
  std::array<UnknownVec, kMaxCurveJetOrder + 1> x;
  std::array<Vec3, kMaxCurveJetOrder + 1> alpha;
  double rank_ratio = 0;
  int orientation = 0;  // as CurveJet::orientation

  UnknownVec x_at(double s) const {
    UnknownVec r = x[static_cast<std::size_t>(order)];
    for (int k = order - 1; k >= 0; --k) r = (r * s + x[static_cast<std::size_t>(k)]).eval();
    return r;
  }
  Vec3 alpha_at(double s) const {
    Vec3 r = alpha[static_cast<std::size_t>(order)];
    for (int k = order - 1; k >= 0; --k) r = r * s + alpha[static_cast<std::size_t>(k)];
    return r;
  }
  /// Unit tangent alpha'(0).
  const Vec3& tangent() const { return alpha[1]; }
};

namespace internal {
template <int K>
DynamicCurveJet to_dynamic(const CurveJet<K>& j, int n) {
  static_assert(K <= kMaxCurveJetOrder, "DynamicCurveJet holds orders up to kMaxCurveJetOrder");
  DynamicCurveJet d;
  d.order = K;
  d.status = j.status;
  d.rank_ratio = j.rank_ratio;
  d.orientation = j.orientation;
  for (int k = 0; k <= kMaxCurveJetOrder; ++k) {
    d.x[static_cast<std::size_t>(k)] = k <= K ? j.x[static_cast<std::size_t>(k)] : UnknownVec::Zero(n);
    d.alpha[static_cast<std::size_t>(k)] = k <= K ? j.alpha[static_cast<std::size_t>(k)] : Vec3::Zero();
  }
  return d;
}
}  // namespace internal

/// Throws InputError when order is outside 1..kMaxCurveJetOrder (or as curve_jet).
DynamicCurveJet curve_jet_dynamic(const Problem& problem, const UnknownVec& x0, int order, const Vec3* hint = nullptr);

// Each order's jet is compiled once, in src/problem/curve_jet_orders_*.cpp, not in every
// translation unit that asks for it: an order-K jet evaluates the surfaces on K + 1 number types
// for each of the three pair kinds (issue 29, the demo's build time).
#define SSIMARCH_CURVE_JET_ORDER(PREFIX, K) \
  PREFIX CurveJet<K> curve_jet<K>(const Problem&, const UnknownVec&, const Vec3*)
SSIMARCH_CURVE_JET_ORDER(extern template, 1);
SSIMARCH_CURVE_JET_ORDER(extern template, 2);
SSIMARCH_CURVE_JET_ORDER(extern template, 3);
SSIMARCH_CURVE_JET_ORDER(extern template, 4);
SSIMARCH_CURVE_JET_ORDER(extern template, 5);
SSIMARCH_CURVE_JET_ORDER(extern template, 6);
SSIMARCH_CURVE_JET_ORDER(extern template, 7);
SSIMARCH_CURVE_JET_ORDER(extern template, 8);
static_assert(kMaxCurveJetOrder == 8, "declare (and instantiate) every order up to kMaxCurveJetOrder");

}  // namespace ssimarch
