// Seed 001 kernel; see the header for the method. Source: seed 001 (thesis
// Appendix A §A.2-A.6, Fig. A.9); docs/math/circle_spherocylinder.md §1.
#include "ssimarch/porosity/circle_spherocylinder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ssimarch/porosity/polynomial_roots.hpp"

namespace ssimarch {

const char* to_string(ArcCase c) {
  switch (c) {
    case ArcCase::kOutside: return "outside";
    case ArcCase::kInside: return "inside";
    case ArcCase::kArcs: return "arcs";
    case ArcCase::kCoaxialOnSurface: return "coaxial_on_surface";
    case ArcCase::kCapSection: return "cap_section";
    case ArcCase::kFallback: return "fallback";
  }
  return "?";
}

template <class T>
T inside_margin(const SpherocylinderT<T>& s, const typename SpherocylinderT<T>::Point& p) {
  const typename SpherocylinderT<T>::Point w = p - s.centre;
  const T h = s.half_length();
  const T lam = std::clamp(s.axis.dot(w), -h, h);
  return s.radius() - (w - lam * s.axis).norm();
}

namespace {

template <class T>
struct Crossings {
  std::array<T, 8> theta{};
  std::array<SpherocylinderPart, 8> piece{};
  int n = 0;
  void add(T t, SpherocylinderPart p) {
    if (n < 8) {
      theta[n] = t;
      piece[n++] = p;
    }
  }
};

template <class T>
struct Kernel {
  using Point = typename SpherocylinderT<T>::Point;
  const SpherocylinderT<T>& s;
  T z, r;
  const KernelTolerances& tol;
  T pi = std::numbers::pi_v<T>;
  T h, scale, ctol, band, A, B;

  Kernel(const SpherocylinderT<T>& s_, T z_, T r_, const KernelTolerances& t) : s(s_), z(z_), r(r_), tol(t) {
    h = s.half_length();
    const T s2 = r * r + z * z + s.centre.squaredNorm() + s.diameter * s.diameter / T(4) + s.length * s.length;
    scale = std::sqrt(s2);
    ctol = T(tol.coefficient) * s2;
    band = T(tol.junction) * scale;
    // A.10, written as sigma^2/4 - (r^2 + (z - r_z)^2 + r_x^2 + r_y^2) to avoid cancellation.
    const T dz = z - s.centre.z();
    A = s.diameter * s.diameter / T(4) -
        (r * r + dz * dz + s.centre.x() * s.centre.x() + s.centre.y() * s.centre.y());
    B = s.axis.z() * z - s.axis.dot(s.centre);  // A.11
  }

  T lambda_phi(T phi) const {  // A.25
    const T q = T(1) + phi * phi;
    return r * (s.axis.x() * (T(1) - phi * phi) + T(2) * s.axis.y() * phi) / q + B;
  }
  T lambda_theta(T th) const { return r * (s.axis.x() * std::cos(th) + s.axis.y() * std::sin(th)) + B; }  // A.24
  T theta_of(T phi) const {
    T th = T(2) * std::atan(phi);  // A.20
    if (th + pi <= T(tol.angle)) th = pi;
    return th;
  }

  // Region function (A.61/A.65): f, f+ or f- by the axial coordinate of the circle point.
  T region_value(T th) const {
    const Point p(r * std::cos(th), r * std::sin(th), z);
    const Point w = p - s.centre;
    const T lam = s.axis.dot(w);
    const T q = s.diameter * s.diameter / T(4);
    switch (piece_of(lam, h, T(0))) {
      case SpherocylinderPart::kPlusCap: return q - (p - s.plus_cap()).squaredNorm();
      case SpherocylinderPart::kMinusCap: return q - (p - s.minus_cap()).squaredNorm();
      case SpherocylinderPart::kCylinder: break;
    }
    return q - w.squaredNorm() + lam * lam;
  }

