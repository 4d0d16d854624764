#include "ssimarch/surface/degenerate_edges.hpp"

#include <cmath>

namespace ssimarch {

namespace {
double edge_eps(const Surface& surface) {
  const Box& b = surface.box();
  const double diagonal = Vec3(b.x.width(), b.y.width(), b.z.width()).norm();
  return kDegenerateEdgeRelative * (std::isfinite(diagonal) && diagonal > 0 ? diagonal : 1.0);
}
}  // namespace

bool closes_seam(const Surface& surface, int parameter) {
  if (!surface.is_parametric()) return false;
  const ParamDomain& d = surface.domain();
  if (parameter == 0 ? d.periodic_u : d.periodic_v) return false;
  const Interval& across = parameter == 0 ? d.u : d.v;
  const Interval& along = parameter == 0 ? d.v : d.u;
  const double eps = edge_eps(surface);
  constexpr int kSamples = 33;
  for (int i = 0; i < kSamples; ++i) {
    const double w = along.lo + along.width() * i / (kSamples - 1);
    const Vec3T<double> a = parameter == 0 ? surface.point(across.lo, w) : surface.point(w, across.lo);
    const Vec3T<double> b = parameter == 0 ? surface.point(across.hi, w) : surface.point(w, across.hi);
    const Vec3 diff(a.x - b.x, a.y - b.y, a.z - b.z);
    if (!diff.allFinite() || diff.norm() > eps) return false;
  }
  return true;
}

std::vector<DegenerateEdge> degenerate_edges(const Surface& surface) {
  std::vector<DegenerateEdge> out;
  if (!surface.is_parametric()) return out;
  const ParamDomain& d = surface.domain();
  const double eps = edge_eps(surface);
  const Interval* range[2] = {&d.u, &d.v};
  const bool periodic[2] = {d.periodic_u, d.periodic_v};
  constexpr int kSamples = 33;
  for (int k = 0; k < 2; ++k) {
    if (periodic[k] || closes_seam(surface, k)) continue;
    const Interval& along = *range[1 - k];
    for (bool upper : {false, true}) {
      const double value = upper ? range[k]->hi : range[k]->lo;
      auto at = [&](double w) {
        Vec3T<double> p = k == 0 ? surface.point(value, w) : surface.point(w, value);
        return Vec3(p.x, p.y, p.z);
      };
      const Vec3 first = at(along.lo);
      bool one_point = first.allFinite();
      for (int i = 1; i < kSamples && one_point; ++i) {
        const Vec3 q = at(along.lo + along.width() * i / (kSamples - 1));
        one_point = q.allFinite() && (q - first).norm() <= eps;
      }
      if (one_point) out.push_back({k, value, upper, first});
    }
  }
  return out;
}

}  // namespace ssimarch
