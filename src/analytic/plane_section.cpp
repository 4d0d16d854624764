// docs/math/closed_form_quadrics.md, "Plane sections": C = M^T Q M is the conic of the section in
// the plane's coordinates; the eigen-decomposition of its quadratic part names it.
#include "ssimarch/analytic/plane_section.hpp"

#include <cmath>
#include <limits>

#include "nearest_root.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

// The plane's data in scaled coordinates (s, t) = (world offset along e0, e1) / scale, and how b
// and c change when the plane moves by h (model units) along its normal: b + h b1, c + 2 h c1 +
// h^2 c2 (A does not change).
struct PlaneConic {
  Eigen::Matrix2d A;
  Eigen::Vector2d b;
  double c = 0;
  Vec3 origin, u, v;  // world: point = origin + scale (s u + t v)
  double scale = 1;
  Eigen::Vector2d b1;
  double c1 = 0, c2 = 0;
  double gap_tolerance = 0;  // model units (contact_gap_tolerance)

  Vec3 world(const Eigen::Vector2d& st) const { return origin + scale * (st.x() * u + st.y() * v); }
  Vec3 direction(const Eigen::Vector2d& d) const { return (d.x() * u + d.y() * v).normalized(); }
};

Conic make(ConicType type, const Vec3& c, const Vec3& e0, const Vec3& e1, double a, double b, Contact contact) {
  Conic k;
  k.type = type;
  k.center = c;
  k.e0 = e0;
  k.e1 = e1;
  k.a = a;
  k.b = b;
  k.contact = contact;
  return k;
}

// The plane touches the quadric: the distance it must move along its normal to become tangent
// (the constant k = c - b^T A+ b of the centred conic, a quadratic in that distance, vanishes) is
// within the gap tolerance. `Ainv`: A's inverse, or its pseudo-inverse on the non-zero eigenvalue.
double tangency_distance(const PlaneConic& pc, const Eigen::Matrix2d& Ainv) {
  const double k0 = pc.c - pc.b.dot(Ainv * pc.b), k1 = pc.c1 - pc.b1.dot(Ainv * pc.b), k2 = pc.c2 - pc.b1.dot(Ainv * pc.b1);
  return std::fabs(internal::nearest_root(k0, k1, k2));
}
bool touches(const PlaneConic& pc, const Eigen::Matrix2d& Ainv) {
  return tangency_distance(pc, Ainv) <= pc.gap_tolerance;
}

// A plane that cuts within the gap tolerance of tangency still cuts a curve whose size the
// geometry decides (issue 26: a sphere 1 - 1e-12 above a plane meets it in a circle of radius
// 1.4e-6, a million times the tolerance, which was reported as a contact point): the section is
// the curve when the plane is farther than rounding (kClosedFormGapRounding eps scale) from
// tangency, so the sign of the cut is known, and the curve reaches farther than the tolerance from
// its centre, so its points are not the contact point's. `reach`: the smaller semi-axis (or half
// the distance of two parallel lines), model units.
bool resolved_cut(const PlaneConic& pc, const Eigen::Matrix2d& Ainv, double reach) {
  const double rounding = kClosedFormGapRounding * std::numeric_limits<double>::epsilon() * pc.scale;
  return tangency_distance(pc, Ainv) > rounding && reach > pc.gap_tolerance;
}

// Both eigenvalues non-zero: a central conic about x0 (ellipse, hyperbola, point, crossing lines).
std::vector<Conic> central(const PlaneConic& pc, const Eigen::Vector2d& lam, const Eigen::Matrix2d& R) {
  const Eigen::Vector2d x0 = -pc.A.ldlt().solve(pc.b);
  const double k = pc.c + pc.b.dot(x0);  // lam0 X^2 + lam1 Y^2 + k = 0 in the eigenbasis
  const Vec3 c = pc.world(x0), w0 = pc.direction(R.col(0)), w1 = pc.direction(R.col(1));
  const Eigen::Matrix2d Ainv = R * lam.cwiseInverse().asDiagonal() * R.transpose();
  const bool touching = touches(pc, Ainv);
  if (lam[0] * lam[1] > 0) {
    const bool cuts = k / lam[0] < 0;
    if (touching && !(cuts && resolved_cut(pc, Ainv, pc.scale * std::sqrt(-k / lam[0]))))
      return {make(ConicType::kPoint, c, w0, w1, 0, 0, Contact::kTangential)};
    if (!cuts) return {};
    // |lam0| >= |lam1|: the semi-axis along w1 is the major one.
    const double major = pc.scale * std::sqrt(-k / lam[1]), minor = pc.scale * std::sqrt(-k / lam[0]);
    const bool circle = std::fabs(major - minor) <= kClosedFormDegeneracy * major;
    return {make(circle ? ConicType::kCircle : ConicType::kEllipse, c, w1, w0, major, circle ? major : minor,
                 Contact::kTransversal)};
  }
  if (touching) {  // two lines crossing at x0 (a plane through a cone's apex, tangent to a hyperboloid)
    const double m = std::sqrt(-lam[0] / lam[1]);
    return {make(ConicType::kLine, c, pc.direction(R.col(0) + m * R.col(1)), w1, 0, 0, Contact::kTransversal),
            make(ConicType::kLine, c, pc.direction(R.col(0) - m * R.col(1)), w1, 0, 0, Contact::kTransversal)};
  }
  // Hyperbola: the transverse axis is the eigen-direction along which -k / lam > 0.
  const int i = (-k / lam[0] > 0) ? 0 : 1, j = 1 - i;
  const Vec3 t = i == 0 ? w0 : w1, n = i == 0 ? w1 : w0;
  const double a = pc.scale * std::sqrt(-k / lam[i]), b = pc.scale * std::sqrt(k / lam[j]);
  return {make(ConicType::kHyperbola, c, t, n, a, b, Contact::kTransversal),
          make(ConicType::kHyperbola, c, -t, -n, a, b, Contact::kTransversal)};
}

