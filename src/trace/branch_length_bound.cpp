#include "ssimarch/trace/branch_length_bound.hpp"

#include <cmath>

namespace ssimarch {

namespace {

// Area of the patch (u, v) -> s.point(u, v) over its domain: a grid of parallelograms spanned
// by the cells' edge vectors.
double patch_area(const Surface& s, const Interval& u, const Interval& v) {
  const int n = kAreaGridCells;
  const double du = u.width() / n, dv = v.width() / n;
  auto at = [&](int i, int j) {
    const Vec3T<double> p = s.point(u.lo + i * du, v.lo + j * dv);
    return Vec3(p.x, p.y, p.z);
  };
  double area = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 p = at(i, j);
      area += 0.5 * ((at(i + 1, j) - p).cross(at(i, j + 1) - p).norm() +
                     (at(i + 1, j) - at(i + 1, j + 1)).cross(at(i, j + 1) - at(i + 1, j + 1)).norm());
    }
  return area;
}

}  // namespace

double branch_length_bound(const Problem& P, double resolution) {
  const auto& b = P.bounds();
  if (P.kind() == PairKind::kImplicitImplicit) {
    double volume = 1;
    for (int k = 0; k < 3; ++k) volume *= b[static_cast<std::size_t>(k)].width() + resolution;
    return 4 * volume / (M_PI * resolution * resolution) + P.scale();
  }
  double area = patch_area(P.first(), b[0], b[1]);
  if (P.kind() == PairKind::kParametricParametric) area = std::min(area, patch_area(P.second(), b[2], b[3]));
  return 2 * area / resolution + P.scale();
}

}  // namespace ssimarch
