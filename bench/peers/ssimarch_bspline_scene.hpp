// The peer case as ssimarch receives it in B-spline form (issue 27 item 4): the case's scene with
// both surfaces replaced by OpenCASCADE's GeomConvert B-splines of them, pole for pole, weight
// for weight and knot for knot (the surfaces "OCCT B-spline" and SISL get), traced as given and
// with the surfaces swapped.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "occt_surfaces.hpp"

namespace peers {

/// The scene of `scene_path` (one intersection) with its surfaces replaced by `bspline`'s, in a
/// clamped (non-periodic) form, and two intersections: "<name>" and "<name>_swapped", with the
/// case's options, as scene JSON (`peer_bench --write-bspline-scenes DIR` writes it, for
/// `ssimarch trace`).
nlohmann::json ssimarch_bspline_scene_json(const std::string& scene_path, const OcctPair& bspline);

}  // namespace peers
