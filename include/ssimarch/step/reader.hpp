// Faces and surfaces of STEP AP203/AP214/AP242 files (ISO 10303-42 geometry and topology) as
// ssimarch surfaces (docs/cad.md, "STEP import"):
//   PLANE, CYLINDRICAL_SURFACE, CONICAL_SURFACE, SPHERICAL_SURFACE, TOROIDAL_SURFACE (each on an
//   AXIS2_PLACEMENT_3D) -> Plane, Cylinder, Cone, Sphere, Torus with the same parameterisation
//   (a cone's v is moved to start at its apex);
//   B_SPLINE_SURFACE_WITH_KNOTS, BEZIER_SURFACE and their RATIONAL_B_SPLINE_SURFACE complex
//   instances -> BSplineSurface; RECTANGULAR_TRIMMED_SURFACE -> its basis with the rectangle.
// Trimming: a face (ADVANCED_FACE, FACE_SURFACE) bounds its surface by the parameter range of
// its boundary (edges sampled: lines by their vertices, circles and ellipses along their arcs,
// B-spline edges by their control points, which hold the curve in their hull): the rectangle
// of a plane, the axial range of a cylinder or cone. Spheres, tori and B-spline surfaces keep
// their whole domain. The loops themselves (holes, curved outer bounds) are the face's region
// (face_region), to which a scene cuts the traced curves.
// Plane angles are converted to radians by the file's plane-angle unit (a CONVERSION_BASED_UNIT
// such as degrees); lengths stay in the file's unit.
// Every error is an InputError naming "file:line: #id" of the instance at fault.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/geometry/bspline_curve.hpp"
#include "ssimarch/step/part21.hpp"
#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/pipeline/spline_surface_data.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// A face of the file, numbered 1, 2, ... in the order the file defines them.
struct StepFace {
  int index = 0;
  std::int64_t entity = 0;          // the ADVANCED_FACE / FACE_SURFACE instance
  std::int64_t surface_entity = 0;  // its face_geometry
  int line = 0;
  std::string surface_type;  // the surface instance's type as written, e.g. CYLINDRICAL_SURFACE
  bool same_sense = true;    // face normal along the surface normal
};

class StepModel {
 public:
  explicit StepModel(StepFile file);
  static StepModel read(const std::filesystem::path& path, const InputLimits& limits = {});

  const StepFile& file() const { return file_; }
  const std::vector<StepFace>& faces() const { return faces_; }
  /// Face `index` (1-based); throws InputError(where) naming how many faces there are.
  const StepFace& face(int index, const std::string& where) const;
  /// The surface of a face instance (trimmed to its boundary's range, see above) or of a
  /// surface instance. Throws InputError for other entities and unsupported surface types.
  Surface surface(std::int64_t entity) const;
  /// The control data of a face's (or surface instance's) B-spline or Bezier surface, through a
  /// RECTANGULAR_TRIMMED_SURFACE; empty for other surfaces.
  std::optional<SplineSurfaceData> spline_data(std::int64_t entity) const;
  /// The region a face instance keeps inside its trimming loops (outer and inner bounds, each
  /// edge's exact curve: LINE, CIRCLE, ELLIPSE, B-spline; docs/cad.md "Trimming loops"); null
  /// for a surface instance and for a face bounded only by seams and vertices.
  std::shared_ptr<const FaceRegion> face_region(std::int64_t entity) const;
  /// A B_SPLINE_CURVE_WITH_KNOTS (2D or 3D, not rational) as a B-spline curve.
  BSplineCurve bspline_curve(std::int64_t entity) const;
  /// Radians per plane-angle unit of the file (1 unless it declares another unit).
  double angle_unit() const { return angle_unit_; }

 private:
  StepFile file_;
  std::vector<StepFace> faces_;
  double angle_unit_ = 1;
};

}  // namespace ssimarch
