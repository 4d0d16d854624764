// libFuzzer target: tracing fuzzed small scenes. A scene that reads is traced with its options
// capped (points per curve, start samples, certified boxes) so that one input takes at most a few
// seconds of CPU under the sanitizers (the largest seed, Thesis pair 1: 4.8 s; 0.2 s in a release
// build); libFuzzer's -timeout (60 s of wall clock in scripts/run-fuzzers) reports a hang.
// docs/reliability.md, "Fuzzing".
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;  // small scenes: the reader target covers large ones
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    ssimarch::Scene scene = ssimarch::parse_scene(text, "fuzz.json");
    for (ssimarch::IntersectionSpec& spec : scene.intersections) {
      ssimarch::TraceOptions& o = spec.options.trace;
      o.max_points = std::min(o.max_points, 300L);
      o.start_samples = std::min(o.start_samples, 8);
      o.start_box_budget = std::min(o.start_box_budget, 200L);
    }
    const ssimarch::TraceJobResult job = ssimarch::trace_scene(scene, {});
    (void)job.complete();
  } catch (const ssimarch::InputError&) {
  }
  return 0;
}
