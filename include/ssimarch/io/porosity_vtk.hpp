// Porosity profiles and maps for ParaView (VTK XML, io/vtk_xml.hpp; docs/output-format.md
// "ParaView / VTK"), in the bed's frame: the container's axis is the z axis.
#pragma once

#include "ssimarch/io/vtk_xml.hpp"
#include "ssimarch/porosity/profile.hpp"

namespace ssimarch {

/// eps(r): one polyline through (r, 0, z_mid) (z_mid: the middle of the height range it averages
/// over); point data "r", "porosity".
VtkPolyData radial_profile_poly_data(const PorosityProfile& profile, const Container& container);

/// Annular bins: one polyline through the bin centres ((r_inner + r_outer) / 2, 0, z_mid); point
/// data "r_inner", "r_outer", "porosity".
VtkPolyData bin_profile_poly_data(const PorosityProfile& profile, const Container& container);

/// eps(z): one polyline through (0, 0, z) on the axis; point data "z", "porosity".
VtkPolyData axial_profile_poly_data(const PorosityProfile& profile);

/// eps(r, z) as image data in the plane y = 0: point (i, 0, k) at (r_i, 0, z_k), NR x 1 x NZ
/// points, point data "porosity". Throws std::invalid_argument when r or z is not evenly spaced
/// (the job's cell centres are).
VtkImageData porosity_map_image_data(const PorosityMap& map);

}  // namespace ssimarch
