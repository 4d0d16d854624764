// Checked access to the parameters of Part 21 instances for the STEP readers (private to io/):
// each accessor throws InputError naming "file:line: #id", the entity and the attribute.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ssimarch/core/error.hpp"
#include "ssimarch/core/vec3.hpp"
#include "ssimarch/step/part21.hpp"
#include "ssimarch/step/reader.hpp"
#include "ssimarch/pipeline/face_region.hpp"
#include "ssimarch/pipeline/spline_surface_data.hpp"
#include "ssimarch/surface/surface.hpp"
#include "ssimarch/core/text_cat.hpp"

namespace ssimarch::internal {

// Every 3D point and direction read through it is moved by the placement of the part occurrence
// being read (identity by default); 2D points and directions (parameter space) are not. With a
// unit conversion (`scale`: target units per file unit, docs/cad.md "Length unit") every length
// is scaled first: 3D points, vector magnitudes and what the reader reads with length(). The
// placements' translations are read through the same access, so p -> R (s p) + s t = s (R p + t).
class StepAccess {
 public:
  explicit StepAccess(const StepFile& file, const PartPlacement& placement = {}, double scale = 1.0)
      : file_(file), placement_(placement), scale_(scale) {}
  const PartPlacement& placement() const { return placement_; }
  double scale() const { return scale_; }
  const StepFile& file() const { return file_; }

  [[noreturn]] void fail(const StepInstance& inst, const std::string& message) const {
    throw InputError(file_.where(inst), cat(inst.type_text(), ": ", message));
  }
  /// The record `type` of `inst`, or (simple instance) its only record when `type` is empty.
  const StepRecord& record(const StepInstance& inst, const std::string& type) const {
    const StepRecord* r = type.empty() ? &inst.records.front() : inst.record(type);
    if (!r) fail(inst, cat("has no ", type, " part"));
    return *r;
  }
  /// Parameter `k` of a record, which must have at least `k + 1`.
  const StepValue& param(const StepInstance& inst, const StepRecord& r, std::size_t k, const char* what) const {
    if (k >= r.params.size())
      fail(inst, cat("attribute ", what, " (parameter ", k + 1, " of ", r.type, ") is missing"));
    return r.params[k];
  }
  double number(const StepInstance& inst, const StepValue& v, const char* what) const {
    const StepValue* x = &v;
    if (x->kind == StepValue::Kind::kTyped && x->items.size() == 1) x = &x->items[0];  // LENGTH_MEASURE(2.)
    if (!x->is_number()) fail(inst, cat(what, " must be a number"));
    return x->number;
  }
  /// A length (a radius, an offset, a trimming distance): number() in the target unit.
  double length(const StepInstance& inst, const StepValue& v, const char* what) const {
    return number(inst, v, what) * scale_;
  }
  int integer(const StepInstance& inst, const StepValue& v, const char* what, int lo, int hi) const {
    const double x = number(inst, v, what);
    if (v.kind != StepValue::Kind::kInteger || x < lo || x > hi)
      fail(inst, cat(what, " must be an integer in [", lo, ", ", hi, "]"));
    return static_cast<int>(x);
  }
  const std::vector<StepValue>& list(const StepInstance& inst, const StepValue& v, const char* what) const {
    if (v.kind != StepValue::Kind::kList) fail(inst, cat(what, " must be a list"));
    return v.items;
  }
  std::vector<double> numbers(const StepInstance& inst, const StepValue& v, const char* what) const {
    std::vector<double> out;
    for (const StepValue& x : list(inst, v, what)) out.push_back(number(inst, x, what));
    return out;
  }
  bool boolean(const StepInstance& inst, const StepValue& v, const char* what) const {
    if (v.kind != StepValue::Kind::kEnum || (v.text != "T" && v.text != "F"))
      fail(inst, cat(what, " must be .T. or .F."));
    return v.text == "T";
  }
  const StepInstance& ref(const StepInstance& inst, const StepValue& v, const char* what) const {
    if (v.kind != StepValue::Kind::kRef) fail(inst, cat(what, " must be a reference #id"));
    return file_.at(v.ref, inst);
  }
  /// CARTESIAN_POINT or DIRECTION coordinates as written (2D points get z = 0), and whether the
  /// instance is 3D.
  Vec3 coordinates(const StepInstance& inst, const char* type, bool* three_d = nullptr) const {
    const StepRecord& r = record(inst, type);
    const std::vector<double> c = numbers(inst, param(inst, r, 1, "coordinates"), "coordinates");
    if (c.size() < 2 || c.size() > 3) fail(inst, "must have 2 or 3 coordinates");
    if (three_d) *three_d = c.size() == 3;
    return {c[0], c[1], c.size() == 3 ? c[2] : 0.0};
  }
  /// A CARTESIAN_POINT, placed.
  Vec3 point(const StepInstance& from, const StepValue& v, const char* what) const {
    bool three_d = false;
    const Vec3 p = coordinates(ref(from, v, what), "CARTESIAN_POINT", &three_d);
    return three_d ? placement_.apply(p * scale_) : p;
  }
  /// A VECTOR instance: its orientation (a DIRECTION, placed) made unit times its magnitude; a
  /// zero vector fails naming it with `what` ("a line's direction").
  Vec3 vector(const StepInstance& vec, const char* what) const {
    const StepRecord& vr = record(vec, "VECTOR");
    const Vec3 d = direction(ref(vec, param(vec, vr, 1, "orientation"), "orientation")).normalized() *
                   length(vec, param(vec, vr, 2, "magnitude"), "magnitude");
    if (!(d.norm() > 0)) fail(vec, cat(what, " must not be zero"));
    return d;
  }
  /// A DIRECTION instance, placed (rotated).
  Vec3 direction(const StepInstance& inst) const {
    bool three_d = false;
    const Vec3 d = coordinates(inst, "DIRECTION", &three_d);
    return three_d ? placement_.rotate(d) : d;
  }

