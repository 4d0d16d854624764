#include "ssimarch/io/batch_file.hpp"

#include <algorithm>
#include <set>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/json_reader.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/io/trace_writers.hpp"

namespace ssimarch {

using nlohmann::json;

namespace {

struct BatchContext {
  std::filesystem::path folder;
  InputLimits limits;
};

std::shared_ptr<const Scene> job_scene(const json& scene, const std::string& where, const BatchContext& c) {
  if (scene.is_string()) {
    const std::filesystem::path p(scene.get<std::string>());
    return std::make_shared<const Scene>(load_scene(p.is_absolute() ? p : c.folder / p, c.limits));
  }
  if (scene.is_object()) return std::make_shared<const Scene>(parse_scene(scene.dump(), where));
  throw InputError(where, "must be a scene file name or a scene object, got " + json_kind(scene));
}

// The intersections of the entry: the scene's (all, or those listed), or every surface pair.
std::vector<IntersectionSpec> job_intersections(const JsonObject& o, const Scene& scene) {
  const std::string pairs = o.has("pairs") ? json_string(o.at("pairs"), o.path("pairs"), "\"scene\" or \"all\"") : "scene";
  if (pairs != "scene" && pairs != "all")
    throw InputError(o.path("pairs"), "must be \"scene\" (the scene's intersections) or \"all\" (every pair of its surfaces), got \"" +
                                          pairs + "\"");
  if (pairs == "all" && o.has("intersections"))
    throw InputError(o.path("intersections"), "lists intersections of the scene; \"pairs\": \"all\" traces every surface pair");
  std::vector<IntersectionSpec> specs;
  if (pairs == "all") {
    specs = all_surface_pairs(scene, TraceJobOptions{});
  } else if (o.has("intersections")) {
    const json& names = o.at("intersections");
    if (!names.is_array()) throw InputError(o.path("intersections"), "must be a list of intersection names, got " + json_kind(names));
    for (std::size_t i = 0; i < names.size(); ++i) {
      const std::string name = json_string(names[i], index_path(o.path("intersections"), i), "an intersection name");
      const IntersectionSpec* spec = scene.intersection(name);
      if (!spec)
        throw InputError(index_path(o.path("intersections"), i),
                         "the scene has no intersection \"" + name + "\" (it has: " + scene.intersection_names() + ")");
      specs.push_back(*spec);
    }
  } else {
    specs = scene.intersections;
  }
  // The entry's options over each intersection's own (as command-line flags are over a scene's).
  if (o.has("options"))
    for (IntersectionSpec& s : specs) read_trace_options(o.at("options"), scene.constants, o.path("options"), &s.options);
  return specs;
}

BatchJob read_job(const json& entry, const std::string& where, const BatchContext& c) {
  BatchJob job;
  job.source = entry.is_string() ? entry.get<std::string>() : where;
  try {
    if (entry.is_string()) {
      job.scene = job_scene(entry, where, c);
      job.intersections = job.scene->intersections;
    } else {
      JsonObject o(entry, where, {"scene"}, {"pairs", "intersections", "options", "description"});
      if (o.at("scene").is_string()) job.source = o.at("scene").get<std::string>();
      job.scene = job_scene(o.at("scene"), o.path("scene"), c);
      job.intersections = job_intersections(o, *job.scene);
    }
  } catch (const InputError& e) {
    job.scene.reset();
    job.intersections.clear();
    job.error = e.what();
  }
  return job;
}

}  // namespace

Batch parse_batch(const std::string& text, const std::string& source, const std::filesystem::path& folder,
                  const InputLimits& limits) {
  const json root = parse_json_text(text, source);
  JsonObject top(root, source + ":", {"jobs"}, {"description"});
  const json& list = top.at("jobs");
  if (!list.is_array()) throw InputError(top.path("jobs"), "must be a list of jobs, got " + json_kind(list));
  Batch batch;
  const BatchContext context{folder, limits};
  for (std::size_t i = 0; i < list.size(); ++i) batch.jobs.push_back(read_job(list[i], index_path(top.path("jobs"), i), context));
  batch.units = batch_units(batch.jobs);
  return batch;
}

Batch load_batch(const std::filesystem::path& path, const InputLimits& limits) {
  return parse_batch(read_text_file(path, "batch file", limits.max_scene_bytes), path.string(), path.parent_path(), limits);
}

json batch_unit_json(const Batch& batch, std::size_t unit, const BatchOutcome& outcome) {
  const BatchUnit& u = batch.units[unit];
  const IntersectionSpec& spec = batch.jobs[u.job].intersections[u.intersection];
  if (!outcome.run)
    return json{{"name", spec.name}, {"surfaces", json::array({spec.surfaces[0], spec.surfaces[1]})}, {"complete", false}, {"error", outcome.error}};
  json j = to_json(*outcome.run);
  j["complete"] = run_complete(*outcome.run);
  return j;
}

json batch_result_json(const Batch& batch, const std::vector<json>& units) {
  json jobs = json::array();
  std::size_t failed_jobs = 0, failed = 0, incomplete = 0, curves = 0, u = 0;
  for (const BatchJob& job : batch.jobs) {
    if (!job.error.empty()) {
      ++failed_jobs;
      jobs.push_back(json{{"source", job.source}, {"error", job.error}});
      continue;
    }
    json list = json::array();
    for (std::size_t i = 0; i < job.intersections.size(); ++i, ++u) {
      const json& entry = units.at(u);
      if (entry.contains("error")) ++failed;
      else if (!entry.at("complete").get<bool>()) ++incomplete;
      if (entry.contains("curves")) curves += entry.at("curves").size();
      list.push_back(entry);
    }
    jobs.push_back(json{{"source", job.source}, {"intersections", std::move(list)}});
  }
  json summary{{"jobs", batch.jobs.size()},        {"failed_jobs", failed_jobs}, {"intersections", batch.units.size()},
               {"failed_intersections", failed}, {"incomplete", incomplete},   {"curves", curves}};
  return json{{"jobs", std::move(jobs)}, {"summary", std::move(summary)}};
}

bool batch_result_complete(const json& result) {
  const json& s = result.at("summary");
  return s.at("failed_jobs").get<std::size_t>() == 0 && s.at("failed_intersections").get<std::size_t>() == 0 &&
         s.at("incomplete").get<std::size_t>() == 0;
}

}  // namespace ssimarch
