#include "ssimarch/io/step_surface_json.hpp"

#include <cmath>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/json_reader.hpp"
#include "text_cat.hpp"

namespace ssimarch {

const StepModel& StepFileCache::get(const std::filesystem::path& path, const InputLimits& limits) {
  auto& slot = models_[path];
  if (!slot) slot = std::make_shared<const StepModel>(StepModel::read(path, limits));
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
                               const InputLimits& limits, const std::string& where) {
  JsonObject f(spec, where, {"step"}, {"face", "entity"});
  if (f.has("face") == f.has("entity"))
    throw InputError(where, "a STEP surface names exactly one of \"face\" (its number in `ssimarch faces FILE`) and "
                            "\"entity\" (an instance id #n)");
  const std::filesystem::path file = json_string(f.at("step"), f.path("step"), "a STEP file path");
  const std::filesystem::path resolved = file.is_absolute() || base_dir.empty() ? file : base_dir / file;
  const StepModel& model = cache->get(resolved, limits);
  if (f.has("face")) {
    const std::int64_t k = positive_integer(f.at("face"), f.path("face"));
    return model.surface(model.face(static_cast<int>(std::min<std::int64_t>(k, 1 << 30)), f.path("face")).entity);
  }
  const std::int64_t id = positive_integer(f.at("entity"), f.path("entity"));
  if (!model.file().find(id)) throw InputError(f.path("entity"), internal::cat(model.file().source, " has no instance #", id));
  return model.surface(id);
}

}  // namespace ssimarch
