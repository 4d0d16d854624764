// Triangle meshes of surfaces for display (the HTML viewer, docs/viewer.md): a parametric form on a
// regular grid over its domain, an implicit form by marching tetrahedra in a box. Display
// accuracy only: the intersection curves never use these meshes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/surface/domain.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// An indexed triangle mesh; triangles are wound so that their normal points to increasing f for
/// an implicit form, along F_u x F_v for a parametric one.
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Sum of the triangles' areas (model units squared).
  double area() const;
};

/// Resolution of a display mesh.
struct SurfaceMeshOptions {
  int grid = 64;   ///< parametric: grid cells along each parameter direction (>= 1)
  int cells = 48;  ///< implicit: cells along the longest side of the box (>= 2)
};

/// F(u, v) at (grid+1)^2 points evenly over the domain, two triangles per cell. Non-finite points
/// (a pole of the parametrisation evaluating to NaN) drop their triangles.
TriangleMesh mesh_parametric(const Surface& s, int grid_u, int grid_v);

/// The zero set of f in `box` by marching tetrahedra (each cube of a regular grid split into six
/// tetrahedra around its main diagonal, Freudenthal/Kuhn; so neighbouring cubes share faces and the
/// mesh has no cracks). Each vertex lies on a grid edge with a sign change of f and is put on the
/// surface by regula falsi (Illinois) along that edge, to |f| <= 1e-12 |f|_edge or 60 steps. Grid
/// vertices where f = 0 count as outside (f >= 0). The cubes are as close to cubic as the box allows,
/// `cells` along its longest side.
TriangleMesh mesh_implicit(const Surface& s, const Box& box, int cells);

/// The display mesh of a surface: mesh_parametric when it has a parametric form, else
/// mesh_implicit in s.box(). Throws InputError for a non-positive resolution.
TriangleMesh surface_mesh(const Surface& s, const SurfaceMeshOptions& options = {});

}  // namespace ssimarch
