// Self-contained HTML pages of the 3D viewer (docs/viewer.md): the viewer's bundled script (built
// from viewer/ at build time, passed in by the caller) and the page's data as JSON, both inline, so
// the page opens offline. The data of a trace page is the result JSON of `ssimarch trace` plus
// display meshes of the surfaces; of a porosity page the particles, the profiles and a correlation.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "ssimarch/geometry/surface_mesh.hpp"
#include "ssimarch/pipeline/porosity_job.hpp"
#include "ssimarch/pipeline/scene.hpp"
#include "ssimarch/porosity/particle.hpp"

namespace ssimarch {

/// {"kind": "trace", "title", "intersections": result["intersections"], "surfaces": {NAME: {"type",
/// "form": "parametric" | "implicit", "positions": [x, y, z, ...], "triangles": [i, j, k, ...],
/// parametric: "domain": {"u": [lo, hi], "v": [lo, hi]}}}, "starts": {INTERSECTION: [[x, y, z], ...]}}:
/// the display mesh (geometry/surface_mesh) of every surface the intersections name, and the start
/// points the scene gives (neither without a scene). `result` is the JSON of docs/output-format.md; throws InputError
/// when it has no "intersections" array or names a surface the scene lacks.
nlohmann::json trace_page_data(const nlohmann::json& result, const Scene* scene, const std::string& title,
                               const SurfaceMeshOptions& mesh = {});

/// {"kind": "porosity", "title", "container": {"radius", "z_range"}, "spherocylinders", "bulk_porosity",
/// "particles": {"count", "centre": [x, y, z, ...], "diameter": [...], and for spherocylinders "axis",
/// "length"}, "radial" / "bins" / "axial": {"x", ["x_upper"], "porosity"}, "map": {"r", "z",
/// "porosity"}, "correlation": {"label", "x", "porosity"}}. The correlation (spheres only) is de
/// Klerk (2003) at the radial profile's radii with eps_b the mean exact porosity more than 2.5 mean
/// diameters from the wall, as in the porosity demo.
nlohmann::json porosity_page_data(const PorosityJobResult& result, std::span<const Particle> particles,
                                  const std::string& title);

/// Writes the page. `script` is the viewer bundle; throws std::logic_error when it is empty or
/// holds "</script" (it could not be inlined). "</" in the data is written "<\/" (the same JSON).
void write_viewer_page(std::ostream& out, const nlohmann::json& data, std::string_view script);

}  // namespace ssimarch
