// Swept and offset STEP surfaces (ISO 10303-42 §4.4.30-4.4.33) as ssimarch surfaces:
//   SURFACE_OF_LINEAR_EXTRUSION  S(u, v) = C(u) + v V
//   SURFACE_OF_REVOLUTION        S(u, v) = C(v) turned by u about the axis
// are tensor products of the swept curve C as a NURBS curve with a line (degree 1) or with the
// full circle as a rational quadratic of nine points (Piegl & Tiller, The NURBS Book, 2nd ed.,
// §7.5 and §8.5): exact surfaces, with a parameterisation of their own (u of a revolution runs
// along the circle's NURBS parameter, not the angle). The normal keeps STEP's direction (both
// parameters run the same way), so a face's same_sense stays valid; faces are trimmed by their
// loops in 3D (step/face_region.cpp), which does not need STEP's parameters.
//   OFFSET_SURFACE of a plane, cylinder, sphere or torus is the same kind of surface moved by
// the distance along its normal; offsets of other surfaces have no exact form here and are
// refused.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ssimarch/surface/frame.hpp"
#include "access.hpp"

namespace ssimarch::internal {

NurbsCurve3 step_bspline_curve(const StepAccess& a, const StepInstance& c) {
  const StepRecord* base = c.record("B_SPLINE_CURVE");
  const StepRecord& b = base ? *base : a.record(c, "B_SPLINE_CURVE_WITH_KNOTS");
  const std::size_t o = base ? 0 : 1;
  NurbsCurve3 n;
  n.degree = a.integer(c, a.param(c, b, o, "degree"), "degree", 1, 64);
  for (const StepValue& v : a.list(c, a.param(c, b, o + 1, "control_points_list"), "control_points_list"))
    n.points.push_back(a.point(c, v, "control point"));
  if (const StepRecord* rat = c.record("RATIONAL_B_SPLINE_CURVE"))
    n.weights = a.numbers(c, a.param(c, *rat, 0, "weights_data"), "weights_data");
  else
    n.weights.assign(n.points.size(), 1.0);
  if (n.weights.size() != n.points.size()) a.fail(c, "has another number of weights than control points");
  for (double w : n.weights)
    if (!(w > 0)) a.fail(c, "weights must be > 0");
  if (n.points.size() < static_cast<std::size_t>(n.degree) + 1) a.fail(c, "has fewer than degree + 1 control points");
  const StepRecord& k = base ? a.record(c, "B_SPLINE_CURVE_WITH_KNOTS") : b;
  const std::size_t ko = base ? 0 : 6;
  const std::vector<double> m = a.numbers(c, a.param(c, k, ko, "knot_multiplicities"), "knot_multiplicities");
  const std::vector<double> v = a.numbers(c, a.param(c, k, ko + 1, "knots"), "knots");
  if (m.size() != v.size()) a.fail(c, "has another number of multiplicities than knots");
  const std::size_t expected = n.points.size() + static_cast<std::size_t>(n.degree) + 1;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!(m[i] >= 1 && m[i] == std::floor(m[i]) && n.knots.size() + static_cast<std::size_t>(m[i]) <= expected))
      a.fail(c, "knot multiplicities must be integers >= 1 adding up to control points + degree + 1");
    n.knots.insert(n.knots.end(), static_cast<std::size_t>(m[i]), v[i]);
  }
  if (n.knots.size() != expected) a.fail(c, "knot multiplicities must add up to control points + degree + 1");
  for (std::size_t i = 1; i < n.knots.size(); ++i)
    if (!(n.knots[i] >= n.knots[i - 1])) a.fail(c, "knots must not decrease");
  return n;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The whole conic a cos t e0 + b sin t e1 about its centre as nine rational quadratic points.
NurbsCurve3 full_conic(const Frame& f, double ra, double rb) {
  const double h = std::numbers::sqrt2 / 2;
  NurbsCurve3 n;
  n.degree = 2;
  n.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  const int sx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, sy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  for (int i = 0; i < 9; ++i) {
    n.points.push_back(f.to_world(sx[i] * ra, sy[i] * rb, 0.0));
    n.weights.push_back(i % 2 ? h : 1.0);
  }
  return n;
}

struct Line {
  Vec3 point, direction;  // L(s) = point + s direction
};

Line step_line(const StepAccess& a, const StepInstance& c) {
  const StepRecord& r = c.records.front();
  const Vec3 p = a.point(c, a.param(c, r, 1, "pnt"), "pnt");
  return {p, a.vector(a.ref(c, a.param(c, r, 2, "dir"), "dir"), "a line's direction")};
}

NurbsCurve3 line_piece(const Line& l, double s0, double s1) {
  return {1, {s0, s0, s1, s1}, {Vec3(l.point + s0 * l.direction), Vec3(l.point + s1 * l.direction)}, {1.0, 1.0}};
}

