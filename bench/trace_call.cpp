// The C++ call that ssimarch.trace wraps, timed (docs/benchmarks.md, "Python layer"): load_scene +
// trace_scene with a step_length override, exactly what python/ssimarch_module.cpp runs for
// ssimarch.trace(SCENE, only=NAME, step_length=H). Prints the wall time and the process CPU time
// of each call in ms, a line per call; bench/python-overhead --cxx compares them with the Python
// call's (CPU time: less disturbed than wall time on a loaded machine). Built by the preset
// `bench`, or against an installed package: c++ -O3 bench/trace_call.cpp $(pkg-config --cflags --libs ssimarch).
// Usage: trace_call SCENE NAME STEP_LENGTH REPEAT
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <iostream>
#include <string>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/option_table.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: trace_call SCENE NAME STEP_LENGTH REPEAT\n";
    return 2;
  }
  try {
    ssimarch::TraceRequest request;
    request.only = {argv[2]};
    request.overrides.push_back({ssimarch::find_trace_option("step_length"), std::stod(argv[3]), "step_length"});
    const int repeat = std::atoi(argv[4]);
    for (int i = 0; i < repeat; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      const ssimarch::Scene scene = ssimarch::load_scene(argv[1]);
      const ssimarch::TraceJobResult job = ssimarch::trace_scene(scene, request);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const double cpu_ms = 1e3 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      if (job.runs.empty()) return 1;
      std::cout << ms << " " << cpu_ms << "\n";
    }
  } catch (const ssimarch::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
