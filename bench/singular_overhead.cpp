// Time of tracing with and without singular-point handling (issue 10, "Measure and publish": a
// curve without singular points may get at most 10% slower). The scene option table has no switch
// for it, so this program calls trace_all directly with TraceAllOptions::through_singular_points
// on and off, for every intersection of the scenes given, with the scene's own options.
//
//   build/bin/singular_overhead examples/viviani.json ...   # one JSON object per line
//
// Each time is the best of `--repeat N` runs (default 3) of the whole trace_all (start points
// included), in CPU time of this process (std::clock), so a loaded machine inflates it less.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/trace/trace_all.hpp"

using namespace ssimarch;

namespace {

struct Timing {
  double cpu_ms = 1e300;
  std::size_t curves = 0;
  std::size_t singular = 0;
  double length = 0;
};

Timing time_trace(const Problem& problem, const IntersectionSpec& spec, bool through, int repeat) {
  Timing t;
  TraceAllOptions all;
  all.through_singular_points = through;
  for (int i = 0; i < repeat; ++i) {
    const std::clock_t c0 = std::clock();
    const TraceResult r = trace_all(problem, spec.options.trace, spec.starts, all);
    t.cpu_ms = std::min(t.cpu_ms, 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    t.curves = r.curves.size();
    t.singular = r.singular_points.size();
    t.length = 0;
    for (const TracedCurve& c : r.curves) t.length += c.length;
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  std::vector<std::string> scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else scenes.push_back(a);
  }
  try {
    for (const std::string& path : scenes) {
      const Scene scene = load_scene(path);
      for (const IntersectionSpec& spec : scene.intersections) {
        const Problem problem = scene.problem(spec);
        const Timing on = time_trace(problem, spec, true, repeat);
        const Timing off = time_trace(problem, spec, false, repeat);
        std::printf("{\"scene\": \"%s\", \"name\": \"%s\", \"on_ms\": %.3f, \"off_ms\": %.3f, \"on_curves\": %zu, "
                    "\"off_curves\": %zu, \"on_singular\": %zu, \"on_length\": %.12g, \"off_length\": %.12g}\n",
                    path.c_str(), spec.name.c_str(), on.cpu_ms, off.cpu_ms, on.curves, off.curves, on.singular,
                    on.length, off.length);
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "singular_overhead: %s\n", e.what());
    return 2;
  }
  return 0;
}
