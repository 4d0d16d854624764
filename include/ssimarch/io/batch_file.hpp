// Batch files (`ssimarch batch JOBS.json`, docs/scene-format.md "Batch files") read into the
// batch model of pipeline/batch_job.hpp, and the merged batch result as JSON
// (docs/output-format.md "Batch output").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ssimarch/core/input_limits.hpp"
#include "ssimarch/pipeline/batch_job.hpp"

namespace ssimarch {

/// Reads a batch file. Throws InputError when the file itself is unusable (missing, a JSON
/// syntax error, not an object with a "jobs" list, an unknown top-level key); a bad entry of
/// "jobs" (a missing or invalid scene, an unknown key, an unknown intersection name) becomes that
/// job's error and the other jobs are read. Scene paths are relative to the batch file's folder.
Batch load_batch(const std::filesystem::path& path, const InputLimits& limits = {});
/// Same, from text; `source` names it in messages, `folder` resolves relative scene paths.
Batch parse_batch(const std::string& text, const std::string& source, const std::filesystem::path& folder,
                  const InputLimits& limits = {});

/// One unit's entry of the output: the trace JSON of io/trace_writers.hpp to_json plus
/// "complete" (TraceJobResult::complete's rule for this intersection), or {"name", "surfaces",
/// "complete": false, "error"} when it failed.
nlohmann::json batch_unit_json(const Batch& batch, std::size_t unit, const BatchOutcome& outcome);

/// The merged output: {"jobs": [{"source", "intersections": [unit entries]} or {"source",
/// "error"}], "summary": {...}}; units[u] is unit u's entry (batch_unit_json).
nlohmann::json batch_result_json(const Batch& batch, const std::vector<nlohmann::json>& units);

/// Whether the merged output reports every job read and every intersection complete.
bool batch_result_complete(const nlohmann::json& result);

}  // namespace ssimarch