  // Cylindrical part (§A.2): appends valid crossings; `all` receives every root (fallback).
  void cylinder(Crossings<T>& valid, Crossings<T>& all) const {
    const T ux = s.axis.x(), uy = s.axis.y();
    const T rx = s.centre.x(), ry = s.centre.y();
    const T a = A + (B - ux * r) * (B - ux * r) - T(2) * rx * r;  // A.19
    const T b = T(4) * r * (ry + uy * (B - ux * r));
    const T c = T(2) * (A + B * B - (ux * r) * (ux * r) + T(2) * (uy * r) * (uy * r));
    const T d = T(4) * r * (ry + uy * (B + ux * r));
    const T e = A + (B + ux * r) * (B + ux * r) + T(2) * rx * r;
    int n_pi = 0;
    RealRoots<T> phis;
    const T rt = T(tol.root);
    if (negligible(a, ctol)) {
      if (negligible(b, ctol)) {
        if (negligible(c, ctol)) {
          n_pi = 4;  // the cylinder touches the circle only at theta = pi (convexity)
        } else {
          n_pi = 2;
          const T q[3] = {e, d, c};
          phis = real_roots(q, 2, rt);
        }
      } else {
        n_pi = 1;
        const T q[4] = {e, d, c, b};
        phis = real_roots(q, 3, rt);
      }
    } else {
      const T q[5] = {e, d, c, b, a};
      phis = real_roots(q, 4, rt);
    }
    const T lam_pi = B - ux * r;  // A.26
    for (int k = 0; k < n_pi; ++k) {
      all.add(pi, SpherocylinderPart::kCylinder);
      if (piece_of(lam_pi, h, band) == SpherocylinderPart::kCylinder) valid.add(pi, SpherocylinderPart::kCylinder);  // flowchart fix
    }
    for (int k = 0; k < phis.count; ++k) {
      const T th = theta_of(phis.x[k]);
      all.add(th, SpherocylinderPart::kCylinder);
      if (piece_of(lambda_phi(phis.x[k]), h, band) == SpherocylinderPart::kCylinder) valid.add(th, SpherocylinderPart::kCylinder);
    }
  }

  // One hemispherical cap (§A.3-A.4). Returns true with `full` set when the circle lies on the
  // cap sphere (A.38 / A.52).
  bool cap(int sgn, Crossings<T>& valid, Crossings<T>& all, bool& full) const {
    const Point rc = sgn > 0 ? s.plus_cap() : s.minus_cap();  // A.29 / A.47
    const SpherocylinderPart want = sgn > 0 ? SpherocylinderPart::kPlusCap : SpherocylinderPart::kMinusCap;
    const T stol = T(tol.special) * scale;
    const T q = s.diameter * s.diameter / T(4);
    const T dz = z - rc.z();
    if (std::abs(rc.x()) <= stol && std::abs(rc.y()) <= stol) {
      if (std::abs(r * r - (q - dz * dz)) <= T(tol.special) * scale * scale) {
        full = true;
        return true;
      }
      return false;  // centred on the axis but not through the circle: no isolated crossing
    }
    const T Ac = q - (r * r + dz * dz + rc.x() * rc.x() + rc.y() * rc.y());  // A.33 / A.48
    const T ap = Ac - T(2) * rc.x() * r;                                        // A.41 / A.54
    const T bp = T(4) * rc.y() * r;
    const T cp = Ac + T(2) * rc.x() * r;
    const T lam_pi = B - s.axis.x() * r;
    auto take = [&](T th, T lam) {
      all.add(th, want);
      if (piece_of(lam, h, band) == want) valid.add(th, want);
    };
    if (negligible(ap, ctol)) {
      if (negligible(bp, ctol)) {
        take(pi, lam_pi);
        take(pi, lam_pi);
      } else {
        take(pi, lam_pi);
        const T phi = -cp / bp;
        take(theta_of(phi), lambda_phi(phi));
      }
    } else {
      const T qc[3] = {cp, bp, ap};
      const RealRoots<T> phis = real_roots(qc, 2, T(tol.root));
      for (int k = 0; k < phis.count; ++k) take(theta_of(phis.x[k]), lambda_phi(phis.x[k]));
    }
    return false;
  }

