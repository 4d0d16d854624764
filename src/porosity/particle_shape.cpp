// Chord and shadow geometry. Source: docs/math/circle_spherocylinder.md "Chord formulation".
#include "ssimarch/porosity/particle_shape.hpp"

#include "ssimarch/porosity/polynomial_roots.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ssimarch {

namespace {

// Squared distance from q to the segment [p0, p1] in the plane.
double dist2_segment(double qx, double qy, double p0x, double p0y, double p1x, double p1y) {
  const double dx = p1x - p0x, dy = p1y - p0y;
  const double l2 = dx * dx + dy * dy;
  double t = 0.0;
  if (l2 > 0) t = std::clamp(((qx - p0x) * dx + (qy - p0y) * dy) / l2, 0.0, 1.0);
  const double ex = qx - (p0x + t * dx), ey = qy - (p0y + t * dy);
  return ex * ex + ey * ey;
}

void hull(Chord& acc, double lo, double hi) {
  if (acc.empty()) {
    acc = {lo, hi};
  } else {
    acc.lo = std::min(acc.lo, lo);
    acc.hi = std::max(acc.hi, hi);
  }
}

}  // namespace

ParticleShape::ParticleShape(const Particle& p) : p_(p) {
  a_ = p.radius();
  a2_ = a_ * a_;
  h_ = p.half_length();
  cp_ = p.plus_cap();
  cm_ = p.minus_cap();
  const double ux = p.axis.x(), uy = p.axis.y();
  alpha_ = ux * ux + uy * uy;
  const double dx = cp_.x() - cm_.x(), dy = cp_.y() - cm_.y();
  plen_ = std::hypot(dx, dy);
  if (plen_ > 1e-14 * a_) {
    has_lines_ = true;
    ex_ = dx / plen_;
    ey_ = dy / plen_;
  }
  const double dseg = std::sqrt(dist2_segment(0, 0, cm_.x(), cm_.y(), cp_.x(), cp_.y()));
  rho_min_ = std::max(0.0, dseg - a_);
  const double rho_plus = std::hypot(cp_.x(), cp_.y());
  rho_max_ = (h_ == 0 ? rho_plus : std::max(rho_plus, std::hypot(cm_.x(), cm_.y()))) + a_;
  z_min_ = std::min(cp_.z(), cm_.z()) - a_;
  z_max_ = std::max(cp_.z(), cm_.z()) + a_;
}

Chord ParticleShape::vertical_chord(double x, double y) const {
  Chord out;
  for (const Vec3* c : {&cp_, &cm_}) {
    const double dx = x - c->x(), dy = y - c->y();
    const double q = a2_ - dx * dx - dy * dy;
    if (q >= 0) {
      const double s = std::sqrt(q);
      hull(out, c->z() - s, c->z() + s);
    }
    if (h_ == 0) break;
  }
  if (h_ == 0) return out;
  // Finite cylinder: dist^2 to the axis <= a^2 is alpha tau^2 + beta tau + gamma <= 0 with
  // tau = t - c_z; the slab |lambda| <= h is linear in tau.
  const Vec3& c = p_.centre;
  const double ux = p_.axis.x(), uy = p_.axis.y(), uz = p_.axis.z();
  const double wx = x - c.x(), wy = y - c.y();
  const double lam0 = ux * wx + uy * wy;
  const double beta = -2 * lam0 * uz;
  const double gamma = wx * wx + wy * wy - lam0 * lam0 - a2_;
  double t0, t1;
  if (alpha_ > 1e-300) {
    const double disc = beta * beta - 4 * alpha_ * gamma;
    if (disc < 0) return out;
    const double sq = std::sqrt(disc);
    const double q = -(beta + std::copysign(sq, beta)) / 2;
    if (q == 0) {
      t0 = t1 = 0;
    } else {
      t0 = q / alpha_;
      t1 = gamma / q;
    }
    if (t0 > t1) std::swap(t0, t1);
  } else {
    if (gamma > 0) return out;
    t0 = -INFINITY;
    t1 = INFINITY;
  }
  if (uz != 0) {
    double s0 = (-h_ - lam0) / uz, s1 = (h_ - lam0) / uz;
    if (s0 > s1) std::swap(s0, s1);
    t0 = std::max(t0, s0);
    t1 = std::min(t1, s1);
  } else if (std::abs(lam0) > h_) {
    return out;
  }
  if (t1 >= t0 && std::isfinite(t0) && std::isfinite(t1)) hull(out, c.z() + t0, c.z() + t1);
  return out;
}