// One eigenvalue zero: a parabola, two parallel lines or one double line (a tangential contact).
std::vector<Conic> parabolic(const PlaneConic& pc, double lam, const Eigen::Matrix2d& R) {
  const Eigen::Vector2d beta = R.transpose() * pc.b;  // lam X^2 + 2 b0 X + 2 b1 Y + c = 0
  const double X0 = -beta[0] / lam, k = pc.c - beta[0] * beta[0] / lam;
  const Vec3 w0 = pc.direction(R.col(0)), w1 = pc.direction(R.col(1));
  if (std::fabs(beta[1]) > kClosedFormDegeneracy) {
    const double Y0 = -k / (2 * beta[1]);
    const double opens = (lam * beta[1] > 0) ? -1.0 : 1.0;  // Y - Y0 = -(lam / (2 b1)) (X - X0)^2
    const double focal = pc.scale * std::fabs(beta[1] / (2 * lam));
    return {make(ConicType::kParabola, pc.world(R * Eigen::Vector2d(X0, Y0)), opens * w1, w0, focal, 0,
                 Contact::kTransversal)};
  }
  const Eigen::Matrix2d Ainv = R.col(0) * R.col(0).transpose() / lam;
  const bool cuts = k / lam < 0;
  if (touches(pc, Ainv) && !(cuts && resolved_cut(pc, Ainv, pc.scale * std::sqrt(-k / lam))))
    return {make(ConicType::kLine, pc.world(R * Eigen::Vector2d(X0, 0)), w1, w0, 0, 0, Contact::kTangential)};
  if (!cuts) return {};
  const double d = std::sqrt(-k / lam);
  return {make(ConicType::kLine, pc.world(R * Eigen::Vector2d(X0 + d, 0)), w1, w0, 0, 0, Contact::kTransversal),
          make(ConicType::kLine, pc.world(R * Eigen::Vector2d(X0 - d, 0)), w1, w0, 0, 0, Contact::kTransversal)};
}

}  // namespace

std::optional<std::vector<Conic>> plane_section(const Frame& plane, const Eigen::Matrix4d& Q, double scale,
                                                double gap_tolerance) {
  // Homogeneous world point of (s, t): M (s, t, 1) with the coordinates scaled by `scale`.
  Eigen::Matrix<double, 4, 3> M = Eigen::Matrix<double, 4, 3>::Zero();
  M.block<3, 1>(0, 0) = scale * plane.e0;
  M.block<3, 1>(0, 1) = scale * plane.e1;
  M.block<3, 1>(0, 2) = plane.origin;
  M(3, 2) = 1;
  Eigen::Matrix3d C = M.transpose() * Q * M;
  const double m = C.cwiseAbs().maxCoeff();
  if (!(m > 0) || !std::isfinite(m)) return std::nullopt;
  C /= m;
  // The plane moved by h along its normal n: M's last column gains h (n, 0).
  const Vec3 n = plane.e0.cross(plane.e1).normalized();
  const Eigen::Vector4d N(n.x(), n.y(), n.z(), 0);
  const Eigen::Vector3d moved = M.transpose() * Q * N / m;  // (b1, c1)
  PlaneConic pc{C.topLeftCorner<2, 2>(), C.topRightCorner<2, 1>(), C(2, 2), plane.origin, plane.e0, plane.e1, scale,
                moved.head<2>(), moved[2], N.dot(Q * N) / m, gap_tolerance};
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(pc.A);
  Eigen::Vector2d lam = eig.eigenvalues();
  Eigen::Matrix2d R = eig.eigenvectors();
  if (std::fabs(lam[0]) < std::fabs(lam[1])) {  // order by magnitude, largest first
    std::swap(lam[0], lam[1]);
    R.col(0).swap(R.col(1));
  }
  if (std::fabs(lam[0]) <= kClosedFormDegeneracy) return std::nullopt;
  if (std::fabs(lam[1]) > kClosedFormDegeneracy) return central(pc, lam, R);
  return parabolic(pc, lam[0], R);
}

}  // namespace ssimarch
