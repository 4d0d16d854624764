// Area of a union of disks in closed form (internal to porosity: sections of overlapping balls).
// Green's theorem: the area is the integral of (x dy - y dx) / 2 along the union's boundary, which
// is made of the arcs of each circle lying outside every other disk; on the arc
// theta in [t1, t2] of the circle (cx, cy, s) the integral is
//   (s^2 (t2 - t1) + cx s (sin t2 - sin t1) - cy s (cos t2 - cos t1)) / 2.
// Source: docs/math/particle_union.md §3 (the standard boundary formula, e.g. Avis, Bhattacharya
// and Imai 1988, "Computing the volume of the union of spheres", The Visual Computer 3, §2).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "ssimarch/porosity/sphere_arc.hpp"

namespace ssimarch::internal {

struct Disk {
  double x = 0.0, y = 0.0, s = 0.0;  ///< centre and radius (> 0)
};

/// Area of the union of the disks, inside the disk `clip` when given. Equal disks count once (the
/// first of them); a disk inside another adds nothing. `cuts` is scratch.
inline double union_of_disks_area(const std::vector<Disk>& disks, std::vector<double>& cuts,
                                  const Disk* clip = nullptr) {
  constexpr double pi = std::numbers::pi;
  auto same = [](const Disk& a, const Disk& b) { return a.x == b.x && a.y == b.y && a.s == b.s; };
  auto inside = [](const Disk& e, double px, double py) { return std::hypot(px - e.x, py - e.y) < e.s; };
  // Angles on circle d where circle e crosses it.
  auto crossings = [&](const Disk& d, const Disk& e) {
    const double dx = e.x - d.x, dy = e.y - d.y, D = std::hypot(dx, dy);
    if (D >= d.s + e.s || D <= std::abs(d.s - e.s)) return;
    const double base = std::atan2(dy, dx);
    const double al = std::acos(std::clamp((d.s * d.s + D * D - e.s * e.s) / (2 * d.s * D), -1.0, 1.0));
    cuts.push_back(std::remainder(base - al, 2 * pi));
    cuts.push_back(std::remainder(base + al, 2 * pi));
  };
  // Green's integral over the arcs of circle d between its cuts that `keep` accepts.
  auto boundary = [&](const Disk& d, auto&& keep) {
    if (cuts.empty()) cuts.push_back(-pi);
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(cuts.front() + 2 * pi);
    double a = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double t1 = cuts[k], t2 = cuts[k + 1];
      if (!(t2 > t1)) continue;
      const double tm = (t1 + t2) / 2;
      if (keep(d.x + d.s * std::cos(tm), d.y + d.s * std::sin(tm)))
        a += (d.s * d.s * (t2 - t1) + d.x * d.s * (std::sin(t2) - std::sin(t1)) -
              d.y * d.s * (std::cos(t2) - std::cos(t1))) /
             2;
    }
    return a;
  };
  double area = 0.0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const Disk& d = disks[i];
    bool repeated = false;
    for (std::size_t j = 0; j < i && !repeated; ++j) repeated = same(disks[j], d);
    if (repeated) continue;
    cuts.clear();
    for (std::size_t j = 0; j < disks.size(); ++j)
      if (j != i && !same(disks[j], d)) crossings(d, disks[j]);
    if (clip) crossings(d, *clip);
    area += boundary(d, [&](double px, double py) {
      if (clip && !inside(*clip, px, py)) return false;
      for (std::size_t j = 0; j < disks.size(); ++j)
        if (j != i && !same(disks[j], d) && inside(disks[j], px, py)) return false;
      return true;
    });
  }
  if (clip) {
    // The clip circle's arcs inside the union close the boundary.
    cuts.clear();
    for (const Disk& e : disks) crossings(*clip, e);
    area += boundary(*clip, [&](double px, double py) {
      for (const Disk& e : disks)
        if (inside(e, px, py)) return true;
      return false;
    });
  }
  return area;
}