bool ParticleShape::shadow_contains(double x, double y) const {
  return dist2_segment(x, y, cm_.x(), cm_.y(), cp_.x(), cp_.y()) <= a2_;
}

int ParticleShape::shadow_arcs(double r, std::array<Arc, 4>& arcs, bool& full) const {
  full = false;
  std::array<double, 8> cand{};
  int n = 0;
  auto add = [&](double t) {
    if (n < 8) cand[n++] = std::remainder(t, 2 * std::numbers::pi);
  };
  // Outline arcs: circles of radius a around the projected cap centres.
  for (const Vec3* c : {&cp_, &cm_}) {
    const double rho = std::hypot(c->x(), c->y());
    if (rho > 0) {
      const double cs = (r * r + rho * rho - a2_) / (2 * r * rho);
      if (std::abs(cs) <= 1) {
        const double phi = std::atan2(c->y(), c->x()), al = std::acos(cs);
        add(phi - al);
        add(phi + al);
      }
    }
    if (h_ == 0) break;
  }
  // Outline edges: lines n.p = n.P- +- a.
  if (has_lines_) {
    const double nx = -ey_, ny = ex_;
    const double phin = std::atan2(ny, nx);
    const double base = nx * cm_.x() + ny * cm_.y();
    for (double d : {base + a_, base - a_}) {
      if (std::abs(d) <= r) {
        const double al = std::acos(d / r);
        add(phin - al);
        add(phin + al);
      }
    }
  }
  auto inside = [&](double t) { return shadow_contains(r * std::cos(t), r * std::sin(t)); };
  if (n == 0) {
    full = inside(0.0);
    return 0;
  }
  internal::small_sort(cand.data(), n);
  // Classify each arc between consecutive candidates by its midpoint; merge neighbouring inside arcs.
  std::array<Arc, 8> raw{};
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const double lo = cand[k], hi = (k + 1 < n) ? cand[k + 1] : cand[0] + 2 * std::numbers::pi;
    if (!(hi > lo) || !inside((lo + hi) / 2)) continue;
    if (m > 0 && raw[m - 1].end == lo) {
      raw[m - 1].end = hi;
    } else {
      raw[m++] = {lo, hi};
    }
  }
  // Wrap-around merge: last arc ending where the first begins (+ 2 pi).
  if (m >= 2 && raw[m - 1].end == raw[0].begin + 2 * std::numbers::pi) {
    raw[0].begin = raw[m - 1].begin - 2 * std::numbers::pi;
    --m;
  }
  if (m == 1 && raw[0].end - raw[0].begin >= 2 * std::numbers::pi) {
    full = true;
    return 0;
  }
  const int count = std::min(m, 4);
  for (int k = 0; k < count; ++k) arcs[k] = raw[k];
  return count;
}

