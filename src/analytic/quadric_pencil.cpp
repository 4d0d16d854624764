// docs/math/closed_form_quadrics.md, "The pencil": the real roots of det(A - lambda B) and the
// cones and cylinders among their members, as rulings through an ellipse of each.
#include "ssimarch/analytic/quadric_pencil.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

// |Im lambda| / (1 + |lambda|) of a generalized eigenvalue below which it may be a real root
// (then polished): a double real root comes out of QZ as a pair split by ~sqrt(epsilon).
constexpr double kImaginaryPart = 1e-6;
constexpr int kPolishSteps = 30;

Eigen::Matrix4d unit_scaled(const Eigen::Matrix4d& m) { return m / m.cwiseAbs().maxCoeff(); }

// Eigen-pairs of a symmetric matrix with the eigenvalues ordered by magnitude.
struct SortedEigen {
  Eigen::Vector4d values;
  Eigen::Matrix4d vectors;
};
SortedEigen by_magnitude(const Eigen::Matrix4d& q) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(q);
  std::array<int, 4> order{0, 1, 2, 3};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return std::fabs(es.eigenvalues()[i]) < std::fabs(es.eigenvalues()[j]); });
  SortedEigen out;
  for (int k = 0; k < 4; ++k) {
    out.values[k] = es.eigenvalues()[order[static_cast<std::size_t>(k)]];
    out.vectors.col(k) = es.eigenvectors().col(order[static_cast<std::size_t>(k)]);
  }
  return out;
}

// A root of det(A - lambda B) to rounding: Newton on the eigenvalue mu(lambda) of A - lambda B
// nearest 0, d mu / d lambda = -v^T B v (v its unit eigenvector; first-order perturbation).
std::optional<double> polish(const Eigen::Matrix4d& A, const Eigen::Matrix4d& B, double lambda) {
  for (int it = 0; it < kPolishSteps; ++it) {
    const SortedEigen e = by_magnitude(A - lambda * B);
    const Eigen::Vector4d v = e.vectors.col(0);
    const double slope = v.dot(B * v);
    if (!(std::fabs(slope) > 0)) return std::nullopt;
    const double step = e.values[0] / slope;
    lambda += step;
    if (!std::isfinite(lambda)) return std::nullopt;
    if (std::fabs(step) <= 4e-16 * (1 + std::fabs(lambda))) break;
  }
  return lambda;
}

// The real roots of det(A - lambda B), polished, without repeats.
std::vector<double> real_roots(const Eigen::Matrix4d& A, const Eigen::Matrix4d& B) {
  const Eigen::GeneralizedEigenSolver<Eigen::Matrix4d> ges(A, B, false);
  std::vector<double> out;
  if (ges.info() != Eigen::Success) return out;
  for (int i = 0; i < 4; ++i) {
    const std::complex<double> alpha = ges.alphas()[i];
    const double beta = ges.betas()[i];
    if (!(std::fabs(beta) > 1e-14 * std::abs(alpha))) continue;  // lambda = infinity: B itself
    const std::complex<double> lambda = alpha / beta;
    if (!(std::fabs(lambda.imag()) <= kImaginaryPart * (1 + std::abs(lambda)))) continue;
    const auto root = polish(A, B, lambda.real());
    if (!root) continue;
    if (std::none_of(out.begin(), out.end(), [&](double r) { return std::fabs(r - *root) <= 1e-12 * (1 + std::fabs(r)); }))
      out.push_back(*root);
  }
  return out;
}

// Unit vectors e0, e1 completing the unit `axis` to an orthonormal frame.
void plane_axes(const Vec3& axis, Vec3* e0, Vec3* e1) {
  int k = 0;
  axis.cwiseAbs().minCoeff(&k);
  *e0 = Vec3::Unit(k).cross(axis).normalized();
  *e1 = axis.cross(*e0);
}

