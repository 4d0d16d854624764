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

// The part of a curve jet that does not depend on its order (src/problem/curve_jet_start.cpp,
// compiled once for the three pair kinds: its SVD and LU are most of a jet's compile time, issue
// 29): D = d point/dx, the point, the rank ratio, the unit tangent x'(0) oriented by
// `hint`, the orientation, and for K >= 2 the LU of [J; alpha_1^T D] every higher order solves with.
template <int N>
struct CurveJetStart {
  CurveJetStatus status = CurveJetStatus::kSingular;
  Eigen::Matrix<double, 3, N> D;
  Vec3 point = Vec3::Zero();
  Eigen::Matrix<double, N, 1> x1 = Eigen::Matrix<double, N, 1>::Zero();
  Vec3 alpha1 = Vec3::Zero();
  double rank_ratio = 0;
  int orientation = 0;
  Eigen::PartialPivLU<Eigen::Matrix<double, N, N>> lu;
};
template <int N>
CurveJetStart<N> curve_jet_start(const Problem& problem, const UnknownVec& x0, const Vec3* hint);
extern template CurveJetStart<2> curve_jet_start<2>(const Problem&, const UnknownVec&, const Vec3*);
extern template CurveJetStart<3> curve_jet_start<3>(const Problem&, const UnknownVec&, const Vec3*);
extern template CurveJetStart<4> curve_jet_start<4>(const Problem&, const UnknownVec&, const Vec3*);

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
  const CurveJetStart<N> start = curve_jet_start<N>(problem, x0, hint);
  jet.alpha[0] = start.point;
  jet.rank_ratio = start.rank_ratio;
  jet.status = start.status;
  if (start.status != CurveJetStatus::kOk) return jet;
  jet.x[1] = start.x1;
  jet.alpha[1] = start.alpha1;
  jet.orientation = start.orientation;
  if constexpr (K >= 2) higher_coefficients<N, K, 2>(problem, start.lu, start.D, &jet);
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