int ParticleShape::junction_angles(double r, std::array<double, 8>& out) const {
  if (h_ == 0) return 0;
  // Orthonormal v1, v2 perpendicular to the axis: junction circle C + a (cos psi v1 + sin psi v2).
  const Vec3& u = p_.axis;
  const Vec3 helper = std::abs(u.z()) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
  const Vec3 v1 = u.cross(helper).normalized(), v2 = u.cross(v1);
  int n = 0;
  for (const Vec3* c : {&cp_, &cm_}) {
    const double cx = c->x(), cy = c->y();
    const double K0 = cx * cx + cy * cy - r * r;
    const double A1 = 2 * a_ * (cx * v1.x() + cy * v1.y()), B1 = 2 * a_ * (cx * v2.x() + cy * v2.y());
    const double P = a2_ * (v1.x() * v1.x() + v1.y() * v1.y()), Q = 2 * a2_ * (v1.x() * v2.x() + v1.y() * v2.y());
    const double S = a2_ * (v2.x() * v2.x() + v2.y() * v2.y());
    // (1 + t^2)^2 (K0 + A1 cos + B1 sin + P cos^2 + Q cos sin + S sin^2), t = tan(psi/2), ascending.
    double q[5] = {K0 + A1 + P, 2 * B1 + 2 * Q, 2 * K0 - 2 * P + 4 * S, 2 * B1 - 2 * Q, K0 - A1 + P};
    int deg = 4;
    const double scale = std::abs(K0) + std::abs(A1) + std::abs(B1) + P + std::abs(Q) + S;
    while (deg > 0 && std::abs(q[deg]) <= 1e-14 * scale) --deg;
    std::array<double, 5> psis{};
    int np = 0;
    if (deg < 4) psis[np++] = std::numbers::pi;  // root at t = infinity
    if (deg >= 1) {
      const RealRoots<double> t = real_roots(q, deg, 1e-14);
      for (int k = 0; k < t.count && np < 5; ++k) psis[np++] = 2 * std::atan(t.x[k]);
    }
    for (int k = 0; k < np && n < 8; ++k) {
      const Vec3 e = *c + a_ * (std::cos(psis[k]) * v1 + std::sin(psis[k]) * v2);
      out[n++] = std::atan2(e.y(), e.x());
    }
  }
  return n;
}

int ParticleShape::clip_angles(double r, double z_cut, std::array<double, 8>& out, int n) const {
  for (const Vec3* c : {&cp_, &cm_}) {
    const double dz = z_cut - c->z(), s2 = a2_ - dz * dz;
    const double rho = std::hypot(c->x(), c->y());
    if (s2 > 0 && rho > 0) {
      const double cs = (r * r + rho * rho - s2) / (2 * r * rho);
      if (std::abs(cs) <= 1 && n + 2 <= 8) {
        const double phi = std::atan2(c->y(), c->x()), al = std::acos(cs);
        out[n++] = std::remainder(phi - al, 2 * std::numbers::pi);
        out[n++] = std::remainder(phi + al, 2 * std::numbers::pi);
      }
    }
    if (h_ == 0) break;
  }
  return n;
}

void ParticleShape::clip_radii(double z_cut, std::vector<double>& out) const {
  for (const Vec3* c : {&cp_, &cm_}) {
    const double dz = z_cut - c->z(), s2 = a2_ - dz * dz;
    if (s2 > 0) {
      const double rho = std::hypot(c->x(), c->y()), sr = std::sqrt(s2);
      out.push_back(rho + sr);
      out.push_back(std::abs(rho - sr));
    }
    if (h_ == 0) break;
  }
}

std::vector<double> ParticleShape::critical_radii() const {
  std::vector<double> out;
  out.push_back(rho_min_);
  out.push_back(rho_max_);
  for (const Vec3* c : {&cp_, &cm_}) {
    const double rho = std::hypot(c->x(), c->y());
    out.push_back(rho + a_);
    if (rho > a_) out.push_back(rho - a_);
    if (h_ == 0) break;
  }
  if (has_lines_) {
    const double nx = -ey_, ny = ex_;
    for (double sg : {+1.0, -1.0}) {
      // Edge from P- + sg a n to P+ + sg a n: foot of the perpendicular from the origin, and corners.
      const double qx = cm_.x() + sg * a_ * nx, qy = cm_.y() + sg * a_ * ny;
      const double t = -(qx * ex_ + qy * ey_);
      if (t > 0 && t < plen_) out.push_back(std::abs(qx * nx + qy * ny));
      out.push_back(std::hypot(qx, qy));
      out.push_back(std::hypot(qx + plen_ * ex_, qy + plen_ * ey_));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  std::vector<double> clipped;
  for (double v : out)
    if (v >= rho_min_ && v <= rho_max_) clipped.push_back(v);
  return clipped;
}

}  // namespace ssimarch
