#include "ssimarch/surface/derivatives.hpp"

#include <algorithm>
#include <cmath>

namespace ssimarch {
namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

Curvatures from_k_h(double K, double H) {
  const double d = std::sqrt(std::max(0.0, H * H - K));
  return {K, H, H + d, H - d};
}

}  // namespace

Vec3 point(const Surface& s, double u, double v) { return to_vec3(s.point<double>(u, v)); }

std::optional<Vec3> unit_normal(const Surface& s, double u, double v, double tol) {
  const auto F = parametric_jet<1>(s, u, v);
  const Vec3 fu = partial(F, 1, 0), fv = partial(F, 0, 1);
  const Vec3 n = fu.cross(fv);
  const double len = n.norm();
  if (!finite(fu) || !finite(fv) || !std::isfinite(len) || !(len > tol * (fu.squaredNorm() + fv.squaredNorm())))
    return std::nullopt;
  return n / len;
}

std::optional<Vec3> unit_normal(const Surface& s, const Vec3& p, double min_gradient) {
  const Vec3 g = gradient(s, p);
  const double len = g.norm();
  if (!finite(g) || !std::isfinite(len) || !(len > min_gradient)) return std::nullopt;
  return g / len;
}

std::optional<FundamentalForms> fundamental_forms(const Surface& s, double u, double v, double tol) {
  const auto F = parametric_jet<2>(s, u, v);
  const Vec3 fu = partial(F, 1, 0), fv = partial(F, 0, 1);
  const Vec3 fuu = partial(F, 2, 0), fuv = partial(F, 1, 1), fvv = partial(F, 0, 2);
  const Vec3 c = fu.cross(fv);
  const double len = c.norm();
  if (!finite(fu) || !finite(fv) || !finite(fuu) || !finite(fuv) || !finite(fvv) || !std::isfinite(len) ||
      !(len > tol * (fu.squaredNorm() + fv.squaredNorm())))
    return std::nullopt;
  const Vec3 n = c / len;
  return FundamentalForms{fu.dot(fu), fu.dot(fv), fv.dot(fv), fuu.dot(n), fuv.dot(n), fvv.dot(n)};
}

double normal_curvature(const FundamentalForms& ff, double du, double dv) {
  const double I = ff.E * du * du + 2 * ff.F * du * dv + ff.G * dv * dv;
  const double II = ff.L * du * du + 2 * ff.M * du * dv + ff.N * dv * dv;
  return II / I;
}

Curvatures curvatures(const FundamentalForms& ff) {
  const double det = ff.E * ff.G - ff.F * ff.F;
  const double K = (ff.L * ff.N - ff.M * ff.M) / det;
  const double H = (ff.E * ff.N - 2 * ff.F * ff.M + ff.G * ff.L) / (2 * det);
  return from_k_h(K, H);
}

Vec3 gradient(const Surface& s, const Vec3& p) {
  const auto f = implicit_jet<1>(s, p);
  return {f.d(0), f.d(1), f.d(2)};
}

Eigen::Matrix3d hessian(const Surface& s, const Vec3& p) {
  const auto f = implicit_jet<2>(s, p);
  Eigen::Matrix3d h;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      std::array<int, 3> a{0, 0, 0};
      a[static_cast<std::size_t>(i)] += 1;
      a[static_cast<std::size_t>(j)] += 1;
      h(i, j) = f.derivative(a);
    }
  return h;
}

std::optional<double> normal_curvature(const Surface& s, const Vec3& p, const Vec3& w, double min_gradient) {
  // Below this ratio |tangential part| / |w|, w is taken as normal: no tangent direction.
  constexpr double kMinTangential = 1e-12;
  const auto f = implicit_jet<2>(s, p);
  const Vec3 g{f.d(0), f.d(1), f.d(2)};
  const double gl = g.norm();
  if (!finite(g) || !std::isfinite(gl) || !(gl > min_gradient) || !finite(w)) return std::nullopt;
  const Vec3 n = g / gl;
  Vec3 t = w - n * n.dot(w);
  const double tl = t.norm();
  if (!(tl > kMinTangential * w.norm())) return std::nullopt;
  t /= tl;
  const Eigen::Matrix3d H = hessian(s, p);
  const double k = -t.dot(H * t) / gl;
  if (!std::isfinite(k)) return std::nullopt;
  return k;
}

std::optional<Curvatures> implicit_curvatures(const Surface& s, const Vec3& p, double min_gradient) {
  const Vec3 g = gradient(s, p);
  const double gl = g.norm();
  if (!finite(g) || !std::isfinite(gl) || !(gl > min_gradient)) return std::nullopt;
  const Eigen::Matrix3d H = hessian(s, p);
  if (!H.allFinite()) return std::nullopt;
  Eigen::Matrix4d B = Eigen::Matrix4d::Zero();
  B.topLeftCorner<3, 3>() = H;
  B.topRightCorner<3, 1>() = g;
  B.bottomLeftCorner<1, 3>() = g.transpose();
  const double K = -B.determinant() / std::pow(gl, 4);
  const double Hm = (g.dot(H * g) - gl * gl * H.trace()) / (2 * gl * gl * gl);
  return from_k_h(K, Hm);
}

}  // namespace ssimarch
