#include "ssimarch/io/scene.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/surface/surface_json.hpp"

namespace ssimarch {

using nlohmann::json;

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string type_of(const json& j) { return j.type_name(); }

// Line and column (1-based) of a byte offset.
std::pair<int, int> line_column(const std::string& text, std::size_t offset) {
  int line = 1, col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

void check_keys(const json& obj, const std::vector<std::string>& allowed, const std::string& where) {
  for (const auto& [k, v] : obj.items()) {
    (void)v;
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
      throw InputError(where, "unknown key \"" + k + "\" (known keys: " + join(allowed) + ")");
  }
}

expr::Constants resolve_constants(const json& j, const std::string& where) {
  expr::Constants c;
  if (j.is_null()) return c;
  if (!j.is_object()) throw InputError(where, "must be an object of name: value pairs, not " + type_of(j));
  // Constants may refer to each other in any order: evaluate in passes until none is left.
  std::map<std::string, json> pending;
  for (const auto& [k, v] : j.items()) {
    if (k.empty() || !(std::isalpha(static_cast<unsigned char>(k[0])) || k[0] == '_'))
      throw InputError(where + "." + k, "a constant's name must start with a letter or '_'");
    for (char ch : k)
      if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'))
        throw InputError(where + "." + k, "a constant's name may contain only letters, digits and '_'");
    pending[k] = v;
  }
  while (!pending.empty()) {
    bool progress = false;
    for (auto it = pending.begin(); it != pending.end();) {
      try {
        c[it->first] = number_from_json(it->second, c, where + "." + it->first);
        it = pending.erase(it);
        progress = true;
      } catch (const InputError&) {
        ++it;
      }
    }
    if (!progress) {
      // Report the first one with its own message (unknown name or cycle).
      auto it = pending.begin();
      expr::Constants others = c;
      number_from_json(it->second, others, where + "." + it->first);  // throws
      throw InputError(where + "." + it->first, "cannot be evaluated");
    }
  }
  return c;
}

Vec3 vec3_from_json(const json& j, const expr::Constants& c, const std::string& where) {
  if (!j.is_array() || j.size() != 3)
    throw InputError(where, "must be a list of 3 numbers [x, y, z], got " + (j.is_array() ? std::to_string(j.size()) + " components" : type_of(j)));
  return {number_from_json(j[0], c, where + "[0]"), number_from_json(j[1], c, where + "[1]"),
          number_from_json(j[2], c, where + "[2]")};
}

}  // namespace

double number_from_json(const json& j, const expr::Constants& constants, const std::string& where) {
  double v;
  if (j.is_number()) {
    v = j.get<double>();
  } else if (j.is_string()) {
    v = expr::evaluate_constant(j.get<std::string>(), constants, where);
  } else {
    throw InputError(where, "must be a number or an expression string, not " + type_of(j));
  }
  if (!std::isfinite(v)) throw InputError(where, "must be finite");
  return v;
}

const std::vector<std::string>& trace_option_keys() {
  static const std::vector<std::string> keys = {
      "predictor", "corrector", "step", "step_length", "min_step_length", "min_step", "deviation", "turn_angle",
      "taylor_order", "tolerance",
      "max_corrector_iterations", "max_turn_angle", "max_correction_ratio", "max_points", "max_length",
      "start_samples", "certified_start_points", "start_box_budget", "geometry"};
  return keys;
}

void apply_trace_options(const json& options, const expr::Constants& c, const std::string& where, TraceOptions* o,
                         json* extra) {
  if (options.is_null()) return;
  if (!options.is_object()) throw InputError(where, "must be an object, not " + type_of(options));
  auto str = [&](const std::string& key, const json& v) {
    if (!v.is_string()) throw InputError(where + "." + key, "must be a string, not " + type_of(v));
    return v.get<std::string>();
  };
  auto integer = [&](const std::string& key, const json& v) {
    double d = number_from_json(v, c, where + "." + key);
    if (d != std::floor(d) || std::fabs(d) > 1e15) throw InputError(where + "." + key, "must be an integer");
    return static_cast<long>(d);
  };
  for (const auto& [key, v] : options.items()) {
    const std::string w = where + "." + key;
    if (key == "predictor") {
      if (!parse(str(key, v), &o->predictor)) throw InputError(w, "unknown predictor \"" + v.get<std::string>() + "\"");
    } else if (key == "corrector") {
      if (!parse(str(key, v), &o->corrector)) throw InputError(w, "unknown corrector \"" + v.get<std::string>() + "\"");
    } else if (key == "step") {
      if (!parse(str(key, v), &o->step)) throw InputError(w, "unknown step rule \"" + v.get<std::string>() + "\"");
    } else if (key == "step_length") {
      o->step_length = number_from_json(v, c, w);
    } else if (key == "min_step") {
      o->min_step = number_from_json(v, c, w);
    } else if (key == "min_step_length") {
      o->min_step_length = number_from_json(v, c, w);
    } else if (key == "deviation") {
      o->deviation = number_from_json(v, c, w);
    } else if (key == "turn_angle") {
      o->turn_angle = number_from_json(v, c, w);
    } else if (key == "taylor_order") {
      o->taylor_order = static_cast<int>(integer(key, v));
    } else if (key == "tolerance") {
      o->tolerance = number_from_json(v, c, w);
    } else if (key == "max_corrector_iterations") {
      o->max_corrector_iterations = static_cast<int>(integer(key, v));
    } else if (key == "max_turn_angle") {
      o->max_turn_angle = number_from_json(v, c, w);
    } else if (key == "max_correction_ratio") {
      o->max_correction_ratio = number_from_json(v, c, w);
    } else if (key == "max_points") {
      o->max_points = integer(key, v);
    } else if (key == "max_length") {
      o->max_length = number_from_json(v, c, w);
    } else if (key == "start_samples") {
      o->start_samples = static_cast<int>(integer(key, v));
    } else if (key == "certified_start_points") {
      if (!v.is_boolean()) throw InputError(w, "must be true or false, not " + type_of(v));
      o->certified_start_points = v.get<bool>();
    } else if (key == "start_box_budget") {
      o->start_box_budget = integer(key, v);
    } else if (key == "geometry") {
      (*extra)[key] = str(key, v);
    } else {
      throw InputError(w, "unknown option (known options: " + join(trace_option_keys()) + ")");
    }
  }
  std::string error;
  if (!o->is_valid(&error)) throw InputError(where, error);
}

PairKind choose_pair_kind(const Surface& a, const Surface& b, const std::optional<std::array<std::string, 2>>& as,
                          const std::string& where, bool* swapped) {
  *swapped = false;
  if (as) {
    const Surface* s[2] = {&a, &b};
    for (int i = 0; i < 2; ++i) {
      const std::string& form = (*as)[static_cast<std::size_t>(i)];
      std::string w = where + ".as[" + std::to_string(i) + "]";
      if (form == "parametric") {
        if (!s[i]->is_parametric()) throw InputError(w, "this " + std::string(s[i]->type_name()) + " surface has no parametric form");
      } else if (form == "implicit") {
        if (!s[i]->is_implicit()) throw InputError(w, "this " + std::string(s[i]->type_name()) + " surface has no implicit form");
      } else {
        throw InputError(w, "must be \"parametric\" or \"implicit\", not \"" + form + "\"");
      }
    }
    if ((*as)[0] == (*as)[1]) return (*as)[0] == "parametric" ? PairKind::kParametricParametric : PairKind::kImplicitImplicit;
    *swapped = (*as)[0] == "implicit";
    return PairKind::kParametricImplicit;
  }
  if (a.is_implicit() && b.is_implicit()) return PairKind::kImplicitImplicit;
  if (b.is_implicit() && a.is_parametric()) return PairKind::kParametricImplicit;
  if (a.is_implicit() && b.is_parametric()) {
    *swapped = true;
    return PairKind::kParametricImplicit;
  }
  if (a.is_parametric() && b.is_parametric()) return PairKind::kParametricParametric;
  throw InputError(where, "these two surfaces cannot be intersected: one is implicit only and the other has no form to pair with it");
}

const Surface& Scene::surface(const std::string& name) const {
  auto it = surfaces.find(name);
  if (it == surfaces.end())
    throw InputError(source, "unknown surface \"" + name + "\" (the scene defines: " + join(surface_names) + ")");
  return it->second;
}

Problem Scene::problem(const IntersectionSpec& spec) const {
  const Surface& a = surface(spec.surfaces[0]);
  const Surface& b = surface(spec.surfaces[1]);
  return spec.swapped ? Problem(b, a, spec.kind) : Problem(a, b, spec.kind);
}

Scene parse_scene(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    auto [line, col] = line_column(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string msg = e.what();
    auto pos = msg.find("syntax error");
    throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(col),
                     "invalid JSON: " + (pos != std::string::npos ? msg.substr(pos) : msg));
  }
  Scene scene;
  scene.source = source;
  if (!root.is_object()) throw InputError(source, "a scene must be a JSON object with \"surfaces\" and \"intersections\"");
  check_keys(root, {"constants", "surfaces", "intersections", "description"}, source);
  scene.constants = resolve_constants(root.value("constants", json()), source + ": constants");

