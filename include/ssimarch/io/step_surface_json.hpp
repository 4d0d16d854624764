// Scene surfaces taken from STEP files (docs/scene-format.md, "Surfaces from STEP files"):
//   {"step": "part.step", "face": 3}      the third face of the file (`ssimarch faces part.step`)
//   {"step": "part.step", "entity": 57}   instance #57: a face, or a surface
// A relative path is relative to the scene file's folder. Each file is parsed once per scene.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/io/step_reader.hpp"

namespace ssimarch {

/// The STEP files a scene has read, by resolved path.
class StepFileCache {
 public:
  const StepModel& get(const std::filesystem::path& path, const InputLimits& limits);

 private:
  std::map<std::filesystem::path, std::shared_ptr<const StepModel>> models_;
};

/// True when a surface's JSON is the STEP form (has the key "step").
bool is_step_surface(const nlohmann::json& spec);

/// The surface a STEP form names. Throws InputError naming `where` + ".step" / ".face" /
/// ".entity" for a bad key, and the file:line: #id of the STEP instance at fault.
Surface step_surface_from_json(const nlohmann::json& spec, const std::filesystem::path& base_dir, StepFileCache* cache,
                               const InputLimits& limits, const std::string& where);

}  // namespace ssimarch
