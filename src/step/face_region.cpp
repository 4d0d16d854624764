// The region of a STEP face inside its trimming loops (ISO 10303-42 §5.4: FACE_BOUND ->
// EDGE_LOOP -> ORIENTED_EDGE -> EDGE_CURVE and its curve), as a pipeline/face_region.hpp
// region: each edge kept as its exact 3D curve over the piece between its vertices, in the
// loop's direction. A face lies to the left of its loops seen from the face normal (§5.4.24:
// the surface normal, reversed when the face's same_sense is false), so the inward direction
// across an edge at c is n_face(c) x T(c). Seam edges (one EDGE_CURVE used twice by the face,
// once each way, where a closed surface's parameter wraps) bound nothing and are left out.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

#include "ssimarch/geometry/bspline_curve.hpp"
#include "ssimarch/surface/frame.hpp"
#include "access.hpp"

namespace ssimarch::internal {

namespace {

// A 3D curve piece c(s), s in [lo, hi], traversed by the loop in the direction `sign`.
struct EdgePiece {
  std::function<Vec3(double)> at;
  double lo = 0, hi = 0;
  double sign = 1;
  std::function<Vec3(double)> derivative;                   // d at / ds, exact
  std::vector<double> breaks;                               // a B-spline's distinct knots inside (lo, hi)
  std::int64_t edge = 0;                                    // the EDGE_CURVE instance
  std::array<std::pair<std::int64_t, Vec3>, 2> vertices{};  // its VERTEX_POINTs: id, point
};

// The parameter of the nearest point of the piece to p: the nearest of 64 samples, then Newton
// on f(s) = (c(s) - p) . c'(s) (f' from central differences of f), clamped to the piece.
double nearest_parameter(const EdgePiece& e, const Vec3& p) {
  constexpr int kSamples = 64;
  double s = e.lo, best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSamples; ++i) {
    const double t = e.lo + (e.hi - e.lo) * i / kSamples;
    const double d = (e.at(t) - p).squaredNorm();
    if (d < best) {
      best = d;
      s = t;
    }
  }
  const double h = 1e-7 * std::max(1.0, e.hi - e.lo);
  auto f = [&](double t) { return (e.at(t) - p).dot(e.derivative(t)); };
  for (int it = 0; it < 60; ++it) {
    const double df = (f(s + h) - f(s - h)) / (2 * h);
    const Vec3 d = e.derivative(s);
    const double slope = df > 0 ? df : d.squaredNorm();  // Gauss-Newton where Newton's slope is not positive
    if (!(slope > 0)) break;
    const double next = std::clamp(s - f(s) / slope, e.lo, e.hi);
    const bool done = std::abs(next - s) <= 1e-15 * std::max(1.0, std::abs(s));
    s = next;
    if (done) break;
  }
  return s;
}

class StepFaceRegion final : public FaceRegion {
 public:
  StepFaceRegion(std::vector<EdgePiece> edges, bool same_sense, std::string name, std::string solid)
      : edges_(std::move(edges)),
        face_sign_(same_sense ? 1.0 : -1.0),
        name_(std::move(name)),
        solid_(std::move(solid)) {}

  Side side(const Vec3& p, const Vec3& surface_normal) const override {
    Side out{std::numeric_limits<double>::infinity(), p};
    double nearest = std::numeric_limits<double>::infinity();
    for (const EdgePiece& e : edges_) {
      const double s = nearest_parameter(e, p);
      const Vec3 c = e.at(s);
      const double d = (p - c).norm();
      if (d >= nearest) continue;
      nearest = d;
      const Vec3 inward = (face_sign_ * surface_normal).cross(e.sign * e.derivative(s));
      out = {inward.norm() > 0 ? (p - c).dot(inward.normalized()) : d, c};
    }
    return out;
  }
  int boundary_curves() const override { return static_cast<int>(edges_.size()); }
  std::array<double, 2> boundary_range(int i) const override {
    const EdgePiece& e = edges_[static_cast<std::size_t>(i)];
    return {e.lo, e.hi};
  }
  Vec3 boundary_point(int i, double s) const override { return edges_[static_cast<std::size_t>(i)].at(s); }
  std::vector<double> boundary_breaks(int i) const override { return edges_[static_cast<std::size_t>(i)].breaks; }
  Vec3 boundary_derivative(int i, double s) const override { return edges_[static_cast<std::size_t>(i)].derivative(s); }
  std::string name() const override { return name_; }
  std::string solid() const override { return solid_; }
  std::int64_t boundary_edge(int i) const override { return edges_[static_cast<std::size_t>(i)].edge; }
  std::array<std::int64_t, 2> boundary_edge_vertices(int i) const override {
    const EdgePiece& e = edges_[static_cast<std::size_t>(i)];
    return {e.vertices[0].first, e.vertices[1].first};
  }
  std::vector<std::pair<std::int64_t, Vec3>> boundary_vertices() const override {
    std::map<std::int64_t, Vec3> unique;
    for (const EdgePiece& e : edges_)
      for (const auto& [id, p] : e.vertices) unique.emplace(id, p);
    return {unique.begin(), unique.end()};
  }

