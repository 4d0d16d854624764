// Points along the boundary of a STEP face (ISO 10303-42 §5.4 topology: FACE_BOUND ->
// EDGE_LOOP -> ORIENTED_EDGE -> EDGE_CURVE -> VERTEX_POINT and the edge's curve), from which
// step/reader.cpp takes a face's parameter range.
#include <cmath>
#include <numbers>

#include "ssimarch/surface/frame.hpp"
#include "access.hpp"

namespace ssimarch::internal {

StepPlacement step_placement(const StepAccess& a, const StepInstance& inst) {
  const StepRecord& r = a.record(inst, "AXIS2_PLACEMENT_3D");
  StepPlacement p;
  p.origin = a.point(inst, a.param(inst, r, 1, "location"), "location");
  const StepValue& axis = a.param(inst, r, 2, "axis");
  const PartPlacement& moved = a.placement();
  p.axis = axis.kind == StepValue::Kind::kUnset ? moved.rotate(Vec3::UnitZ()) : a.direction(a.ref(inst, axis, "axis"));
  const StepValue& ref = a.param(inst, r, 3, "ref_direction");
  if (ref.kind != StepValue::Kind::kUnset) p.reference = a.direction(a.ref(inst, ref, "ref_direction"));
  if (!(p.axis.norm() > 0)) a.fail(inst, "the axis is a zero vector");
  // Without a reference the frame's default e0 is chosen from the axis (Frame::from_axis): taken
  // in the part's own coordinates and moved with it, so a placed part keeps its parametrisation.
  if (!p.reference && !moved.is_identity())
    p.reference = moved.rotate(
        Frame::from_axis(Vec3::Zero(), moved.rotation.transpose() * p.axis, std::nullopt, a.file().where(inst)).e0);
  return p;
}

PartPlacement placement_motion(const StepAccess& a, const StepInstance& inst) {
  const StepPlacement p = step_placement(a, inst);
  const Frame f = Frame::from_axis(p.origin, p.axis, p.reference, a.file().where(inst));
  PartPlacement m;
  m.rotation.col(0) = f.e0;
  m.rotation.col(1) = f.e1;
  m.rotation.col(2) = f.e2;
  m.translation = f.origin;
  return m;
}

namespace {

// Samples per full turn of a circle or ellipse: the range of a cylinder's height along an
// inclined circle is met within 1 - cos(pi/64) ~ 1.2e-3 of its radius.
constexpr int kSamplesPerTurn = 128;

// A conic's point at angle t in its placement: (a cos t, b sin t) in (e0, e1).
struct Conic2 {
  Frame frame;
  double a, b;
  Vec3 at(double t) const { return frame.to_world(a * std::cos(t), b * std::sin(t), 0.0); }
  double angle_of(const Vec3& p) const {
    const Vec3 d = p - frame.origin;
    return std::atan2(d.dot(frame.e1) / b, d.dot(frame.e0) / a);
  }
};

std::optional<Conic2> conic(const StepAccess& a, const StepInstance& curve) {
  const StepRecord& r = curve.records.front();
  if (r.type != "CIRCLE" && r.type != "ELLIPSE") return std::nullopt;
  const StepPlacement p = step_placement(a, a.ref(curve, a.param(curve, r, 1, "position"), "position"));
  const double ra = a.length(curve, a.param(curve, r, 2, "radius"), "radius");
  const double rb = r.type == "CIRCLE" ? ra : a.length(curve, a.param(curve, r, 3, "semi_axis_2"), "semi_axis_2");
  if (!(ra > 0 && rb > 0)) a.fail(curve, "radii must be > 0");
  return Conic2{Frame::from_axis(p.origin, p.axis, p.reference, a.file().where(curve)), ra, rb};
}

void control_points(const StepAccess& a, const StepInstance& curve, std::vector<Vec3>* out) {
  const StepRecord* r = curve.record("B_SPLINE_CURVE_WITH_KNOTS");
  const StepRecord* base = curve.record("B_SPLINE_CURVE");
  const std::size_t k =
      base ? 1 : 2;  // complex: B_SPLINE_CURVE(degree, points, ...); simple: (name, degree, points, ...)
  if (!base && !(r && curve.records.size() == 1)) return;
  const StepRecord& b = base ? *base : *r;
  for (const StepValue& v : a.list(curve, a.param(curve, b, k, "control_points_list"), "control_points_list"))
    out->push_back(a.point(curve, v, "control point"));
}

Vec3 vertex(const StepAccess& a, const StepInstance& edge, const StepRecord& r, std::size_t k, const char* what) {
  const StepInstance& v = a.ref(edge, a.param(edge, r, k, what), what);
  return a.point(v, a.param(v, a.record(v, "VERTEX_POINT"), 1, "vertex_geometry"), "vertex_geometry");
}

void edge_points(const StepAccess& a, const StepInstance& edge, std::vector<Vec3>* out) {
  const StepRecord& r = a.record(edge, "EDGE_CURVE");
  const Vec3 start = vertex(a, edge, r, 1, "edge_start"), end = vertex(a, edge, r, 2, "edge_end");
  out->push_back(start);
  out->push_back(end);
  const StepInstance& curve = edge_curve_3d(a, a.ref(edge, a.param(edge, r, 3, "edge_geometry"), "edge_geometry"));
  const bool same_sense = a.boolean(edge, a.param(edge, r, 4, "same_sense"), "same_sense");
  if (const auto c = conic(a, curve)) {
    // The edge runs along the curve's increasing angle from start to end when same_sense.
    const double two_pi = 2 * std::numbers::pi;
    double t0 = c->angle_of(same_sense ? start : end), t1 = c->angle_of(same_sense ? end : start);
    double sweep = std::fmod(t1 - t0 + 2 * two_pi, two_pi);
    if ((start - end).norm() <= 1e-12 * (1 + c->a)) sweep = two_pi;  // a closed edge: the whole conic
    const int n = std::max(2, static_cast<int>(std::ceil(sweep / two_pi * kSamplesPerTurn)));
    for (int i = 0; i <= n; ++i) out->push_back(c->at(t0 + sweep * i / n));
    return;
  }
  control_points(a, curve, out);
}

}  // namespace

const StepInstance& edge_curve_3d(const StepAccess& a, const StepInstance& curve) {
  const StepRecord& r = curve.records.front();
  if (curve.records.size() == 1 &&
      (r.type == "SURFACE_CURVE" || r.type == "SEAM_CURVE" || r.type == "INTERSECTION_CURVE"))
    return a.ref(curve, a.param(curve, r, 1, "curve_3d"), "curve_3d");
  return curve;
}

std::vector<Vec3> step_boundary_points(const StepAccess& a, const StepInstance& face) {
  std::vector<Vec3> pts;
  const StepRecord& fr = face.records.front();
  for (const StepValue& b : a.list(face, a.param(face, fr, 1, "bounds"), "bounds")) {
    const StepInstance& bound = a.ref(face, b, "bound");
    const StepRecord& br = bound.records.front();
    if (br.type != "FACE_OUTER_BOUND" && br.type != "FACE_BOUND")
      a.fail(bound, "expected FACE_BOUND or FACE_OUTER_BOUND");
    const StepInstance& loop = a.ref(bound, a.param(bound, br, 1, "bound"), "bound");
    const StepRecord& lr = loop.records.front();
    if (lr.type == "EDGE_LOOP") {
      for (const StepValue& e : a.list(loop, a.param(loop, lr, 1, "edge_list"), "edge_list")) {
        const StepInstance& oriented = a.ref(loop, e, "edge");
        const StepRecord& orr = a.record(oriented, "ORIENTED_EDGE");
        edge_points(a, a.ref(oriented, a.param(oriented, orr, 3, "edge_element"), "edge_element"), &pts);
      }
    } else if (lr.type == "VERTEX_LOOP") {
      pts.push_back(vertex(a, loop, lr, 1, "loop_vertex"));
    } else if (lr.type == "POLY_LOOP") {
      for (const StepValue& p : a.list(loop, a.param(loop, lr, 1, "polygon"), "polygon"))
        pts.push_back(a.point(loop, p, "polygon"));
    } else {
      a.fail(loop, "is not a loop this reader knows (EDGE_LOOP, VERTEX_LOOP, POLY_LOOP)");
    }
  }
  return pts;
}

}  // namespace ssimarch::internal
