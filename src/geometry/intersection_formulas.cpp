#include "ssimarch/geometry/intersection_formulas.hpp"

#include <algorithm>
#include <cmath>

namespace ssimarch {

namespace {

// Common start of the transversal methods: normals, theta, tangent, or the reason to stop.
struct TransversalStart {
  bool ok = false;
  CurveGeometry g;
  Vec3 n1, n2;
  double cos_theta = kNaN, sin2_theta = kNaN;
};

TransversalStart start_transversal(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                                   const GeometryTolerances& tol) {
  TransversalStart s;
  s.g.point = local_point(first);
  if (!is_finite(first) || !is_finite(second)) {
    s.g.status = GeometryStatus::kNonFinite;
    return s;
  }
  s.n1 = unit_normal(first);
  s.n2 = unit_normal(second);
  if (!s.n1.allFinite() || !s.n2.allFinite()) {
    s.g.status = GeometryStatus::kNonFinite;
    return s;
  }
  s.g.theta = normal_angle(s.n1, s.n2);
  Vec3 cr = s.n1.cross(s.n2);
  double sin_theta = cr.norm();
  if (!(sin_theta >= tol.singular_sin_theta)) {
    s.g.status = GeometryStatus::kSingular;
    return s;
  }
  s.cos_theta = s.n1.dot(s.n2);
  s.sin2_theta = sin_theta * sin_theta;  // |N1 x N2|^2, accurate also where 1 - cos^2 is not
  s.g.t = cr / sin_theta;  // eq 2.19
  if (orientation && s.g.t.dot(*orientation) < 0) s.g.t = -s.g.t;
  s.ok = true;
  return s;
}

Vec3 any_perpendicular(const Vec3& n) {
  Vec3 a = std::fabs(n.x()) < 0.6 ? Vec3::UnitX() : (std::fabs(n.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  return (a - a.dot(n) * n).normalized();
}

// Curvature vector of one tangential branch with tangent t in the common tangent plane with
// unit normal `normal` (curve-geometry.md §3.2 item 5 written without parameters): c'' = k N + g m
// with c''.t = 0 (eq 3.22) and g from lambda_1 = lambda_2 (eq 3.21), which is affine in g.
CurveGeometry tangential_branch(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3& normal, Vec3 t,
                                double theta, const Vec3* orientation, const GeometryTolerances& tol) {
  CurveGeometry g;
  g.point = local_point(first);
  g.theta = theta;
  if (orientation && t.dot(*orientation) < 0) t = -t;
  g.t = t;
  double k = 0.5 * (normal_curvature(first, t, normal) + normal_curvature(second, t, normal));
  Vec3 m = normal.cross(t);
  auto mismatch = [&](double gm) {
    Vec3 c2 = k * normal + gm * m;
    return third_normal(first, t, c2, normal) - third_normal(second, t, c2, normal);
  };
  double f0 = mismatch(0.0), f1 = mismatch(1.0) - f0;
  // f1 = 3 (II_1 - II_2)(t, m): zero only where the branch direction is a double root, i.e. the
  // two branches are tangent to each other and c'' is not fixed at this order.
  double scale = std::fabs(f0) + std::fabs(mismatch(1.0)) + 1.0;
  if (!(std::fabs(f1) > 1e-14 * scale)) {
    g.status = GeometryStatus::kHigherOrderContact;
    return g;
  }
  Vec3 c2 = k * normal + (-f0 / f1) * m;
  g.kappa = c2.norm();
  g = frenet_frame(g, c2, nullptr, tol.zero_curvature);
  if (g.status == GeometryStatus::kOk) g.status = GeometryStatus::kTangentialSecondOrder;
  return g;
}

// Tangential checks shared by both forms: finite data, defined normals.
bool tangential_prelude(const SurfaceLocal& first, const SurfaceLocal& second, Vec3* n1, Vec3* n2,
                        std::vector<CurveGeometry>* out) {
  CurveGeometry fail;
  fail.point = local_point(first);
  fail.status = GeometryStatus::kNonFinite;
  if (!is_finite(first) || !is_finite(second)) {
    out->push_back(fail);
    return false;
  }
  *n1 = unit_normal(first);
  *n2 = unit_normal(second);
  if (!n1->allFinite() || !n2->allFinite()) {
    out->push_back(fail);
    return false;
  }
  return true;
}

CurveGeometry only_status(const Vec3& point, double theta, GeometryStatus status) {
  CurveGeometry g;
  g.point = point;
  g.theta = theta;
  g.status = status;
  return g;
}

}  // namespace

// Thesis ch. 3 (eqs 3.13-3.15, 3.23-3.25; Ye & Maekawa); seed 004 §4 (eqs 4.1-4.6,
// 4.16-4.20) for implicit surfaces.
CurveGeometry ye_maekawa_transversal(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                                     const GeometryTolerances& tol) {
  TransversalStart s = start_transversal(first, second, orientation, tol);
  if (!s.ok) return s.g;
  CurveGeometry g = s.g;
  const Vec3& t = g.t;
  double c = s.cos_theta;
  double k1 = normal_curvature(first, t, s.n1), k2 = normal_curvature(second, t, s.n2);
  Vec3 c2 = ((k1 - k2 * c) * s.n1 + (k2 - k1 * c) * s.n2) / s.sin2_theta;  // eq 3.14
  g.kappa = std::sqrt(std::max(0.0, k1 * k1 + k2 * k2 - 2 * k1 * k2 * c) / s.sin2_theta);  // eq 3.15
  double l1 = third_normal(first, t, c2, s.n1), l2 = third_normal(second, t, c2, s.n2);
  Vec3 c3 = -g.kappa * g.kappa * t + ((l1 - l2 * c) * s.n1 + (l2 - l1 * c) * s.n2) / s.sin2_theta;  // eq 3.23
  return frenet_frame(g, c2, &c3, tol.zero_curvature);
}

// Thesis ch. 3, eqs 3.8-3.9 (Stoyanov).
CurveGeometry stoyanov(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                       const GeometryTolerances& tol) {
  TransversalStart s = start_transversal(first, second, orientation, tol);
  if (!s.ok) return s.g;
  CurveGeometry g = s.g;
  const Vec3& t = g.t;
  Eigen::Matrix2d gram;
  gram << s.n1.dot(s.n1), s.n1.dot(s.n2), s.n2.dot(s.n1), s.n2.dot(s.n2);
  Eigen::FullPivLU<Eigen::Matrix2d> lu(gram);
  Vec2 a = lu.solve(Vec2(normal_curvature(first, t, s.n1), normal_curvature(second, t, s.n2)));
  Vec3 c2 = a[0] * s.n1 + a[1] * s.n2;
  g.kappa = c2.norm();
  Vec2 beta = lu.solve(Vec2(third_normal(first, t, c2, s.n1), third_normal(second, t, c2, s.n2)));
  Vec3 c3 = -g.kappa * g.kappa * t + beta[0] * s.n1 + beta[1] * s.n2;
  return frenet_frame(g, c2, &c3, tol.zero_curvature);
}

// Seed 004 §4, eqs 4.7-4.15, 4.21-4.23 (Willmore's operator).
CurveGeometry willmore(const ImplicitLocal& f, const ImplicitLocal& g, const Vec3* orientation,
                       const GeometryTolerances& tol) {
  TransversalStart s = start_transversal(f, g, nullptr, tol);
  if (!s.ok) return s.g;
  CurveGeometry r = s.g;
  const Vec3 h = f.grad.cross(g.grad);  // eq 4.7
  // Delta V = (dV/dx) h for the field V; for h = grad f x grad g:
  //   Dh[a]     = (Hf a) x grad g + grad f x (Hg a)
  //   D^2h[a,a] = D^3f[a,a] x grad g + 2 (Hf a) x (Hg a) + grad f x D^3g[a,a]
  auto dh = [&](const Vec3& a) { return Vec3((f.hess * a).cross(g.grad) + f.grad.cross(g.hess * a)); };
  const Vec3 delta_h = dh(h);
  const Vec3 delta2_h = f.third_contract(h, h).cross(g.grad) + 2.0 * (f.hess * h).cross(g.hess * h) +
                        f.grad.cross(g.third_contract(h, h)) + dh(delta_h);
  const Vec3 k = h.cross(delta_h);         // eq 4.13
  const Vec3 delta_k = h.cross(delta2_h);  // Delta k = h x Delta^2 h
  double hn = h.norm(), kn = k.norm();
  r.t = h / hn;
  r.kappa = kn / (hn * hn * hn);  // eq 4.14
  Vec3 c2 = k.cross(h) / (hn * hn * hn * hn);  // eq 4.15
  r = frenet_frame(r, c2, nullptr, tol.zero_curvature);
  if (r.status == GeometryStatus::kOk) {
    r.tau = -delta_h.dot(delta_k) / (kn * kn);  // eq 4.23
    r.kappa_prime = (k.dot(delta_k) / (kn * hn * hn * hn) - 3.0 * kn * h.dot(delta_h) / std::pow(hn, 5)) / hn;
  }
  if (orientation && r.t.dot(*orientation) < 0) r.reverse();
  return r;
}

// Thesis ch. 3 (tangential case, eqs 3.2 and 3.16-3.22; Ye & Maekawa), without parameters.
std::vector<CurveGeometry> ye_maekawa_tangential(const SurfaceLocal& first, const SurfaceLocal& second,
                                                 const Vec3* orientation, const GeometryTolerances& tol) {
  if (std::holds_alternative<ParametricLocal>(first) && std::holds_alternative<ParametricLocal>(second))
    return ye_maekawa_tangential_thesis(std::get<ParametricLocal>(first), std::get<ParametricLocal>(second),
                                        orientation, tol);
  std::vector<CurveGeometry> out;
  Vec3 n1, n2;
  if (!tangential_prelude(first, second, &n1, &n2, &out)) return out;
  double theta = normal_angle(n1, n2);
  Vec3 normal = (n1 + (n1.dot(n2) < 0 ? -n2 : n2)).normalized();
  Vec3 e1 = any_perpendicular(normal), e2 = normal.cross(e1);
  Eigen::Matrix2d diff;  // (II_1 - II_2) in the orthonormal basis (e1, e2), eq 3.2
  const std::array<Vec3, 2> e{e1, e2};
  double size = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      double s1 = second_form(first, e[static_cast<std::size_t>(i)], e[static_cast<std::size_t>(j)], normal);
      double s2 = second_form(second, e[static_cast<std::size_t>(i)], e[static_cast<std::size_t>(j)], normal);
      diff(i, j) = s1 - s2;
      size = std::max({size, std::fabs(s1), std::fabs(s2)});
    }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(diff);
  double mu1 = eig.eigenvalues()[0], mu2 = eig.eigenvalues()[1];  // mu1 <= mu2
  Vec2 v1 = eig.eigenvectors().col(0), v2 = eig.eigenvectors().col(1);
  double big = std::max(std::fabs(mu1), std::fabs(mu2));
  const Vec3 p = local_point(first);
  if (!(big > tol.tangential_discriminant * std::max(size, 1.0))) {
    out.push_back(only_status(p, theta, GeometryStatus::kHigherOrderContact));
    return out;
  }
  auto to3 = [&](const Vec2& w) { return Vec3((w[0] * e1 + w[1] * e2).normalized()); };
  std::vector<Vec3> dirs;
  if (mu1 * mu2 > tol.tangential_discriminant * big * big) {
    out.push_back(only_status(p, theta, GeometryStatus::kIsolatedPoint));
    return out;
  }
  if (std::fabs(mu1 * mu2) <= tol.tangential_discriminant * big * big) {
    dirs.push_back(to3(std::fabs(mu1) < std::fabs(mu2) ? v1 : v2));  // one double direction
  } else {
    // mu1 < 0 < mu2: mu1 cos^2 + mu2 sin^2 = 0 at (cos, sin) ~ (sqrt(mu2), +-sqrt(-mu1)).
    dirs.push_back(to3(std::sqrt(mu2) * v1 + std::sqrt(-mu1) * v2));
    dirs.push_back(to3(std::sqrt(mu2) * v1 - std::sqrt(-mu1) * v2));
  }
  for (const Vec3& t : dirs) out.push_back(tangential_branch(first, second, normal, t, theta, orientation, tol));
  return out;
}

namespace {

// The coefficients of thesis ch. 3 at a tangential point of two parametric surfaces with common
// normal N: G's parameter velocities (p', q') = A (u', v') (eq 3.4, D = (G_p x G_q).N) and both
// surfaces' second fundamental forms along N.
struct ThesisTangentialData {
  double D, a11, a12, a21, a22;
  double LF, MF, NF, LG, MG, NG;
};

// One branch of eqs 3.16-3.22 along the direction w = (u', v') (any scale): its unit tangent and
// the curvature vector c'' from the 2 x 2 system of eqs 3.21-3.22 (a13 sign and eq 3.18 corrected).
CurveGeometry thesis_tangential_branch(const ParametricLocal& F, const ParametricLocal& G, const Vec3& N,
                                       const ThesisTangentialData& c, Vec2 w, double theta, const Vec3* orientation,
                                       const GeometryTolerances& tol) {
  const Vec3& Gp = G.fu;
  const Vec3& Gq = G.fv;
  Vec3 dir = w[0] * F.fu + w[1] * F.fv;
  w /= dir.norm();  // |u' F_u + v' F_v| = 1
  if (orientation && dir.dot(*orientation) < 0) w = -w;
  double u1 = w[0], v1 = w[1];
  Vec3 t = u1 * F.fu + v1 * F.fv;
  double p1 = c.a11 * u1 + c.a12 * v1, q1 = c.a21 * u1 + c.a22 * v1;
  Vec3 delta = G.fuu * p1 * p1 + 2 * G.fuv * p1 * q1 + G.fvv * q1 * q1 - F.fuu * u1 * u1 - 2 * F.fuv * u1 * v1 -
               F.fvv * v1 * v1;                // eq 3.17
  double a13 = -delta.cross(Gq).dot(N) / c.D;  // eq 3.19, corrected sign
  double a23 = -Gp.cross(delta).dot(N) / c.D;  // eq 3.20
  double IIIF = F.fuuu.dot(N) * u1 * u1 * u1 + 3 * F.fuuv.dot(N) * u1 * u1 * v1 + 3 * F.fuvv.dot(N) * u1 * v1 * v1 +
                F.fvvv.dot(N) * v1 * v1 * v1;
  double IIIG = G.fuuu.dot(N) * p1 * p1 * p1 + 3 * G.fuuv.dot(N) * p1 * p1 * q1 + 3 * G.fuvv.dot(N) * p1 * q1 * q1 +
                G.fvvv.dot(N) * q1 * q1 * q1;
  // eq 3.21 with p'' = a11 u'' + a12 v'' + a13, q'' = a21 u'' + a22 v'' + a23 (eq 3.18).
  Eigen::Matrix2d A;
  A << 3 * (c.LF * u1 + c.MF * v1) - 3 * (c.LG * p1 * c.a11 + c.MG * (c.a11 * q1 + p1 * c.a21) + c.NG * q1 * c.a21),
      3 * (c.MF * u1 + c.NF * v1) - 3 * (c.LG * p1 * c.a12 + c.MG * (c.a12 * q1 + p1 * c.a22) + c.NG * q1 * c.a22),
      F.fu.dot(t), F.fv.dot(t);  // eq 3.22
  Vec2 rhs(IIIG - IIIF + 3 * (c.LG * p1 * a13 + c.MG * (a13 * q1 + p1 * a23) + c.NG * q1 * a23),
           -(F.fuu.dot(t) * u1 * u1 + 2 * F.fuv.dot(t) * u1 * v1 + F.fvv.dot(t) * v1 * v1));
  CurveGeometry g;
  g.point = F.p;
  g.theta = theta;
  g.t = t;
  Eigen::FullPivLU<Eigen::Matrix2d> lu(A);
  if (!lu.isInvertible()) {
    g.status = GeometryStatus::kHigherOrderContact;
    return g;
  }
  Vec2 w2 = lu.solve(rhs);
  Vec3 c2 = F.fuu * u1 * u1 + 2 * F.fuv * u1 * v1 + F.fvv * v1 * v1 + F.fu * w2[0] + F.fv * w2[1];  // eq 3.16
  g.kappa = c2.norm();
  g = frenet_frame(g, c2, nullptr, tol.zero_curvature);
  if (g.status == GeometryStatus::kOk) g.status = GeometryStatus::kTangentialSecondOrder;
  return g;
}

}  // namespace

// Thesis ch. 3 (eqs 3.3-3.6, b12 corrected; eqs 3.16-3.22, a13 sign and eq 3.18 corrected;
// docs/geometry.md).
std::vector<CurveGeometry> ye_maekawa_tangential_thesis(const ParametricLocal& F, const ParametricLocal& G,
                                                        const Vec3* orientation, const GeometryTolerances& tol) {
  std::vector<CurveGeometry> out;
  Vec3 n1, n2;
  if (!tangential_prelude(F, G, &n1, &n2, &out)) return out;
  const double theta = normal_angle(n1, n2);
  const Vec3& N = n1;
  const Vec3& Gp = G.fu;
  const Vec3& Gq = G.fv;
  ThesisTangentialData c;
  c.D = Gp.cross(Gq).dot(N);
  c.a11 = F.fu.cross(Gq).dot(N) / c.D, c.a12 = F.fv.cross(Gq).dot(N) / c.D;  // eq 3.4
  c.a21 = Gp.cross(F.fu).dot(N) / c.D, c.a22 = Gp.cross(F.fv).dot(N) / c.D;
  c.LF = F.fuu.dot(N), c.MF = F.fuv.dot(N), c.NF = F.fvv.dot(N);
  c.LG = G.fuu.dot(N), c.MG = G.fuv.dot(N), c.NG = G.fvv.dot(N);
  const double a11 = c.a11, a12 = c.a12, a21 = c.a21, a22 = c.a22;
  double b11 = a11 * a11 * c.LG + 2 * a11 * a21 * c.MG + a21 * a21 * c.NG - c.LF;  // eq 3.5
  double b12 = a11 * a12 * c.LG + (a11 * a22 + a21 * a12) * c.MG + a21 * a22 * c.NG - c.MF;
  double b22 = a12 * a12 * c.LG + 2 * a12 * a22 * c.MG + a22 * a22 * c.NG - c.NF;
  const Vec3 p = F.p;
  double size = std::max(
      {std::fabs(c.LF), std::fabs(c.MF), std::fabs(c.NF), std::fabs(c.LG), std::fabs(c.MG), std::fabs(c.NG), 1.0});
  double big = std::max({std::fabs(b11), std::fabs(b12), std::fabs(b22)});
  if (!std::isfinite(c.D) || !std::isfinite(big)) {
    out.push_back(only_status(p, theta, GeometryStatus::kNonFinite));
    return out;
  }
  if (!(big > tol.tangential_discriminant * size)) {
    out.push_back(only_status(p, theta, GeometryStatus::kHigherOrderContact));
    return out;
  }
  double disc = b12 * b12 - b11 * b22;
  if (disc < -tol.tangential_discriminant * big * big) {
    out.push_back(only_status(p, theta, GeometryStatus::kIsolatedPoint));
    return out;
  }
  double root = std::sqrt(std::max(disc, 0.0));
  bool one = disc <= tol.tangential_discriminant * big * big;
  // Eq 3.6 chooses omega = u'/v' when b11 != 0 and mu = v'/u' otherwise; we take the root
  // variable of the larger leading coefficient, which is the same case split made stable.
  std::vector<Vec2> uv;  // (u', v') up to scale
  for (double sgn : {1.0, -1.0}) {
    uv.push_back(std::fabs(b11) >= std::fabs(b22) ? Vec2((-b12 + sgn * root) / b11, 1.0)
                                                  : Vec2(1.0, (-b12 + sgn * root) / b22));
    if (one) break;
  }
  for (const Vec2& w : uv) out.push_back(thesis_tangential_branch(F, G, N, c, w, theta, orientation, tol));
  return out;
}

namespace {
const CurveGeometry& closest_branch(const std::vector<CurveGeometry>& branches, const Vec3* orientation) {
  std::size_t best = 0;
  if (orientation) {
    double best_dot = -2;
    for (std::size_t i = 0; i < branches.size(); ++i) {
      if (!branches[i].has_tangent()) continue;
      double d = std::fabs(branches[i].t.dot(*orientation));
      if (d > best_dot) {
        best_dot = d;
        best = i;
      }
    }
  }
  return branches[best];
}
}  // namespace

CurveGeometry ye_maekawa(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                         const GeometryTolerances& tol) {
  CurveGeometry g = ye_maekawa_transversal(first, second, orientation, tol);
  if (g.status != GeometryStatus::kSingular) return g;
  return closest_branch(ye_maekawa_tangential(first, second, orientation, tol), orientation);
}

Vec3 intersection_tangent(const SurfaceLocal& first, const SurfaceLocal& second, const Vec3* orientation,
                          const GeometryTolerances& tol) {
  TransversalStart s = start_transversal(first, second, orientation, tol);
  if (s.ok) return s.g.t;
  if (s.g.status != GeometryStatus::kSingular) return Vec3::Constant(kNaN);
  return closest_branch(ye_maekawa_tangential(first, second, orientation, tol), orientation).t;
}

}  // namespace ssimarch
