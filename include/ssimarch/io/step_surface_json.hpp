// Scene surfaces taken from STEP files (docs/scene-format.md, "Surfaces from STEP files"):
//   {"step": "part.step", "face": 3}      the third face of the file (`ssimarch faces part.step`)
//   {"step": "part.step", "entity": 57}   instance #57: a face, or a surface
//   "unit": "mm"                          (either form) the model converted to a length unit
// A relative path is relative to the scene file's folder. Each file is parsed once per scene
// and unit.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/step/reader.hpp"

namespace ssimarch {

/// The STEP files a scene has read, by resolved path and the unit they were converted to.
class StepFileCache {
 public:
  const StepModel& get(const std::filesystem::path& path, const InputLimits& limits,
                       const std::optional<StepLengthUnit>& unit = std::nullopt);

 private:
  std::map<std::pair<std::filesystem::path, std::string>, std::shared_ptr<const StepModel>> models_;
};

/// True when a surface's JSON is the STEP form (has the key "step").
bool is_step_surface(const nlohmann::json& spec);

/// The surface a STEP form names, in *region (when given) the face's region inside its
/// trimming loops (null for a surface instance), and in *spline (when given) a spline
/// surface's control data. Throws InputError naming `where` + ".step" /
/// ".face" / ".entity" for a bad key, and the file:line: #id of the STEP instance at fault.
Surface step_surface_from_json(const nlohmann::json& spec, const std::filesystem::path& base_dir, StepFileCache* cache,
                               const InputLimits& limits, const std::string& where,
                               std::shared_ptr<const FaceRegion>* region = nullptr,
                               std::optional<SplineSurfaceData>* spline = nullptr);

/// The faces of a STEP model to intersect, from a command-line list: "3,7,12" (numbers as
/// `ssimarch faces` lists them, each at most once, at least min_count), "part:NAME" (every face
/// whose instance path in the assembly contains NAME, e.g. part:rod for rod_1 and sub_1/rod_2) or
/// "all". Throws InputError(where, ...) for anything else, a face the model does not have or a
/// part no face is placed as.
std::vector<int> step_face_list(const std::string& text, const StepModel& model, const std::string& where,
                                std::size_t min_count = 2);

/// A scene's surface for face `face` of `model` read from `step`: {"step": path, "face": i}, with
/// "unit" when the model was read converted, so that the scene reads it the same way.
nlohmann::json step_face_json(const std::filesystem::path& step, int face, const StepModel& model);

/// A scene of faces of a STEP model (step_face_json named "face<i>", trimmed to their loops) with
/// one intersection per pair of them, named "face<i>-face<j>", i < j in the list's order, default
/// options (io/scene.hpp parses it).
nlohmann::json step_faces_scene_json(const std::filesystem::path& step, const StepModel& model,
                                     const std::vector<int>& faces);

}  // namespace ssimarch