 private:
  std::vector<EdgePiece> edges_;
  double face_sign_;
  std::string name_, solid_;
};

std::pair<std::int64_t, Vec3> vertex_of(const StepAccess& a, const StepInstance& edge, const StepRecord& r,
                                        std::size_t k, const char* what) {
  const StepInstance& v = a.ref(edge, a.param(edge, r, k, what), what);
  return {v.id, a.point(v, a.param(v, a.record(v, "VERTEX_POINT"), 1, "vertex_geometry"), "vertex_geometry")};
}

// The derivative of a B-spline curve: the degree p - 1 curve of p (P_{i+1} - P_i) / (t_{i+p+1} -
// t_{i+1}) on the knots without their ends (The NURBS Book §3.3, eq. 3.4); zero for degree 0.
BSplineCurve derivative_curve(const BSplineCurve& h) {
  BSplineCurve d;
  d.degree = std::max(0, h.degree - 1);
  d.knots.assign(h.knots.begin() + 1, h.knots.end() - 1);
  const double p = h.degree;
  for (std::size_t i = 0; i + 1 < h.control_points.size(); ++i) {
    const double span = h.knots[i + static_cast<std::size_t>(h.degree) + 1] - h.knots[i + 1];
    d.control_points.push_back(span > 0 ? VecX((h.control_points[i + 1] - h.control_points[i]) * (p / span))
                                        : VecX(VecX::Zero(h.control_points[i].size())));
  }
  return d;
}

// A B-spline edge curve (step/swept_surface.cpp reads it) over its whole range, evaluated in
// homogeneous coordinates (w x, w y, w z, w) by de Boor, its derivative (A' - w' C) / w, and its
// distinct interior knots as the breaks.
void spline_edge(const StepAccess& a, const StepInstance& c, EdgePiece* e) {
  const NurbsCurve3 n = step_bspline_curve(a, c);
  BSplineCurve h;
  h.degree = n.degree;
  h.knots = n.knots;
  for (std::size_t i = 0; i < n.points.size(); ++i) {
    VecX x(4);
    x << n.weights[i] * n.points[i].x(), n.weights[i] * n.points[i].y(), n.weights[i] * n.points[i].z(), n.weights[i];
    h.control_points.push_back(x);
  }
  e->lo = h.start();
  e->hi = h.end();
  for (double k : h.knots)
    if (k > e->lo && k < e->hi && (e->breaks.empty() || k > e->breaks.back())) e->breaks.push_back(k);
  const BSplineCurve dh = derivative_curve(h);  // the reader's degrees are >= 1
  e->derivative = [h, dh](double t) {
    const VecX x = h.at(t), dx = dh.at(t);
    const Vec3 point(x[0] / x[3], x[1] / x[3], x[2] / x[3]);
    return Vec3((Vec3(dx[0], dx[1], dx[2]) - dx[3] * point) / x[3]);
  };
  e->at = [h](double t) {
    const VecX x = h.at(t);
    return Vec3(x[0] / x[3], x[1] / x[3], x[2] / x[3]);
  };
}

// The piece of an oriented edge's curve between its vertices, in the loop's direction.
EdgePiece edge_piece(const StepAccess& a, const StepInstance& edge, double direction) {
  const StepRecord& r = a.record(edge, "EDGE_CURVE");
  const auto start_vertex = vertex_of(a, edge, r, 1, "edge_start"), end_vertex = vertex_of(a, edge, r, 2, "edge_end");
  const Vec3 &start = start_vertex.second, &end = end_vertex.second;
  const bool same_sense = a.boolean(edge, a.param(edge, r, 4, "same_sense"), "same_sense");
  const StepInstance& curve = edge_curve_3d(a, a.ref(edge, a.param(edge, r, 3, "edge_geometry"), "edge_geometry"));
  const StepRecord& cr = curve.records.front();
  EdgePiece e;
  e.edge = edge.id;
  e.vertices = {start_vertex, end_vertex};
  e.sign = direction * (same_sense ? 1.0 : -1.0);
  // From -> to in the curve's increasing parameter.
  const Vec3& from = same_sense ? start : end;
  const Vec3& to = same_sense ? end : start;
  const bool closed = (start - end).norm() <= 1e-12 * std::max(1.0, start.norm());
  if (curve.records.size() == 1 && cr.type == "LINE") {
    const Vec3 p = a.point(curve, a.param(curve, cr, 1, "pnt"), "pnt");
    const Vec3 d = a.vector(a.ref(curve, a.param(curve, cr, 2, "dir"), "dir"), "a line's direction");
    e.at = [p, d](double s) { return Vec3(p + s * d); };
    e.derivative = [d](double) { return d; };
    e.lo = (from - p).dot(d) / d.squaredNorm();
    e.hi = (to - p).dot(d) / d.squaredNorm();
    if (e.lo > e.hi) {  // the vertices run against the line's direction
      std::swap(e.lo, e.hi);
      e.sign = -e.sign;
    }
    return e;
  }
  if (curve.records.size() == 1 && (cr.type == "CIRCLE" || cr.type == "ELLIPSE")) {
    const StepPlacement pl = step_placement(a, a.ref(curve, a.param(curve, cr, 1, "position"), "position"));
    const double ra = a.length(curve, a.param(curve, cr, 2, "radius"), "radius");
    const double rb = cr.type == "CIRCLE" ? ra : a.length(curve, a.param(curve, cr, 3, "semi_axis_2"), "semi_axis_2");
    if (!(ra > 0 && rb > 0)) a.fail(curve, "radii must be > 0");
    const Frame f = Frame::from_axis(pl.origin, pl.axis, pl.reference, a.file().where(curve));
    e.at = [f, ra, rb](double t) { return f.to_world(ra * std::cos(t), rb * std::sin(t), 0.0); };
    e.derivative = [f, ra, rb](double t) { return Vec3(-ra * std::sin(t) * f.e0 + rb * std::cos(t) * f.e1); };
    auto angle = [&](const Vec3& q) {
      return std::atan2((q - f.origin).dot(f.e1) / rb, (q - f.origin).dot(f.e0) / ra);
    };
    const double two_pi = 2 * std::numbers::pi;
    e.lo = angle(from);
    e.hi = e.lo + (closed ? two_pi : std::fmod(angle(to) - e.lo + 2 * two_pi, two_pi));
    return e;
  }
  if (curve.record("B_SPLINE_CURVE_WITH_KNOTS")) {
    spline_edge(a, curve, &e);
    if (!closed) {
      e.lo = nearest_parameter(e, from);
      e.hi = nearest_parameter(e, to);
    }
    if (e.lo > e.hi) {  // the vertices run against the curve's parameter
      std::swap(e.lo, e.hi);
      e.sign = -e.sign;
    }
    std::erase_if(e.breaks, [&](double k) { return !(k > e.lo && k < e.hi); });
    return e;
  }
  a.fail(curve,
         "is not an edge curve the trimming reader knows (LINE, CIRCLE, ELLIPSE, B_SPLINE_CURVE_WITH_KNOTS, "
         "rational ones, through SURFACE_CURVE / SEAM_CURVE)");
}

}  // namespace

