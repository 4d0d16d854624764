#include "ssimarch/io/step_surface_json.hpp"

#include <algorithm>
#include <cmath>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/json_reader.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch {

const StepModel& StepFileCache::get(const std::filesystem::path& path, const InputLimits& limits,
                                    const std::optional<StepLengthUnit>& unit) {
  auto& slot = models_[{path, unit ? unit->name : std::string()}];
  if (!slot) slot = std::make_shared<const StepModel>(StepModel::read(path, limits, unit));
  return *slot;
}

bool is_step_surface(const nlohmann::json& spec) { return spec.is_object() && spec.contains("step"); }

namespace {

std::int64_t positive_integer(const nlohmann::json& j, const std::string& where) {
  if (!j.is_number() || !(j.get<double>() >= 1) || j.get<double>() != std::floor(j.get<double>()) ||
      j.get<double>() >= 9007199254740992.0)
    throw InputError(where, "must be an integer >= 1, got " + j.dump());
  return static_cast<std::int64_t>(j.get<double>());
}

}  // namespace

Surface step_surface_from_json(const nlohmann::json& spec, const std::filesystem::path& base_dir, StepFileCache* cache,
                               const InputLimits& limits, const std::string& where,
                               std::shared_ptr<const FaceRegion>* region, std::optional<SplineSurfaceData>* spline) {
  JsonObject f(spec, where, {"step"}, {"face", "entity", "unit"});
  if (f.has("face") == f.has("entity"))
    throw InputError(where, "a STEP surface names exactly one of \"face\" (its number in `ssimarch faces FILE`) and "
                            "\"entity\" (an instance id #n)");
  const std::filesystem::path file = json_string(f.at("step"), f.path("step"), "a STEP file path");
  const std::filesystem::path resolved = file.is_absolute() || base_dir.empty() ? file : base_dir / file;
  std::optional<StepLengthUnit> unit;
  if (f.has("unit"))
    unit = named_length_unit(json_string(f.at("unit"), f.path("unit"), "a length unit"), f.path("unit"));
  const StepModel& model = cache->get(resolved, limits, unit);
  std::int64_t id = 0;
  PartPlacement placement;  // a face of a placed part sits where the assembly puts it
  if (f.has("face")) {
    const std::int64_t k = positive_integer(f.at("face"), f.path("face"));
    const StepFace& face = model.face(static_cast<int>(std::min<std::int64_t>(k, 1 << 30)), f.path("face"));
    id = face.entity;
    placement = face.placement;
  } else {
    id = positive_integer(f.at("entity"), f.path("entity"));
    if (!model.file().find(id)) throw InputError(f.path("entity"), internal::cat(model.file().source, " has no instance #", id));
  }
  Surface surface = model.surface(id, placement);
  if (region) *region = model.face_region(id, placement);
  if (spline) *spline = model.spline_data(id, placement);
  return surface;
}

std::vector<int> step_face_list(const std::string& text, const StepModel& model, const std::string& where,
                                std::size_t min_count) {
  const int n = static_cast<int>(model.faces().size());
  std::vector<int> out;
  if (text == "all") {
    for (int i = 1; i <= n; ++i) out.push_back(i);
  } else if (text.rfind("part:", 0) == 0) {
    const std::string name = text.substr(5);
    if (name.empty()) throw InputError(where, "part: needs a name (part:NAME, a part of the faces' instance paths)");
    for (const StepFace& f : model.faces())
      if (f.instance.find(name) != std::string::npos) out.push_back(f.index);
    if (out.empty())
      throw InputError(where, "no face of " + model.file().source + " is placed as a part whose path contains \"" +
                                  name + "\" (`ssimarch faces` lists the paths)");
  } else {
    std::size_t at = 0;
    while (at <= text.size()) {
      const std::size_t comma = std::min(text.find(',', at), text.size());
      const std::string item = text.substr(at, comma - at);
      const bool digits = !item.empty() && item.size() <= 9 && item.find_first_not_of("0123456789") == std::string::npos;
      if (!digits)
        throw InputError(
            where, "expected face numbers separated by commas (e.g. 3,7), part:NAME or all, got \"" + text + "\"");
      const int k = std::stoi(item);
      model.face(k, where);  // throws naming how many faces there are
      if (std::find(out.begin(), out.end(), k) != out.end())
        throw InputError(where, "face " + item + " is listed twice");
      out.push_back(k);
      at = comma + 1;
    }
  }
  if (out.size() < min_count)
    throw InputError(where, "needs at least " + std::to_string(min_count) + " face" + (min_count == 1 ? "" : "s") +
                                " (" + model.file().source + " has " + std::to_string(n) + ")");
  return out;
}

nlohmann::json step_face_json(const std::filesystem::path& step, int face, const StepModel& model) {
  nlohmann::json j{{"step", step.string()}, {"face", face}};
  if (model.converted_to()) j["unit"] = model.converted_to()->name;
  return j;
}

nlohmann::json step_faces_scene_json(const std::filesystem::path& step, const StepModel& model,
                                     const std::vector<int>& faces) {
  nlohmann::json surfaces = nlohmann::json::object(), pairs = nlohmann::json::array();
  auto name = [](int k) { return "face" + std::to_string(k); };
  for (int k : faces) surfaces[name(k)] = step_face_json(step, k, model);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j)
      pairs.push_back({{"name", name(faces[i]) + "-" + name(faces[j])}, {"surfaces", {name(faces[i]), name(faces[j])}}});
  return {{"surfaces", surfaces}, {"intersections", pairs}};
}

}  // namespace ssimarch
