#include "demo_scenes.hpp"

namespace ssimarch::cli {

const std::vector<DemoScene>& demo_scenes() {
  static const std::vector<DemoScene> scenes = {
      {"viviani",
       "sphere (radius 2) and cylinder (cos u, sin u - 1, v): Viviani's figure eight through its node (0,-2,0)",
       R"json({
  "constants": {"R": 2},
  "surfaces": {
    "sphere": {"sphere": {"center": [0, 0, 0], "radius": "R"}},
    "cyl": {"parametric": ["cos(u)", "sin(u)-1", "v"], "u": [0, "2*pi"], "v": [-3, 3], "periodic": ["u"]}
  },
  "intersections": [
    {"name": "viviani", "surfaces": ["sphere", "cyl"], "start": [1, -1, "sqrt(2)"], "options": {"step_length": 0.05}}
  ]
})json",
       15.2807911561},
      {"torus_curve",
       "thesis pair 1: ruled surface and torus, the (1,4) torus curve C1",
       R"json({
  "surfaces": {
    "ruled": {"parametric": ["(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)",
                             "(4+cos(4*u))*sin(u) + v*(cos(4*u)+sin(4*u))*sin(u)",
                             "sin(4*u) + v*(sin(4*u)-cos(4*u))"],
              "u": [0, "2*pi"], "v": [-0.5, 0.5], "periodic": ["u"]},
    "torus": {"parametric": ["(4+cos(u))*sin(v)", "(4+cos(u))*cos(v)", "sin(u)"],
              "u": [0, "2*pi"], "v": [0, "2*pi"], "periodic": ["u", "v"]}
  },
  "intersections": [
    {"name": "torus_curve", "surfaces": ["ruled", "torus"], "start": [5, 0, 0], "options": {"step_length": 0.05}}
  ]
})json",
       35.6831156534},
      {"two_cylinders",
       "seed 000 example 5: two orthogonal unit cylinders, two ellipses crossing at (0, +-1, 0); start points found automatically",
       R"json({
  "surfaces": {
    "c1": {"implicit": "(y^2+z^2-1)/2", "box": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]},
    "c2": {"implicit": "(x^2+y^2-1)/2", "box": [[-1.5, 1.5], [-1.5, 1.5], [-1.5, 1.5]]}
  },
  "intersections": [
    {"name": "two_cylinders", "surfaces": ["c1", "c2"], "options": {"step_length": 0.05}}
  ]
})json",
       0.0},
  };
  return scenes;
}

}  // namespace ssimarch::cli
