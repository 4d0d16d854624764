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
// Assemblies (docs/cad.md, "Assemblies"): a part placed in an assembly (NEXT_ASSEMBLY_USAGE_OCCURRENCE
// with a CONTEXT_DEPENDENT_SHAPE_REPRESENTATION whose relationship carries an
// ITEM_DEFINED_TRANSFORMATION, or a MAPPED_ITEM) has its faces listed once per placement, in the
// root product's coordinates: the transformations composed down the product structure.
// Plane angles are converted to radians by the file's plane-angle unit (a CONVERSION_BASED_UNIT
// such as degrees); lengths stay in the file's unit unless the model is read converted to another
// (StepModel's `unit`: every point, radius and trimming length scaled once as it is read).
// Every error is an InputError naming "file:line: #id" of the instance at fault.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ssimarch/geometry/bspline_curve.hpp"
#include "ssimarch/step/part21.hpp"
#include "ssimarch/step/units.hpp"
#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/pipeline/spline_surface_data.hpp"
#include "ssimarch/surface/surface.hpp"

namespace ssimarch {

/// Where an occurrence of a part sits in the model: p -> rotation p + translation (a rigid motion:
/// the composed placements of the assembly, from the part's representation to the root's).
struct PartPlacement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();

  Vec3 apply(const Vec3& p) const { return rotation * p + translation; }
  Vec3 rotate(const Vec3& d) const { return rotation * d; }
  /// This placement followed by `outer` (a part placed in a sub-assembly placed in the root).
  PartPlacement then(const PartPlacement& outer) const {
    return {outer.rotation * rotation, outer.rotation * translation + outer.translation};
  }
  PartPlacement inverse() const { return {rotation.transpose(), -(rotation.transpose() * translation)}; }
  bool is_identity() const { return rotation == Eigen::Matrix3d::Identity() && translation == Vec3::Zero(); }
};

/// A face of the file, numbered 1, 2, ... in the order the file defines them; a face of a part
/// placed several times in an assembly is listed once per placement, next to each other.
struct StepFace {
  int index = 0;
  std::int64_t entity = 0;          // the ADVANCED_FACE / FACE_SURFACE instance
  std::int64_t surface_entity = 0;  // its face_geometry
  int line = 0;
  std::string surface_type;  // the surface instance's type as written, e.g. CYLINDRICAL_SURFACE
  bool same_sense = true;    // face normal along the surface normal
  PartPlacement placement;   // where this occurrence of the face sits (identity outside assemblies)
  std::string instance;      // the occurrence's path in the assembly ("rod-assembly/nut_2"); empty outside
};

class StepModel {
 public:
  /// The model in the file's length unit, or converted to `unit` (docs/cad.md "Length unit").
  /// Converting throws InputError naming the file when it declares no length unit, or several
  /// that differ (one scale cannot convert them).
  explicit StepModel(StepFile file, const std::optional<StepLengthUnit>& unit = std::nullopt);
  static StepModel read(const std::filesystem::path& path, const InputLimits& limits = {},
                        const std::optional<StepLengthUnit>& unit = std::nullopt);

  const StepFile& file() const { return file_; }
  const std::vector<StepFace>& faces() const { return faces_; }
  /// Face `index` (1-based); throws InputError(where) naming how many faces there are.
  const StepFace& face(int index, const std::string& where) const;
  /// The surface of a face instance (trimmed to its boundary's range, see above) or of a
  /// surface instance, moved by `placement` (a StepFace's). Throws InputError for other entities
  /// and unsupported surface types.
  Surface surface(std::int64_t entity, const PartPlacement& placement = {}) const;
  /// The control data of a face's (or surface instance's) B-spline or Bezier surface, through a
  /// RECTANGULAR_TRIMMED_SURFACE, moved by `placement`; empty for other surfaces.
  std::optional<SplineSurfaceData> spline_data(std::int64_t entity, const PartPlacement& placement = {}) const;
  /// The region a face instance keeps inside its trimming loops (outer and inner bounds, each
  /// edge's exact curve: LINE, CIRCLE, ELLIPSE, B-spline; docs/cad.md "Trimming loops"), moved by
  /// `placement`; null for a surface instance and for a face bounded only by seams and vertices.
  /// A face of a solid (MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS) has its solid's key (file, solid,
  /// unit and placement: FaceRegion::solid) and its edges' and vertices' instance ids.
  std::shared_ptr<const FaceRegion> face_region(std::int64_t entity, const PartPlacement& placement = {}) const;
  /// A B_SPLINE_CURVE_WITH_KNOTS (2D or 3D, not rational) as a B-spline curve, a 3D one in the
  /// model's unit (not placed: a curve instance belongs to no occurrence).
  BSplineCurve bspline_curve(std::int64_t entity) const;
  /// Radians per plane-angle unit of the file (1 unless it declares another unit).
  double angle_unit() const { return angle_unit_; }
  /// The unit of the model's coordinates: the file's, or the one it was converted to.
  const StepLengthUnit& length_unit() const { return unit_; }
  /// The length unit the file declares (step_length_unit).
  const StepLengthUnit& file_length_unit() const { return file_unit_; }
  /// Model units per file unit: 1 unless converted.
  double length_scale() const { return scale_; }
  /// The unit the model was converted to when read; empty when it keeps the file's.
  const std::optional<StepLengthUnit>& converted_to() const { return converted_to_; }

 private:
  StepFile file_;
  std::vector<StepFace> faces_;
  double angle_unit_ = 1;
  StepLengthUnit file_unit_, unit_;
  std::optional<StepLengthUnit> converted_to_;
  double scale_ = 1;
  std::map<std::int64_t, std::int64_t> solids_;  // face instance -> the solid it bounds
};

}  // namespace ssimarch
