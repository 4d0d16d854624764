// The singular points of a trace as JSON (docs/output-format.md: "singular_points",
// "isolated_points"; issue 10 "Output").
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "ssimarch/singular/analysis.hpp"
#include "ssimarch/trace/result.hpp"

namespace ssimarch {

/// [{"xyz", "params", "type", "ak", "multiplicity", "milnor", "half_branches": [{"tangent",
/// "param_tangent", "expansion": {"coefficient", "exponent"}, "continuation"}], "curves"}]:
/// expansion is the leading term w = coefficient X^exponent of the half-branch's offset from its
/// tangent line at distance X (model units).
nlohmann::json singular_points_to_json(const std::vector<SingularPointReport>& points);

/// One analysed singular point as `ssimarch singular --json` writes it (docs/singular.md):
/// {"xyz", "params", "type", "ak", "multiplicity", "milnor", "tangent_cone": [{"direction",
/// "multiplicity"}], "gap", "sine", "half_branches": [{"tangent", "param_tangent", "expansion":
/// {"coefficient", "exponent", "normal", "terms"}, "branch", "continuation", "exit"}]}; "milnor" is
/// null where infinite or beyond the local jet, "exit" null where no exit point was found.
nlohmann::json singular_analysis_to_json(const SingularAnalysis& point);

}  // namespace ssimarch
