#include "ssimarch/surface/degenerate_edges.hpp"

#include <cmath>

#include "edge_samples.hpp"

namespace ssimarch {

namespace {
double edge_eps(const Surface& surface) { return internal::edge_eps(surface.box()); }
Vec3 point_of(const Surface& surface, double u, double v) {
  const Vec3T<double> p = surface.point(u, v);
  return {p.x, p.y, p.z};
}
}  // namespace

bool closes_seam(const Surface& surface, int parameter) {
  if (!surface.is_parametric()) return false;
  const ParamDomain& d = surface.domain();
  if (parameter == 0 ? d.periodic_u : d.periodic_v) return false;
  return internal::edges_agree([&](double u, double v) { return point_of(surface, u, v); }, parameter, d,
                               edge_eps(surface));
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
