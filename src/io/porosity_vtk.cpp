// Porosity profiles and maps as VTK data sets (see porosity_vtk.hpp).
#include "ssimarch/io/porosity_vtk.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "ssimarch/core/contract.hpp"

namespace ssimarch {

namespace {

VtkPolyData polyline(std::vector<Vec3> points, std::vector<VtkArray> arrays) {
  VtkPolyData d;
  d.points = std::move(points);
  std::vector<std::int64_t> line(d.points.size());
  std::iota(line.begin(), line.end(), std::int64_t{0});
  if (!line.empty()) d.lines.push_back(std::move(line));
  d.point_data = std::move(arrays);
  return d;
}

// Spacing of evenly spaced values; 1 for a single value (any positive spacing would do).
double even_spacing(const std::vector<double>& v, const char* what) {
  if (v.size() < 2) return 1.0;
  const double h = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::abs(v[i] - (v.front() + h * static_cast<double>(i))) > 1e-9 * std::max(std::abs(h), std::abs(v[i])))
      SSIMARCH_CONTRACT_FAILURE(std::string("porosity map: the ") + what + " values are not evenly spaced");
  return h;
}

}  // namespace

VtkPolyData radial_profile_poly_data(const PorosityProfile& profile, const Container& container) {
  const double z = (container.slab.z_min + container.slab.z_max) / 2;
  std::vector<Vec3> pts;
  for (double r : profile.x) pts.emplace_back(r, 0.0, z);
  return polyline(std::move(pts), {VtkArray::real("r", profile.x), VtkArray::real("porosity", profile.porosity)});
}

VtkPolyData bin_profile_poly_data(const PorosityProfile& profile, const Container& container) {
  const double z = (container.slab.z_min + container.slab.z_max) / 2;
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < profile.x.size(); ++i) pts.emplace_back((profile.x[i] + profile.x_upper[i]) / 2, 0.0, z);
  return polyline(std::move(pts), {VtkArray::real("r_inner", profile.x), VtkArray::real("r_outer", profile.x_upper),
                                   VtkArray::real("porosity", profile.porosity)});
}

VtkPolyData axial_profile_poly_data(const PorosityProfile& profile) {
  std::vector<Vec3> pts;
  for (double z : profile.x) pts.emplace_back(0.0, 0.0, z);
  return polyline(std::move(pts), {VtkArray::real("z", profile.x), VtkArray::real("porosity", profile.porosity)});
}

VtkImageData porosity_map_image_data(const PorosityMap& map) {
  SSIMARCH_EXPECTS(!map.r.empty() && !map.z.empty() && map.porosity.size() == map.r.size() * map.z.size(),
                   "porosity map: " + std::to_string(map.porosity.size()) + " values for " +
                       std::to_string(map.r.size()) + " x " + std::to_string(map.z.size()) + " cells");
  VtkImageData d;
  d.dims = {static_cast<int>(map.r.size()), 1, static_cast<int>(map.z.size())};
  d.origin = Vec3(map.r.front(), 0.0, map.z.front());
  d.spacing = Vec3(even_spacing(map.r, "radius"), 1.0, even_spacing(map.z, "height"));
  d.point_data = {VtkArray::real("porosity", map.porosity)};  // i + NR k: the map's own row-major order
  return d;
}

}  // namespace ssimarch
