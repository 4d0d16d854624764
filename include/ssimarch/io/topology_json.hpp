// The curve network of an intersection as JSON (docs/output-format.md "topology"; issue 11
// item 3).
#pragma once

#include <nlohmann/json.hpp>

#include "ssimarch/network/curve_network.hpp"

namespace ssimarch {

/// {"complete", "vertices": [{"id", "kind", "type", "xyz", "params"}], "edges": [{"id", "vertices",
/// "curve", "point_range", "length"}], "branches": [{"curve", "edges", "closed", "length",
/// "rotation_index", "rotation_plane", "rotation_note"}], "components": [{"branches",
/// "vertices"}], "failures": [{"curve", "end", "reason", "message"}]}.
nlohmann::json curve_network_to_json(const CurveNetwork& network);

}  // namespace ssimarch
