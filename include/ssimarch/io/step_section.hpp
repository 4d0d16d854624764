// A section of a STEP model by planes (issue 28 item 4; docs/cad.md, "Sections"): the scene of
// every face whose surface the plane can meet, each trimmed to its loops, against the plane. The
// plane is unbounded (surface/unbounded.hpp: each pair clips it to the face's box), so nothing is
// cut by a default extent; faces are culled by their boxes, which hold them (a primitive's
// trimmed part, a patch's control points).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/step/reader.hpp"

namespace ssimarch {

struct SectionPlane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit
};

/// "X,Y,Z,NX,NY,NZ": six finite numbers, a point of the plane and a non-zero normal (normalised).
/// Throws InputError(where, ...) otherwise.
SectionPlane parse_section_plane(const std::string& text, const std::string& where);

/// Relative tolerance of the box test (dimensionless, of the box's diagonal): a face lying in the
/// plane (a flat box) counts as met, and is reported as coincident by the trace.
inline constexpr double kSectionBoxSlack = 1e-9;

struct SectionScene {
  nlohmann::json scene;               // surfaces face<i> and plane<k>, intersections face<i>-plane<k>
  int pairs = 0;                      // intersections in it
  int culled = 0;                     // face-plane pairs whose boxes are apart
  std::vector<std::string> not_read;  // "face 12 (#345, SURFACE_OF_REVOLUTION): why", one per face
};

/// The section scene of `faces` (numbers as `ssimarch faces` lists them) of the model read from
/// `step`, by each of `planes`: a pair for every face whose box the plane crosses (within
/// kSectionBoxSlack). A face whose surface cannot be read is listed in not_read, not traced.
SectionScene step_section_scene(const std::filesystem::path& step, const StepModel& model,
                                const std::vector<int>& faces, const std::vector<SectionPlane>& planes);

}  // namespace ssimarch