// The member Q = A - lambda B as a real cone or elliptic cylinder: its vertex K (the kernel,
// homogeneous) and the ellipse where the plane through c normal to its axis cuts it;
// nullopt where the member is not one (rank other than 3, an imaginary cone, a hyperbolic or
// parabolic cylinder).
std::optional<PencilMember> member(const Eigen::Matrix4d& A, const Eigen::Matrix4d& B, double lambda, const Vec3& centre,
                                   double scale) {
  const Eigen::Matrix4d Q = unit_scaled(A - lambda * B);
  const SortedEigen e = by_magnitude(Q);
  if (!(std::fabs(e.values[0]) <= kClosedFormDegeneracy && std::fabs(e.values[1]) > kPencilRankGap)) return std::nullopt;
  const Eigen::Vector4d K = e.vectors.col(0);
  const Eigen::Matrix4d Qr = Q - e.values[0] * K * K.transpose();  // the member of rank exactly 3
  PencilMember m;
  m.lambda = lambda;
  m.cylinder = std::fabs(K[3]) <= kPencilFiniteVertex * K.head<3>().norm();
  Vec3 axis, c = centre;
  if (m.cylinder) {
    // The vertex at infinity (to kPencilFiniteVertex): the axis is its direction. K itself is kept
    // (the rulings divide by w = 1 + t K_w), so the ruled surface is the member exactly.
    axis = K.head<3>().normalized();
  } else {
    // A real cone: the quadratic part is indefinite; its axis is the eigenvector of the eigenvalue
    // of the odd sign. The plane of the ellipse keeps half the scale from the vertex.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(Qr.topLeftCorner<3, 3>());
    const Eigen::Vector3d l = es.eigenvalues();
    const int positive = (l.array() > 0).count();
    if (positive == 0 || positive == 3) return std::nullopt;
    const int odd = positive == 1 ? (l[0] > 0 ? 0 : l[1] > 0 ? 1 : 2) : (l[0] < 0 ? 0 : l[1] < 0 ? 1 : 2);
    axis = es.eigenvectors().col(odd);
    const Vec3 vertex = K.head<3>() / K[3];
    const double h = (centre - vertex).dot(axis);
    if (std::fabs(h) < 0.5 * scale) c += ((h >= 0 ? 0.5 : -0.5) * scale - h) * axis;
  }
  Vec3 e0, e1;
  plane_axes(axis, &e0, &e1);
  Eigen::Matrix<double, 4, 3> M;
  M << e0.x(), e1.x(), c.x(), e0.y(), e1.y(), c.y(), e0.z(), e1.z(), c.z(), 0, 0, 1;
  const Eigen::Matrix3d C = M.transpose() * Qr * M;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> conic(C.topLeftCorner<2, 2>());
  const Eigen::Vector2d l = conic.eigenvalues();
  const double size = C.cwiseAbs().maxCoeff();
  if (!(l[0] * l[1] > 0 && std::min(std::fabs(l[0]), std::fabs(l[1])) > kPencilRankGap * size)) return std::nullopt;
  const Eigen::Vector2d x0 = -C.topLeftCorner<2, 2>().ldlt().solve(C.block<2, 1>(0, 2));
  const double k = C(2, 2) + C.block<2, 1>(0, 2).dot(x0);
  if (!(-k / l[0] > kPencilRankGap * size / std::fabs(l[0]))) return std::nullopt;  // imaginary or a point
  const Eigen::Matrix2d g = conic.eigenvectors();
  const Vec3 o = c + x0[0] * e0 + x0[1] * e1;
  const Vec3 g0 = std::sqrt(-k / l[0]) * (g(0, 0) * e0 + g(1, 0) * e1);
  const Vec3 g1 = std::sqrt(-k / l[1]) * (g(0, 1) * e0 + g(1, 1) * e1);
  m.rulings.a = {Eigen::Vector4d(o.x(), o.y(), o.z(), 1), Eigen::Vector4d(g0.x(), g0.y(), g0.z(), 0),
                 Eigen::Vector4d(g1.x(), g1.y(), g1.z(), 0)};
  m.rulings.d = {K, Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()};
  m.rulings.homogeneous = true;
  return m;
}

}  // namespace

std::vector<PencilMember> ruled_members(const Eigen::Matrix4d& A0, const Eigen::Matrix4d& B0, const Vec3& centre,
                                        double scale) {
  const Eigen::Matrix4d A = unit_scaled(A0), B = unit_scaled(B0);
  std::vector<PencilMember> out;
  for (double lambda : real_roots(A, B))
    if (auto m = member(A, B, lambda, centre, scale)) out.push_back(*m);
  auto rank = [&](const PencilMember& m) {
    const Eigen::Vector4d& K = m.rulings.d[0];
    if (m.cylinder) return -1.0;
    return (Vec3(K.head<3>() / K[3]) - centre).norm();
  };
  std::stable_sort(out.begin(), out.end(), [&](const PencilMember& a, const PencilMember& b) { return rank(a) < rank(b); });
  return out;
}

}  // namespace ssimarch