std::shared_ptr<const FaceRegion> step_face_region(const StepAccess& a, const StepInstance& face,
                                                   const std::string& name, const std::string& solid) {
  const StepRecord& fr = face.records.front();
  struct Use {
    const StepInstance* edge;
    double direction;
  };
  std::vector<Use> uses;
  std::map<const StepInstance*, int> count;
  for (const StepValue& b : a.list(face, a.param(face, fr, 1, "bounds"), "bounds")) {
    const StepInstance& bound = a.ref(face, b, "bound");
    const StepRecord& br = bound.records.front();
    const double bound_sign = a.boolean(bound, a.param(bound, br, 2, "orientation"), "orientation") ? 1.0 : -1.0;
    const StepInstance& loop = a.ref(bound, a.param(bound, br, 1, "bound"), "bound");
    const StepRecord& lr = loop.records.front();
    if (lr.type != "EDGE_LOOP") continue;  // a VERTEX_LOOP (a pole, an apex) bounds no area
    for (const StepValue& ev : a.list(loop, a.param(loop, lr, 1, "edge_list"), "edge_list")) {
      const StepInstance& oriented = a.ref(loop, ev, "edge");
      const StepRecord& orr = a.record(oriented, "ORIENTED_EDGE");
      const StepInstance& edge = a.ref(oriented, a.param(oriented, orr, 3, "edge_element"), "edge_element");
      const double o = a.boolean(oriented, a.param(oriented, orr, 4, "orientation"), "orientation") ? 1.0 : -1.0;
      uses.push_back({&edge, o * bound_sign});
      ++count[&edge];
    }
  }
  std::vector<EdgePiece> edges;
  for (const Use& u : uses)
    if (count[u.edge] == 1) edges.push_back(edge_piece(a, *u.edge, u.direction));
  if (edges.empty()) return nullptr;  // bounded only by seams and vertices: the whole surface
  return std::make_shared<StepFaceRegion>(
      std::move(edges), a.boolean(face, a.param(face, fr, 3, "same_sense"), "same_sense"), name, solid);
}

}  // namespace ssimarch::internal
