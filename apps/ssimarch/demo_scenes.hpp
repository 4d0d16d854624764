// The built-in scenes of `ssimarch demo` (also shipped as examples/*.json).
#pragma once

#include <string>
#include <vector>

namespace ssimarch::cli {

struct DemoScene {
  std::string name;        // file stem under out/demo/
  std::string title;       // one line for the summary
  std::string json;        // the scene
  double exact_length;     // the exact length of its (first) curve, 0 if none is known
};

const std::vector<DemoScene>& demo_scenes();

}  // namespace ssimarch::cli
