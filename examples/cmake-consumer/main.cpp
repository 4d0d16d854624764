// Traces the scene given as argument with the installed library and prints, per intersection,
// its name, number of curves and total length ("viviani 1 15.2808").
#include <iostream>

#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: viviani_length SCENE.json\n";
    return 2;
  }
  try {
    const ssimarch::Scene scene = ssimarch::load_scene(argv[1]);
    const ssimarch::TraceJobResult job = ssimarch::trace_scene(scene);
    for (const auto& run : job.runs) {
      double length = 0;
      for (const auto& c : run.result.curves) length += c.length;
      std::cout << run.spec.name << " " << run.result.curves.size() << " " << length << "\n";
    }
  } catch (const ssimarch::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
