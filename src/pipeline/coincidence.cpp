#include "ssimarch/pipeline/coincidence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ssimarch/core/jet.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/start/interval_forms.hpp"

namespace ssimarch {

namespace {

// Value and gradient of an implicit surface at p.
struct ImplicitValue {
  double value;
  Vec3 gradient;
};

ImplicitValue implicit_value(const Surface& s, const Vec3& p) {
  using J = Jet<3, 1>;
  const J v = s.value(Vec3T<J>{J::variable(0, p.x()), J::variable(1, p.y()), J::variable(2, p.z())});
  return {v.value(), Vec3(v.derivative({1, 0, 0}), v.derivative({0, 1, 0}), v.derivative({0, 0, 1}))};
}

double sample(const Interval& iv, int i, int n) { return iv.lo + iv.width() * (i + 0.5) / n; }

// Points of a parametric surface on its parameter grid.
void parametric_samples(const Surface& s, int n, std::vector<Vec3>* out) {
  const ParamDomain& d = s.domain();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3T<double> p = s.point(sample(d.u, i, n), sample(d.v, j, n));
      out->emplace_back(p.x, p.y, p.z);
    }
}

// Grid points of `box` moved onto an implicit surface by Newton along the gradient (at most 20
// steps; kept when the first-order distance falls below `tolerance`).
void implicit_samples(const Surface& s, const Box& box, int n, double tolerance, std::vector<Vec3>* out) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        Vec3 p(sample(box.x, i, n), sample(box.y, j, n), sample(box.z, k, n));
        for (int it = 0; it < 20; ++it) {
          const ImplicitValue f = implicit_value(s, p);
          const double g2 = f.gradient.squaredNorm();
          if (!std::isfinite(f.value) || !(g2 > 0) || !std::isfinite(g2)) break;
          if (std::abs(f.value) <= tolerance * std::sqrt(g2)) {
            out->push_back(p);
            break;
          }
          p -= f.value / g2 * f.gradient;
        }
      }
}

// Distance of p from a surface: to its nearest point (parametric), first order (implicit).
double distance_from(const Surface& s, const Vec3& p) {
  if (s.is_parametric()) {
    const auto uv = closest_parameters(s, p);
    if (!uv) return std::numeric_limits<double>::quiet_NaN();
    const Vec3T<double> q = s.point((*uv)[0], (*uv)[1]);
    return (Vec3(q.x, q.y, q.z) - p).norm();
  }
  const ImplicitValue f = implicit_value(s, p);
  return std::abs(f.value) / f.gradient.norm();
}

// Parameter cells per direction of the enclosures below: 256 interval evaluations, against a
// closest-point solve per sample (a global search on a B-spline) that they spare.
constexpr int kEnclosureCells = 16;

// Boxes that enclose a parametric surface cell by cell of its domain (the certified search's sound
// interval forms, start/interval_forms.hpp): a point farther than a tolerance from every box is
// farther than that from the surface. Empty where no such enclosure exists (implicit or unbounded
// surfaces, interval forms that are not sound: evaluates_on_intervals, an unbounded box).
std::vector<Box> cell_enclosures(const Surface& s) {
  std::vector<Box> out;
  if (!s.is_parametric() || !evaluates_on_intervals(s)) return out;
  const ParamDomain& d = s.domain();
  if (d.unbounded_u || d.unbounded_v || !std::isfinite(d.u.width()) || !std::isfinite(d.v.width())) return out;
  constexpr int n = kEnclosureCells;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const IntervalNumber u(d.u.lo + d.u.width() * i / n, i + 1 == n ? d.u.hi : d.u.lo + d.u.width() * (i + 1) / n);
      const IntervalNumber v(d.v.lo + d.v.width() * j / n, j + 1 == n ? d.v.hi : d.v.lo + d.v.width() * (j + 1) / n);
      const Vec3T<IntervalNumber> p = s.point(u, v);
      const Box b{{p.x.lo(), p.x.hi()}, {p.y.lo(), p.y.hi()}, {p.z.lo(), p.z.hi()}};
      for (const Interval& c : {b.x, b.y, b.z})
        if (!std::isfinite(c.lo) || !std::isfinite(c.hi)) return {};
      out.push_back(b);
    }
  return out;
}

// Whether p lies within `tolerance` of one of the boxes.
bool near_any(const std::vector<Box>& boxes, const Vec3& p, double tolerance) {
  return std::any_of(boxes.begin(), boxes.end(), [&](const Box& b) {
    return p.x() >= b.x.lo - tolerance && p.x() <= b.x.hi + tolerance && p.y() >= b.y.lo - tolerance &&
           p.y() <= b.y.hi + tolerance && p.z() >= b.z.lo - tolerance && p.z() <= b.z.hi + tolerance;
  });
}

void include(Box* b, const Vec3& p, bool first) {
  Interval* axes[3] = {&b->x, &b->y, &b->z};
  for (int k = 0; k < 3; ++k) {
    if (first) *axes[k] = {p[k], p[k]};
    axes[k]->lo = std::min(axes[k]->lo, p[k]);
    axes[k]->hi = std::max(axes[k]->hi, p[k]);
  }
}

}  // namespace

std::optional<Coincidence> find_coincidence(const Surface& sampled, const Surface& other, const Box& box,
                                            double tolerance, int grid) {
  std::vector<Vec3> points;
  if (sampled.is_parametric())
    parametric_samples(sampled, grid, &points);
  else
    implicit_samples(sampled, box, grid, tolerance, &points);
  Coincidence c;
  // Samples outside the other surface's enclosures need no closest-point solve: they lie farther
  // than the tolerance from it (most of them, where the surfaces only cross). The probe's few
  // samples do not pay for the enclosures.
  const std::vector<Box> enclosures = grid > kCoincidenceProbeGrid ? cell_enclosures(other) : std::vector<Box>{};
  for (const Vec3& p : points) {
    if (!p.allFinite()) continue;
    if (!enclosures.empty() && !near_any(enclosures, p, tolerance)) {
      ++c.samples;
      continue;
    }
    const double d = distance_from(other, p);
    if (!std::isfinite(d)) continue;
    ++c.samples;
    if (d > tolerance) continue;
    include(&c.region, p, c.shared == 0);
    ++c.shared;
    c.max_distance = std::max(c.max_distance, d);
  }
  if (c.shared < 2 * grid) return std::nullopt;
  return c;
}

std::optional<Coincidence> find_coincidence(const Problem& problem, double tolerance, int grid) {
  return find_coincidence(problem.first(), problem.second(), problem.first().box(), tolerance, grid);
}

std::optional<Coincidence> probe_coincidence(const Problem& problem, double tolerance) {
  const Surface* order[2][2] = {{&problem.first(), &problem.second()}, {&problem.second(), &problem.first()}};
  for (const auto& [sampled, other] : order)
    if (find_coincidence(*sampled, *other, sampled->box(), tolerance, kCoincidenceProbeGrid))
      if (auto c = find_coincidence(*sampled, *other, sampled->box(), tolerance)) return c;
  return std::nullopt;
}

}  // namespace ssimarch
