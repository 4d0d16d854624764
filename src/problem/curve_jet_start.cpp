// The order-independent part of a curve jet (problem/curve_jet.hpp, CurveJetStart; derivation in
// docs/math/curve_jet.md): compiled here once for the three pair kinds instead of in every file
// that instantiates an order. Its SVDs run on EquationJacobian, the size-bounded dynamic matrix
// that Problem::linearize's SVD instantiates anyway: an Eigen JacobiSVD costs GCC about 15 s of
// compile time per matrix type, and the three fixed sizes (N - 1) x N would be three more.
#include <Eigen/Dense>

#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch::internal {

namespace {

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
                      const Eigen::JacobiSVD<EquationJacobian>& svd) {
  switch (problem.kind()) {
    case PairKind::kParametricParametric: return Problem::rank_ratio(svd.singularValues());
    case PairKind::kImplicitImplicit: {
      Eigen::Matrix<double, N - 1, N> normalised = J;
      for (int r = 0; r < N - 1; ++r)
        if (const double n = J.row(r).norm(); n > 0) normalised.row(r) /= n;
      const Eigen::JacobiSVD<EquationJacobian> s{EquationJacobian(normalised)};
      return Problem::rank_ratio(s.singularValues());
    }
    case PairKind::kParametricImplicit: break;
  }
  return Problem::rank_ratio(problem.linearize(x0));
}

}  // namespace

template <int N>
CurveJetStart<N> curve_jet_start(const Problem& problem, const UnknownVec& x0, const Vec3* hint) {
  CurveJetStart<N> start;
  Eigen::Matrix<double, N - 1, N> J;
  raw_jacobians<N>(problem, x0, &J, &start.D, &start.point);
  if (!J.allFinite() || !start.D.allFinite()) {
    start.status = CurveJetStatus::kNonFinite;
    return start;
  }
  const Eigen::JacobiSVD<EquationJacobian> svd(EquationJacobian(J), Eigen::ComputeFullV);
  start.rank_ratio = raw_rank_ratio<N>(problem, x0, J, svd);
  const Eigen::Matrix<double, N, 1> null = svd.matrixV().col(N - 1);
  const Vec3 speed = start.D * null;
  if (start.rank_ratio <= kCurveJetRankTolerance || speed.norm() == 0) {
    start.status = CurveJetStatus::kSingular;
    return start;
  }
  const double sign = (hint && speed.dot(*hint) < 0) ? -1.0 : 1.0;
  start.x1 = null * (sign / speed.norm());
  start.alpha1 = start.D * start.x1;
  // The sign of det [J; x'] says whether the tangent runs along the generalised cross product of
  // the rows of J_H, a field that is continuous along the curve and vanishes only at its singular
  // points: it changes between consecutive points exactly when a step passed a crossing of
  // branches (thesis ch. 5 §5.2.1, Fig. 5.3).
  Eigen::Matrix<double, N, N> M;
  M.topRows(N - 1) = J;
  M.row(N - 1) = start.x1.transpose();
  start.orientation = M.determinant() >= 0 ? 1 : -1;
  Eigen::Matrix<double, N, N> A;
  A.topRows(N - 1) = J;
  A.row(N - 1) = start.alpha1.transpose() * start.D;
  start.lu.compute(A);
  start.status = CurveJetStatus::kOk;
  return start;
}

template CurveJetStart<2> curve_jet_start<2>(const Problem&, const UnknownVec&, const Vec3*);
template CurveJetStart<3> curve_jet_start<3>(const Problem&, const UnknownVec&, const Vec3*);
template CurveJetStart<4> curve_jet_start<4>(const Problem&, const UnknownVec&, const Vec3*);

}  // namespace ssimarch::internal