/// Area of the intersection of three disks: the arcs of each circle lying inside the other two
/// disks, by the same boundary formula. The section of a lens of two balls inside a bin's circle,
/// evaluated at every height of the shell volumes' quadrature, so the crossings are formed as
/// points (the arcs' ends need their cosines and sines, one atan2 each orders them) and the arcs'
/// midpoints from their ends, on fixed arrays. Equal disks count once.
inline double intersection_of_three_disks_area(const Disk& a, const Disk& b, const Disk& c) {
  constexpr double pi = std::numbers::pi;
  auto same = [](const Disk& p, const Disk& q) { return p.x == q.x && p.y == q.y && p.s == q.s; };
  auto two = [](const Disk& p, const Disk& q) { return disk_disk_area(p.s, q.s, std::hypot(q.x - p.x, q.y - p.y)); };
  if (same(a, b) || same(a, c)) return two(b, c);
  if (same(b, c)) return two(a, b);
  auto inside = [](const Disk& e, double px, double py) {
    return (px - e.x) * (px - e.x) + (py - e.y) * (py - e.y) < e.s * e.s;
  };
  // A point of circle p at angle t: its angle and (cos t, sin t).
  struct Cut {
    double t, c, s;
  };
  const Disk* d[3] = {&a, &b, &c};
  double area = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Disk &p = *d[i], &q = *d[(i + 1) % 3], &r = *d[(i + 2) % 3];
    Cut cuts[5];
    int n = 0;
    for (const Disk* e : {&q, &r}) {
      const double dx = e->x - p.x, dy = e->y - p.y, D = std::hypot(dx, dy);
      if (D >= p.s + e->s || D <= std::abs(p.s - e->s)) continue;
      // The crossings at distance m along the line of centres and h across it, over p's radius.
      const double m = (p.s * p.s - e->s * e->s + D * D) / (2 * D * p.s);
      const double h = std::sqrt(std::max(0.0, (1 - m) * (1 + m)));
      const double ux = dx / D, uy = dy / D;
      for (double side : {-1.0, 1.0}) {
        const double cx = m * ux - side * h * uy, cy = m * uy + side * h * ux;
        cuts[n++] = {std::atan2(cy, cx), cx, cy};
      }
    }
    if (n == 0) {
      // The whole circle lies inside or outside each other disk.
      if (inside(q, p.x + p.s, p.y) && inside(r, p.x + p.s, p.y)) area += pi * p.s * p.s;
      continue;
    }
    for (int k = 1; k < n; ++k)  // insertion sort: std::sort on a small array trips GCC 12's -Warray-bounds
      for (int j = k; j > 0 && cuts[j].t < cuts[j - 1].t; --j) std::swap(cuts[j], cuts[j - 1]);
    cuts[n] = {cuts[0].t + 2 * pi, cuts[0].c, cuts[0].s};
    for (int k = 0; k < n; ++k) {
      const Cut &u = cuts[k], &v = cuts[k + 1];
      const double w = v.t - u.t;
      if (!(w > 0)) continue;
      // The arc's midpoint: along the sum of its ends' directions, reversed past half a turn.
      double mx = u.c + v.c, my = u.s + v.s;
      const double len = std::hypot(mx, my);
      if (len < 1e-9) {
        mx = -u.s, my = u.c;  // half a turn: the midpoint is a quarter turn from either end
      } else {
        const double flip = w > pi ? -1.0 : 1.0;
        mx *= flip / len, my *= flip / len;
      }
      if (inside(q, p.x + p.s * mx, p.y + p.s * my) && inside(r, p.x + p.s * mx, p.y + p.s * my))
        area += (p.s * p.s * w + p.x * p.s * (v.s - u.s) - p.y * p.s * (v.c - u.c)) / 2;
    }
  }
  return area;
}

}  // namespace ssimarch::internal