// The swept curve: a B-spline, a whole circle or ellipse, or a line over `line_range` (its
// TRIMMED_CURVE's parameters when it has them, else what `line_range` finds from the face).
template <class LineRange>
NurbsCurve3 swept_curve(const StepAccess& a, const StepInstance& c, LineRange line_range) {
  const StepRecord& r = c.records.front();
  if (c.record("B_SPLINE_CURVE_WITH_KNOTS")) return step_bspline_curve(a, c);
  if (c.records.size() == 1 && (r.type == "CIRCLE" || r.type == "ELLIPSE")) {
    const StepPlacement p = step_placement(a, a.ref(c, a.param(c, r, 1, "position"), "position"));
    const double ra = a.length(c, a.param(c, r, 2, "radius"), "radius");
    const double rb = r.type == "CIRCLE" ? ra : a.length(c, a.param(c, r, 3, "semi_axis_2"), "semi_axis_2");
    if (!(ra > 0 && rb > 0)) a.fail(c, "radii must be > 0");
    return full_conic(Frame::from_axis(p.origin, p.axis, p.reference, a.file().where(c)), ra, rb);
  }
  if (c.records.size() == 1 && r.type == "LINE") {
    const Line l = step_line(a, c);
    const auto [s0, s1] = line_range(l);
    return line_piece(l, s0, s1);
  }
  if (c.records.size() == 1 && r.type == "TRIMMED_CURVE") {
    const StepInstance& basis = a.ref(c, a.param(c, r, 1, "basis_curve"), "basis_curve");
    if (&basis == &c) a.fail(c, "trims itself");
    if (basis.records.size() == 1 && basis.records.front().type == "LINE") {
      // trim_1, trim_2: sets holding a PARAMETER_VALUE (a point is projected).
      const Line l = step_line(a, basis);
      double s[2];
      for (std::size_t k = 0; k < 2; ++k) {
        double found = kInf;
        for (const StepValue& t : a.list(c, a.param(c, r, 2 + k, "trim"), "trim")) {
          if (t.kind == StepValue::Kind::kTyped && t.text == "PARAMETER_VALUE")
            found = a.number(c, t, "trim parameter");
          else if (t.kind == StepValue::Kind::kRef && !std::isfinite(found))
            found = (a.point(c, t, "trim point") - l.point).dot(l.direction) / l.direction.squaredNorm();
        }
        if (!std::isfinite(found)) a.fail(c, "a trim of a line needs a PARAMETER_VALUE or a point");
        s[k] = found;
      }
      return line_piece(l, std::min(s[0], s[1]), std::max(s[0], s[1]));
    }
    return swept_curve(a, basis, line_range);  // the whole basis: the face's loops trim it
  }
  a.fail(c,
         "is not a swept curve this reader knows (LINE, CIRCLE, ELLIPSE, B_SPLINE_CURVE_WITH_KNOTS, rational ones, "
         "TRIMMED_CURVE of them)");
}

[[noreturn]] void unbounded(const StepAccess& a, const StepInstance& s) {
  a.fail(s, "sweeps an unbounded line: select a face whose boundary bounds it");
}

SplineSurfaceData extrusion(const StepAccess& a, const StepInstance& s, const std::vector<Vec3>& boundary,
                            const std::optional<Interval>& v_range) {
  const StepRecord& r = s.records.front();
  const Vec3 V = a.vector(a.ref(s, a.param(s, r, 2, "extrusion_axis"), "extrusion_axis"), "the extrusion vector");
  // A swept line's range: s of p = L(s) + t V at the boundary points (least squares in s, t).
  auto line_range = [&](const Line& l) {
    if (boundary.empty()) unbounded(a, s);
    const double dd = l.direction.squaredNorm(), dv = l.direction.dot(V), vv = V.squaredNorm(), det = dd * vv - dv * dv;
    if (!(det > 1e-24 * dd * vv)) a.fail(s, "extrudes a line along itself");
    double lo = kInf, hi = -kInf;
    for (const Vec3& p : boundary) {
      const Vec3 q = p - l.point;
      const double x = (vv * q.dot(l.direction) - dv * q.dot(V)) / det;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    if (!(hi > lo)) a.fail(s, "its face's boundary does not bound the swept line");
    return std::pair{lo, hi};
  };
  const NurbsCurve3 c = swept_curve(a, a.ref(s, a.param(s, r, 1, "swept_curve"), "swept_curve"), line_range);
  // v: STEP's own (a trimmed surface's range), or the extent of the boundary along V beyond
  // the curve's control hull.
  double v0 = v_range ? v_range->lo : kInf, v1 = v_range ? v_range->hi : -kInf;
  if (!v_range) {
    if (boundary.empty()) unbounded(a, s);
    const Vec3 unit = V.normalized();
    double blo = kInf, bhi = -kInf, clo = kInf, chi = -kInf;
    for (const Vec3& p : boundary) blo = std::min(blo, p.dot(unit)), bhi = std::max(bhi, p.dot(unit));
    for (const Vec3& p : c.points) clo = std::min(clo, p.dot(unit)), chi = std::max(chi, p.dot(unit));
    v0 = (blo - chi) / V.norm();
    v1 = (bhi - clo) / V.norm();
  }
  if (!(v1 > v0)) a.fail(s, "its face's boundary does not bound the extrusion");
  SplineSurfaceData d{c.degree, 1, c.knots, {v0, v0, v1, v1}, {}, {}};
  const bool rational = std::any_of(c.weights.begin(), c.weights.end(), [](double w) { return w != 1.0; });
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    d.points.push_back({Vec3(c.points[i] + v0 * V), Vec3(c.points[i] + v1 * V)});
    if (rational) d.weights.push_back({c.weights[i], c.weights[i]});
  }
  return d;
}

