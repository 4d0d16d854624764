// Scene files: named constants, named surfaces and the intersections to trace (JSON; schema in
// docs/scene-format.md), read into the typed scene model of pipeline/scene.hpp. Errors are
// InputError with the file and the JSON path or line:column.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/pipeline/scene.hpp"

namespace ssimarch {

/// Reads and validates a scene file. Throws InputError (missing file, JSON syntax error with
/// line and column, duplicate or unknown keys, wrong types, bad values with their JSON path, a
/// file larger than limits.max_scene_bytes).
Scene load_scene(const std::filesystem::path& path, const InputLimits& limits = {});
/// Same, from text; `source` names it in messages. STEP files the scene names
/// ({"step": FILE, ...}, io/step_surface_json.hpp) are found relative to `base_dir` (the
/// current folder when empty) and read within `limits`.
Scene parse_scene(const std::string& text, const std::string& source, const std::filesystem::path& base_dir = {},
                  const InputLimits& limits = {});

/// Applies the keys of an "options" object (trace_option_table(); numbers may be expressions
/// using the constants) to *out, then checks the rules between options. Throws InputError
/// naming where + "." + key and the rule.
void read_trace_options(const nlohmann::json& options, const Constants& constants, const std::string& where,
                        TraceJobOptions* out);

}  // namespace ssimarch
