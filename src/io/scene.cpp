#include "ssimarch/io/scene.hpp"

#include <cctype>
#include <set>

#include "ssimarch/core/error.hpp"
#include "ssimarch/expr/referenced_names.hpp"
#include "ssimarch/io/json_reader.hpp"
#include "ssimarch/io/step_surface_json.hpp"
#include "ssimarch/io/surface_json.hpp"

namespace ssimarch {

using nlohmann::json;

namespace {

void check_name(const std::string& name, const std::string& where) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    throw InputError(where, "a constant's name must start with a letter or '_'");
  for (char ch : name)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'))
      throw InputError(where, "a constant's name may contain only letters, digits and '_'");
}

// The constants a constant's value mentions (a JSON number mentions none).
std::vector<std::string> constant_dependencies(const json& value, const json& all) {
  std::vector<std::string> deps;
  if (!value.is_string()) return deps;
  for (std::string& name : referenced_names(value.get<std::string>()))
    if (all.contains(name)) deps.push_back(std::move(name));
  return deps;
}

// Constants may refer to each other in any order. They are evaluated in dependency order found by
// one depth-first search (Tarjan's topological sort; each constant is compiled once, so the work
// is linear in the size of the constants, where trial passes were cubic for a chain). The search
// keeps its own stack: a chain of 100000 constants must not overflow the call stack.
Constants resolve_constants(const json& j, const std::string& where) {
  Constants c;
  if (j.is_null()) return c;
  if (!j.is_object()) throw InputError(where, "must be an object of name: value pairs, got " + json_kind(j));
  for (const auto& [k, v] : j.items()) check_name(k, key_path(where, k));
  enum class Mark { kNew, kOpen, kDone };
  std::map<std::string, Mark, std::less<>> mark;
  for (const auto& [k, v] : j.items()) mark[k] = Mark::kNew;
  struct Frame {
    std::string name;
    std::vector<std::string> deps;
    std::size_t next = 0;
  };
  for (const auto& [root, unused] : j.items()) {
    if (mark[root] != Mark::kNew) continue;
    std::vector<Frame> stack{{root, constant_dependencies(j[root], j)}};
    mark[root] = Mark::kOpen;
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.next < f.deps.size()) {
        const std::string dep = f.deps[f.next++];
        if (mark[dep] == Mark::kDone) continue;
        if (mark[dep] == Mark::kOpen) {
          std::string cycle = dep;
          for (auto it = stack.rbegin(); it != stack.rend() && it->name != dep; ++it) cycle = it->name + " -> " + cycle;
          throw InputError(key_path(where, dep), "the constants refer to each other in a cycle: " + dep + " -> " + cycle);
        }
        mark[dep] = Mark::kOpen;
        stack.push_back({dep, constant_dependencies(j[dep], j)});
        continue;
      }
      c[f.name] = json_number(j[f.name], c, key_path(where, f.name));
      mark[f.name] = Mark::kDone;
      stack.pop_back();
    }
  }
  return c;
}

std::optional<std::array<SurfaceForm, 2>> surface_forms(const json& e, const std::string& where) {
  if (!e.contains("as")) return std::nullopt;
  const json& a = e["as"];
  if (!a.is_array() || a.size() != 2 || !a[0].is_string() || !a[1].is_string())
    throw InputError(where + ".as", "must be a list of 2 strings, each \"parametric\" or \"implicit\"");
  std::array<SurfaceForm, 2> forms{};
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string form = a[i].get<std::string>();
    if (form == "parametric") forms[i] = SurfaceForm::kParametric;
    else if (form == "implicit") forms[i] = SurfaceForm::kImplicit;
    else throw InputError(index_path(where + ".as", i), "must be \"parametric\" or \"implicit\", not \"" + form + "\"");
  }
  return forms;
}

std::vector<Vec3> start_points(const json& e, const Constants& c, const std::string& where) {
  std::vector<Vec3> starts;
  if (!e.contains("start")) return starts;
  const json& s = e["start"];
  if (s.is_array() && !s.empty() && s[0].is_array()) {
    for (std::size_t k = 0; k < s.size(); ++k) starts.push_back(json_vec3(s[k], c, index_path(where + ".start", k)));
  } else {
    starts.push_back(json_vec3(s, c, where + ".start"));
  }
  return starts;
}

