// In-process time of run_intersection on a scene (docs/benchmarks.md, "Peers" and "Profiling"):
// the call peer_bench times, without the peers, so a change can be timed before and after in
// one window on a loaded machine. The scene is loaded once; then REPEAT calls on each of its
// intersections (or NAME only), printing per intersection the best, median and worst wall time
// in ms, the start-point search's time (median), the curves, their total length and the
// start-point method. Built by the preset `bench`.
// Usage: intersection_timing SCENE [REPEAT] [NAME]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::cerr << "usage: intersection_timing SCENE [REPEAT] [NAME]\n";
    return 2;
  }
  try {
    const ssimarch::Scene scene = ssimarch::load_scene(argv[1]);
    const int repeat = argc > 2 ? std::max(1, std::atoi(argv[2])) : 20;
    ssimarch::TraceRequest request;
    if (argc > 3) request.only = {argv[3]};
    for (const ssimarch::IntersectionSpec& spec : ssimarch::select_intersections(scene, request)) {
      std::vector<double> ms, search_ms;
      std::size_t curves = 0;
      double length = 0;
      std::string method;
      for (int i = 0; i < repeat; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const ssimarch::IntersectionRun run = ssimarch::run_intersection(scene, spec);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        search_ms.push_back(run.result.start_search.time_ms);
        curves = run.result.curves.size();
        length = 0;
        for (const ssimarch::TracedCurve& c : run.result.curves) length += c.length;
        method = std::string(ssimarch::to_string(run.result.start_search.method));
      }
      std::sort(ms.begin(), ms.end());
      std::sort(search_ms.begin(), search_ms.end());
      std::printf("%s: best %.4g ms, median %.4g ms, worst %.4g ms of %d; start points median %.4g ms (%s); %zu curves, length %.12g\n",
                  spec.name.c_str(), ms.front(), ms[ms.size() / 2], ms.back(), repeat, search_ms[search_ms.size() / 2],
                  method.c_str(), curves, length);
    }
  } catch (const ssimarch::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