  // Arcs between all candidate roots, each classified by the exact point-in-solid test.
  CircleSpherocylinderResult<T> classify_all(const Crossings<T>& all) const {
    CircleSpherocylinderResult<T> res;
    res.which = ArcCase::kFallback;
    std::array<T, 9> t{};
    const int n = all.n;
    for (int k = 0; k < n; ++k) t[k] = all.theta[k];
    internal::small_sort(t.data(), n);
    auto inside_at = [&](T th) {
      return inside_margin(s, Point(r * std::cos(th), r * std::sin(th), z)) > T(0);
    };
    if (n == 0) {
      res.inside_length = inside_at(T(0)) ? T(2) * pi * r : T(0);
      return res;
    }
    T total = T(0);
    bool prev_in = false;
    for (int k = 0; k < n; ++k) {
      const T lo = t[k];
      const T hi = (k + 1 < n) ? t[k + 1] : t[0] + T(2) * pi;
      const bool in = hi > lo && inside_at((lo + hi) / T(2));
      if (in) total += hi - lo;
      if (k > 0 && in != prev_in && res.count < 4) res.crossing_angles[res.count++] = lo;
      prev_in = in;
    }
    res.inside_length = total * r;
    return res;
  }

  CircleSpherocylinderResult<T> run() const {
    CircleSpherocylinderResult<T> res;
    const T stol = T(tol.special) * scale;
    // A.14: coaxial circle on the cylindrical surface.
    if (std::abs(s.centre.x()) <= stol && std::abs(s.centre.y()) <= stol && std::abs(s.axis.x()) <= T(tol.special) &&
        std::abs(s.axis.y()) <= T(tol.special) && std::abs(r - s.radius()) <= stol) {
      if (std::abs(z - s.centre.z()) <= h) {
        res.which = ArcCase::kCoaxialOnSurface;
        res.inside_length = T(2) * pi * r;
        return res;
      }
    }
    Crossings<T> valid, all;
    cylinder(valid, all);
    bool full = false;
    for (int sgn : {+1, -1}) {
      if (valid.n >= 4) break;  // at most four crossings (§A.2, oracle s001.max_crossings)
      if (cap(sgn, valid, all, full) && full) {
        res.which = ArcCase::kCapSection;
        res.inside_length = T(2) * pi * r;
        return res;
      }
    }
    if (!consistent_count(valid.n)) return classify_all(all);
    // Sort crossings with their pieces.
    std::array<int, 4> idx{0, 1, 2, 3};
    internal::small_sort(idx.data(), valid.n, [&](int i, int j) { return valid.theta[i] < valid.theta[j]; });
    res.count = valid.n;
    for (int k = 0; k < valid.n; ++k) {
      res.crossing_angles[k] = valid.theta[idx[k]];
      res.crossing_pieces[k] = valid.piece[idx[k]];
    }
    const auto& th = res.crossing_angles;
    T bar = T(0);  // A.60
    if (res.count == 2) bar = th[1] - th[0];
    if (res.count == 4) bar = (th[3] - th[2]) + (th[1] - th[0]);
    T f;
    bool pi_in = res.count > 0 && pi_in_crossings(th[res.count - 1], pi, T(tol.angle));
    if (!pi_in) {
      f = region_value(pi);  // A.61
      if (negligible(f, ctol)) pi_in = true;  // theta = pi (numerically) on the surface: use theta_m
      else {
        res.which = res.count == 0 ? (region_inside(f) ? ArcCase::kInside : ArcCase::kOutside) : ArcCase::kArcs;
        res.inside_length = region_inside(f) ? (T(2) * pi - bar) * r : bar * r;  // A.62
        return res;
      }
    }
    const T thm = res.count > 0 ? (th[0] - pi) / T(2) : T(0);  // A.63
    f = region_value(thm);                                   // A.64-A.65
    res.theta_m_test = true;
    res.which = res.count == 0 ? (region_inside(f) ? ArcCase::kInside : ArcCase::kOutside) : ArcCase::kArcs;
    res.inside_length = region_inside(f) ? (T(2) * pi - bar) * r : bar * r;  // A.66
    return res;
  }
};

}  // namespace

template <class T>
CircleSpherocylinderResult<T> circle_spherocylinder(const SpherocylinderT<T>& s, T z, T r,
                                                    const KernelTolerances& tol) {
  return Kernel<T>(s, z, r, tol).run();
}

template CircleSpherocylinderResult<double> circle_spherocylinder(const SpherocylinderT<double>&, double, double,
                                                                  const KernelTolerances&);
template CircleSpherocylinderResult<long double> circle_spherocylinder(const SpherocylinderT<long double>&,
                                                                       long double, long double,
                                                                       const KernelTolerances&);
template double inside_margin(const SpherocylinderT<double>&, const Vec3&);
template long double inside_margin(const SpherocylinderT<long double>&, const SpherocylinderT<long double>::Point&);

}  // namespace ssimarch