std::array<std::string, 2> surface_pair(const json& e, const Scene& scene, const std::string& where) {
  const std::string w = where + ".surfaces";
  if (!e.contains("surfaces") || !e["surfaces"].is_array() || e["surfaces"].size() != 2)
    throw InputError(w, "must be a list of the names of 2 surfaces");
  std::array<std::string, 2> names;
  for (std::size_t k = 0; k < 2; ++k) {
    names[k] = json_string(e["surfaces"][k], index_path(w, k), "a surface name");
    if (!scene.surfaces.count(names[k]))
      throw InputError(index_path(w, k), "unknown surface \"" + names[k] + "\" (the scene defines: " +
                                             join_names(scene.surface_names) + ")");
  }
  return names;
}

IntersectionSpec intersection(const json& e, const Scene& scene, std::size_t i, const std::string& where) {
  JsonObject fields(e, where, {}, {"name", "surfaces", "start", "as", "options", "description"});
  IntersectionSpec spec;
  spec.name = e.contains("name") ? json_string(e["name"], where + ".name", "a name") : "intersection" + std::to_string(i + 1);
  if (spec.name.empty()) throw InputError(where + ".name", "must not be empty");
  spec.surfaces = surface_pair(e, scene, where);
  spec.kind = choose_pair_kind(scene.surfaces.at(spec.surfaces[0]), scene.surfaces.at(spec.surfaces[1]),
                               surface_forms(e, where), where, &spec.swapped);
  spec.starts = start_points(e, scene.constants, where);
  if (e.contains("options")) read_trace_options(e["options"], scene.constants, where + ".options", &spec.options);
  return spec;
}

}  // namespace

void read_trace_options(const json& options, const Constants& c, const std::string& where, TraceJobOptions* out) {
  if (options.is_null()) return;
  if (!options.is_object()) throw InputError(where, "must be an object, got " + json_kind(options));
  for (const auto& [key, v] : options.items()) {
    const std::string w = key_path(where, key);
    const TraceOptionSpec* spec = find_trace_option(key);
    if (!spec) throw InputError(w, "unknown option (known options: " + trace_option_keys() + ")");
    if (v.is_number()) apply_trace_option(*spec, v.get<double>(), c, w, out);
    else if (v.is_string()) apply_trace_option(*spec, v.get<std::string>(), c, w, out);
    else if (v.is_boolean() && spec->choices == std::vector<std::string>{"true", "false"})
      apply_trace_option(*spec, std::string(v.get<bool>() ? "true" : "false"), c, w, out);
    else throw InputError(w, "must be " + spec->rule + ", got " + json_kind(v));
  }
  check_trace_options(*out, where);
}

Scene parse_scene(const std::string& text, const std::string& source, const std::filesystem::path& base_dir,
                  const InputLimits& limits) {
  const json root = parse_json_text(text, source);
  Scene scene;
  scene.source = source;
  if (!root.is_object()) throw InputError(source, "a scene must be a JSON object with \"surfaces\" and \"intersections\"");
  JsonObject fields(root, source + ":", {}, {"constants", "surfaces", "intersections", "description"});
  scene.constants = resolve_constants(root.value("constants", json()), source + ": constants");

  const json& surfaces = root.contains("surfaces") ? root["surfaces"] : json();
  if (!surfaces.is_object() || surfaces.empty())
    throw InputError(source + ": surfaces", "must be a non-empty object of name: surface pairs");
  StepFileCache step_files;
  for (const auto& [name, spec] : surfaces.items()) {
    if (name.empty()) throw InputError(source + ": surfaces", "a surface name must not be empty");
    scene.surface_names.push_back(name);
    const std::string where = source + ": surfaces." + name;
    std::optional<SplineSurfaceData> spline;
    if (is_step_surface(spec)) {
      std::shared_ptr<const FaceRegion> region;
      scene.surfaces.emplace(name, step_surface_from_json(spec, base_dir, &step_files, limits, where, &region, &spline));
      if (region) scene.regions.emplace(name, std::move(region));
    } else {
      scene.surfaces.emplace(name, surface_from_json(spec, scene.constants, where));
      spline = spline_data_from_json(spec, scene.constants, where);
    }
    if (spline) scene.spline_data.emplace(name, std::move(*spline));
  }

  const json& list = root.contains("intersections") ? root["intersections"] : json::array();
  if (!list.is_array()) throw InputError(source + ": intersections", "must be a list, got " + json_kind(list));
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = source + ": intersections[" + std::to_string(i) + "]";
    IntersectionSpec spec = intersection(list[i], scene, i, where);
    if (!names.insert(spec.name).second) throw InputError(where + ".name", "duplicate intersection name \"" + spec.name + "\"");
    scene.intersections.push_back(std::move(spec));
  }
  return scene;
}

Scene load_scene(const std::filesystem::path& path, const InputLimits& limits) {
  return parse_scene(read_text_file(path, "scene file", limits.max_scene_bytes), path.string(), path.parent_path(), limits);
}

}  // namespace ssimarch