SplineSurfaceData revolution(const StepAccess& a, const StepInstance& s, const std::vector<Vec3>& boundary) {
  const StepRecord& r = s.records.front();
  const StepInstance& ax = a.ref(s, a.param(s, r, 2, "axis_position"), "axis_position");
  const StepRecord& ar = a.record(ax, "AXIS1_PLACEMENT");
  const Vec3 O = a.point(ax, a.param(ax, ar, 1, "location"), "location");
  const StepValue& av = a.param(ax, ar, 2, "axis");
  const Vec3 A = av.kind == StepValue::Kind::kUnset ? a.placement().rotate(Vec3::UnitZ())
                                                    : a.direction(a.ref(ax, av, "axis")).normalized();
  // A swept line's range from the boundary: its axial coordinate is linear in s; a line normal
  // to the axis is bounded by the boundary's distances from the axis.
  auto line_range = [&](const Line& l) {
    if (boundary.empty()) unbounded(a, s);
    double lo = kInf, hi = -kInf;
    const double da = l.direction.dot(A);
    const Vec3 dp = l.direction - da * A;
    const Vec3 q0 = (l.point - O) - (l.point - O).dot(A) * A;  // radial offset at s = 0
    const double sc = -q0.dot(dp) / dp.squaredNorm(), rho2 = (q0 + sc * dp).squaredNorm();
    for (const Vec3& p : boundary) {
      if (std::abs(da) > 1e-12 * l.direction.norm()) {
        const double x = (p - l.point).dot(A) / da;
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      } else {
        const Vec3 q = (p - O) - (p - O).dot(A) * A;
        const double w = std::sqrt(std::max(q.squaredNorm() - rho2, 0.0) / dp.squaredNorm());
        lo = std::min(lo, sc - w);
        hi = std::max(hi, sc + w);
      }
    }
    if (!(hi > lo)) a.fail(s, "its face's boundary does not bound the swept line");
    return std::pair{lo, hi};
  };
  const NurbsCurve3 c = swept_curve(a, a.ref(s, a.param(s, r, 1, "swept_curve"), "swept_curve"), line_range);
  // Each profile point turned about the axis: the nine-point circle of radius |q| in the plane
  // normal to A through its foot on the axis, starting at the point itself.
  const double h = std::numbers::sqrt2 / 2;
  const int sx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, sy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  SplineSurfaceData d{2, c.degree, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, c.knots, {}, {}};
  for (int i = 0; i < 9; ++i) {
    d.points.emplace_back();
    d.weights.emplace_back();
    for (std::size_t j = 0; j < c.points.size(); ++j) {
      const Vec3 foot = O + (c.points[j] - O).dot(A) * A, x = c.points[j] - foot, y = A.cross(x);
      d.points.back().push_back(foot + sx[i] * x + sy[i] * y);
      d.weights.back().push_back((i % 2 ? h : 1.0) * c.weights[j]);
    }
  }
  return d;
}

}  // namespace

std::optional<SplineSurfaceData> step_swept_surface(const StepAccess& a, const StepInstance& s,
                                                    const std::vector<Vec3>& boundary,
                                                    const std::optional<Interval>& v_range) {
  if (s.records.size() != 1) return std::nullopt;
  const std::string& t = s.records.front().type;
  if (t == "SURFACE_OF_LINEAR_EXTRUSION") return extrusion(a, s, boundary, v_range);
  if (t == "SURFACE_OF_REVOLUTION") return revolution(a, s, boundary);
  return std::nullopt;
}

Surface step_offset_surface(const Surface& basis, double d, const StepAccess& a, const StepInstance& s) {
  try {
    if (const auto* p = basis.get_if<Plane>()) {
      const Frame& f = p->frame();
      return Plane(f.origin + d * f.e2, f.e2, p->domain(), f.e0);
    }
    if (const auto* c = basis.get_if<Cylinder>()) {
      const Frame& f = c->frame();
      return Cylinder(f.origin, f.e2, c->radius() + d, c->domain().v, f.e0);
    }
    if (const auto* p = basis.get_if<Sphere>()) {
      const Frame& f = p->frame();
      return Sphere(f.origin, p->radius() + d, f.e2, f.e0);
    }
    if (const auto* t = basis.get_if<Torus>()) {
      const Frame& f = t->frame();
      return Torus(f.origin, f.e2, t->major_radius(), t->minor_radius() + d, f.e0);
    }
  } catch (const InputError& e) {
    a.fail(s, "the offset surface does not exist: " + e.message());
  }
  a.fail(s, std::string("offsets a ") + std::string(basis.type_name()) +
                " surface: only offsets of planes, cylinders, spheres and tori are exact surfaces here");
}

}  // namespace ssimarch::internal