 private:
  const StepFile& file_;
  PartPlacement placement_;
  double scale_ = 1.0;
};

/// An AXIS2_PLACEMENT_3D: location, axis (default z) and reference direction (default: none,
/// Frame::from_axis's choice, which is x for the z axis as ISO 10303-42 has it).
struct StepPlacement {
  Vec3 origin, axis;
  std::optional<Vec3> reference;
};
StepPlacement step_placement(const StepAccess& a, const StepInstance& inst);

/// A placement as a rigid motion: p -> [e0 e1 e2] p + origin, its frame (Frame::from_axis) read
/// through `a` (so already placed where `a` places).
PartPlacement placement_motion(const StepAccess& a, const StepInstance& inst);

/// One occurrence of a face in the model: the face instance, where it sits, its assembly path.
struct PlacedFace {
  std::int64_t face = 0;
  PartPlacement placement;
  std::string instance;
};
/// Every face of the file with its occurrences in the product structure (step/assembly.cpp,
/// docs/cad.md "Assemblies"), in file order, a face's occurrences together; a face outside any
/// assembly once, unplaced.
std::vector<PlacedFace> placed_faces(const StepAccess& a);

/// Points along a face's boundary (see step/reader.hpp, "Trimming"): empty when the face
/// has no bounds.
std::vector<Vec3> step_boundary_points(const StepAccess& a, const StepInstance& face);

/// The 3D curve of an edge's geometry, looking through SURFACE_CURVE, SEAM_CURVE and
/// INTERSECTION_CURVE (ISO 10303-42 §4.4.x: their first curve is the 3D one).
const StepInstance& edge_curve_3d(const StepAccess& a, const StepInstance& curve);

/// A rational B-spline curve in 3D (weights all 1 when polynomial).
struct NurbsCurve3 {
  int degree = 1;
  std::vector<double> knots;
  std::vector<Vec3> points;
  std::vector<double> weights;
};
/// A B_SPLINE_CURVE_WITH_KNOTS, simple or complex with RATIONAL_B_SPLINE_CURVE.
NurbsCurve3 step_bspline_curve(const StepAccess& a, const StepInstance& curve);

/// SURFACE_OF_LINEAR_EXTRUSION and SURFACE_OF_REVOLUTION as exact rational B-spline surfaces
/// (step/swept_surface.cpp); `boundary` (a face's boundary points) bounds a swept line and
/// an extrusion's length, `v_range` (a RECTANGULAR_TRIMMED_SURFACE's v, which is STEP's and
/// ours for an extrusion) its length first. Empty for other types.
std::optional<SplineSurfaceData> step_swept_surface(const StepAccess& a, const StepInstance& s,
                                                    const std::vector<Vec3>& boundary,
                                                    const std::optional<Interval>& v_range = std::nullopt);
/// OFFSET_SURFACE `s` of `basis` at distance d: a plane, cylinder, sphere or torus moved along
/// its normal; fails naming `s` for other bases.
Surface step_offset_surface(const Surface& basis, double d, const StepAccess& a, const StepInstance& s);

/// The region inside a face's trimming loops (step/face_region.cpp); null when no edge of
/// the face bounds an area (only seams and vertex loops). `name` is for messages, `solid` the
/// key of the solid occurrence the face bounds (FaceRegion::solid; empty: none).
std::shared_ptr<const FaceRegion> step_face_region(const StepAccess& a, const StepInstance& face,
                                                   const std::string& name, const std::string& solid = {});

/// The solid each face bounds: face instance id -> the MANIFOLD_SOLID_BREP or BREP_WITH_VOIDS
/// whose shells (CLOSED_SHELL, ORIENTED_CLOSED_SHELL) list it (ISO 10303-42 §5.4.x).
std::map<std::int64_t, std::int64_t> solids_of_faces(const StepAccess& a);

}  // namespace ssimarch::internal
