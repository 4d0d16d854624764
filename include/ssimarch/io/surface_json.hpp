// Surfaces from scene-file JSON (schema: docs/scene-format.md, section "Surfaces").
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/pipeline/spline_surface_data.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Builds a surface from its JSON description, e.g. {"sphere": {"center": [0,0,0], "radius": "R"}}
/// or {"parametric": ["cos(u)", "sin(u)", "v"], "u": [0, "2*pi"], "v": [-1, 1], "periodic": ["u"]}.
/// Every number may be a JSON number or an expression string evaluated with `constants`.
/// Throws InputError whose where() is the JSON path of the offending value, starting with
/// `where` (e.g. "surfaces.cyl" -> "surfaces.cyl.cylinder.radius").
Surface surface_from_json(const nlohmann::json& spec, const Constants& constants, const std::string& where);

/// The control data of a "bspline" / "nurbs" / "bezier" surface (one surface_from_json has
/// accepted), empty for other types.
std::optional<SplineSurfaceData> spline_data_from_json(const nlohmann::json& spec, const Constants& constants,
                                                       const std::string& where);

/// The type keys surface_from_json understands (aliases included), for messages and docs.
const std::vector<std::string>& surface_type_names();

}  // namespace ssimarch