  const json& surfaces = root.contains("surfaces") ? root["surfaces"] : json();
  if (!surfaces.is_object() || surfaces.empty())
    throw InputError(source + ": surfaces", "must be a non-empty object of name: surface pairs");
  for (const auto& [name, spec] : surfaces.items()) {
    scene.surface_names.push_back(name);
    scene.surfaces.emplace(name, surface_from_json(spec, scene.constants, source + ": surfaces." + name));
  }

  const json& list = root.contains("intersections") ? root["intersections"] : json::array();
  if (!list.is_array()) throw InputError(source + ": intersections", "must be a list, not " + type_of(list));
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& e = list[i];
    std::string where = source + ": intersections[" + std::to_string(i) + "]";
    if (!e.is_object()) throw InputError(where, "must be an object");
    check_keys(e, {"name", "surfaces", "start", "as", "options", "description"}, where);
    IntersectionSpec spec;
    spec.name = e.contains("name") ? e["name"].get<std::string>() : "intersection" + std::to_string(i + 1);
    if (!names.insert(spec.name).second) throw InputError(where + ".name", "duplicate intersection name \"" + spec.name + "\"");
    if (!e.contains("surfaces") || !e["surfaces"].is_array() || e["surfaces"].size() != 2)
      throw InputError(where + ".surfaces", "must be a list of the names of 2 surfaces");
    for (int k = 0; k < 2; ++k) {
      const json& n = e["surfaces"][static_cast<std::size_t>(k)];
      if (!n.is_string()) throw InputError(where + ".surfaces[" + std::to_string(k) + "]", "must be a surface name");
      spec.surfaces[static_cast<std::size_t>(k)] = n.get<std::string>();
      if (!scene.surfaces.count(n.get<std::string>()))
        throw InputError(where + ".surfaces[" + std::to_string(k) + "]",
                         "unknown surface \"" + n.get<std::string>() + "\" (the scene defines: " + join(scene.surface_names) + ")");
    }
    std::optional<std::array<std::string, 2>> as;
    if (e.contains("as")) {
      const json& a = e["as"];
      if (!a.is_array() || a.size() != 2 || !a[0].is_string() || !a[1].is_string())
        throw InputError(where + ".as", "must be a list of 2 strings, each \"parametric\" or \"implicit\"");
      as = std::array<std::string, 2>{a[0].get<std::string>(), a[1].get<std::string>()};
    }
    spec.kind = choose_pair_kind(scene.surfaces.at(spec.surfaces[0]), scene.surfaces.at(spec.surfaces[1]), as, where, &spec.swapped);
    if (e.contains("start")) {
      const json& s = e["start"];
      if (s.is_array() && !s.empty() && s[0].is_array()) {
        for (std::size_t k = 0; k < s.size(); ++k)
          spec.starts.push_back(vec3_from_json(s[k], scene.constants, where + ".start[" + std::to_string(k) + "]"));
      } else {
        spec.starts.push_back(vec3_from_json(s, scene.constants, where + ".start"));
      }
    }
    apply_trace_options(e.value("options", json()), scene.constants, where + ".options", &spec.options, &spec.extra_options);
    scene.intersections.push_back(std::move(spec));
  }
  return scene;
}

Scene load_scene(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string(), "no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string(), "is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot be opened for reading");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(path.string(), "the file is empty");
  return parse_scene(text, path.string());
}

}  // namespace ssimarch
