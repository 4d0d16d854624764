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
#include <vector>

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

}  // namespace ssimarch::internal
