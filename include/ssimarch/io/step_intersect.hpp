// Part against part (issue 28 item 4; docs/cad.md, "Part against part"): the scene of every pair
// of faces, one from each set, whose boxes meet, each face trimmed to its loops. The two sets come
// from one STEP model or two; pairs are found by sweep and prune (surface/box_pairs.hpp), not by
// trying all of them.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ssimarch/step/reader.hpp"

namespace ssimarch {

/// Relative slack of the box test (dimensionless, of the larger model's box diagonal): faces that
/// touch (a shared edge, a rod resting on a plate) have boxes that touch, up to rounding.
inline constexpr double kIntersectBoxSlack = 1e-9;

struct StepFaceSet {
  std::filesystem::path step;  // as the scene's surfaces name it
  const StepModel* model = nullptr;
  std::vector<int> faces;  // numbers as `ssimarch faces` lists them
};

struct IntersectScene {
  nlohmann::json scene;               // surfaces and one intersection per pair whose boxes meet
  int pairs = 0;                      // intersections in it
  int culled = 0;                     // pairs of the two sets left out: boxes apart, or of one solid sharing nothing
  int culled_by_solid = 0;            // of them, faces of one solid that share no edge and no vertex
  std::vector<std::string> not_read;  // "A face 12 (#345, SURFACE_OF_REVOLUTION): why", one per face
};

/// The intersections of the faces of `a` with those of `b`. With `same_model` (both sets from one
/// file) the surfaces are named face<i> and a pair of faces in both sets is one intersection
/// face<i>-face<j> (i < j), a face never with itself; else a<i> and b<j>, named a<i>-b<j>. A face
/// whose surface cannot be read is listed in not_read, not traced. With `solid_topology` (the
/// option of that name: pipeline/shared_boundary.hpp) two faces of one solid that share no edge and
/// no vertex are left out too: they do not meet.
IntersectScene step_intersect_scene(const StepFaceSet& a, const StepFaceSet& b, bool same_model,
                                    bool solid_topology = true);

}  // namespace ssimarch
