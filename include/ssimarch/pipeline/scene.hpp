// The typed model of a scene: named constants, named surfaces and the intersections to trace,
// each with its options. io/scene.hpp fills it from a scene file (docs/scene-format.md); a
// program (Python, an MPI driver) may build one directly.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/expr/program.hpp"
#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/pipeline/option_table.hpp"
#include "ssimarch/pipeline/spline_surface_data.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Which form of a surface an intersection uses (a scene's "as").
enum class SurfaceForm { kParametric, kImplicit };

/// One entry of "intersections".
struct IntersectionSpec {
  std::string name;
  std::array<std::string, 2> surfaces;  // names as written in the scene
  PairKind kind = PairKind::kImplicitImplicit;
  bool swapped = false;                 // true when the Problem takes the surfaces in the other order
  std::vector<Vec3> starts;             // empty: find start points automatically
  TraceJobOptions options;
};

struct Scene {
  std::string source;  // file name (for messages)
  Constants constants;
  std::vector<std::string> surface_names;  // in file order
  std::map<std::string, Surface> surfaces;
  /// Surfaces that are CAD faces: the region their trimming loops keep (absent: the whole
  /// surface in its domain). The curves of an intersection are cut to both surfaces' regions.
  std::map<std::string, std::shared_ptr<const FaceRegion>> regions;
  /// Spline surfaces' control data as given (for writing them to STEP), by surface name.
  std::map<std::string, SplineSurfaceData> spline_data;
  std::vector<IntersectionSpec> intersections;

  /// Throws InputError naming the known surfaces when `name` is unknown.
  const Surface& surface(const std::string& name) const;
  /// The intersection with this name, or nullptr.
  const IntersectionSpec* intersection(const std::string& name) const;
  /// "a, b, c" (for messages).
  std::string intersection_names() const;
  /// The Problem of an intersection (surfaces in the order its pair kind needs).
  Problem problem(const IntersectionSpec& spec) const;
};

/// Pair kind of two surfaces: both implicit-capable -> implicit-implicit; one -> parametric-
/// implicit (the implicit-capable one used implicitly); none -> parametric-parametric.
/// `as` (the form of each surface) overrides. *swapped tells whether the Problem takes them in
/// the other order (parametric first). Throws InputError(where + ".as[i]" or where, ...).
PairKind choose_pair_kind(const Surface& a, const Surface& b, const std::optional<std::array<SurfaceForm, 2>>& as,
                          const std::string& where, bool* swapped);

}  // namespace ssimarch
