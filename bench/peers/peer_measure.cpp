#include "peer_measure.hpp"

#include <algorithm>
#include <cmath>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/surface/derivatives.hpp"

namespace peers {

using namespace ssimarch;

double distance_to(const Surface& s, const Vec3& p) {
  if (s.is_implicit()) {
    const auto f = implicit_jet<1>(s, p);
    const double g = std::sqrt(f.d(0) * f.d(0) + f.d(1) * f.d(1) + f.d(2) * f.d(2));
    return g > 0 ? std::fabs(f.value()) / g : std::fabs(f.value());
  }
  const auto uv = closest_parameters(s, p, 48);
  if (!uv) return INFINITY;
  return (ssimarch::point(s, uv->x(), uv->y()) - p).norm();
}

double residual(const Surface& a, const Surface& b, const Vec3& p) { return std::max(distance_to(a, p), distance_to(b, p)); }

double median(std::vector<double> t) {
  if (t.empty()) return NAN;
  std::sort(t.begin(), t.end());
  const std::size_t n = t.size();
  return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

}  // namespace peers
