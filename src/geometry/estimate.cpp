#include "ssimarch/geometry/estimate.hpp"

#include <cmath>

namespace ssimarch {

namespace {

// Below this |t_P x t_Q| (sine of the turning angle, dimensionless) the Wu-Andrade planes are
// parallel to rounding and the circle does not exist; likewise for |a x b| / (|a| |b|) of three
// points.
constexpr double kParallelSine = 1e-13;

struct SampleFrame {
  bool exists = false;    // the samples for this frame are there
  bool straight = false;  // they are, but tangents parallel / points collinear
  double kappa = kNaN;
  Vec3 n = Vec3::Constant(kNaN), b = Vec3::Constant(kNaN);
};

Vec3 unit_perpendicular(const Vec3& v, const Vec3& t) {
  Vec3 w = v - v.dot(t) * t;
  return w / w.norm();
}

bool finite(const CurveSample& s) { return s.point.allFinite() && s.tangent.allFinite(); }

// A sample without a tangent (no direction at a tangential point) cannot carry a frame: the
// frame then counts as missing, and the estimate reports kInsufficientSamples.
SampleFrame frame_at(std::span<const CurveSample> s, std::size_t k, EstimateCircle kind) {
  SampleFrame f;
  const std::size_t lo = kind == EstimateCircle::kThreePoint && k > 0 ? k - 1 : k;
  for (std::size_t i = lo; i <= k + 1 && i < s.size(); ++i)
    if (!finite(s[i])) return f;
  const Vec3& p = s[k].point;
  const Vec3& t = s[k].tangent;
  Circle c;
  Vec3 towards_centre;
  if (kind == EstimateCircle::kThreePoint) {
    if (k < 1 || k + 1 >= s.size()) return f;
    f.exists = true;
    c = three_point_circle(s[k - 1].point, p, s[k + 1].point);
    if (!c.valid) {
      f.straight = true;
      f.kappa = 0;
      return f;
    }
    towards_centre = c.center - p;
  } else {
    if (k + 1 >= s.size()) return f;
    f.exists = true;
    bool literal = kind == EstimateCircle::kWuAndradeLiteral;
    c = wu_andrade_circle(p, t, s[k + 1].point, s[k + 1].tangent, literal);
    if (!c.valid) {
      // Eq 2.10 with parallel tangents: no turning, zero curvature to rounding.
      f.straight = true;
      f.kappa = (s[k + 1].tangent - t).norm() / (s[k + 1].point - p).norm();
      return f;
    }
    // The literal construction returns the centre reflected through the chord midpoint: P - C'
    // points towards the true centre (thesis ch. 3, eq 3.10).
    towards_centre = literal ? Vec3(p - c.center) : Vec3(c.center - p);
  }
  f.kappa = 1.0 / c.radius;
  f.b = t.cross(unit_perpendicular(towards_centre, t)).normalized();
  f.n = f.b.cross(t);
  return f;
}

}  // namespace

// Thesis ch. 3, eq 3.10 (Wu-Andrade), geometric plane assignment; `literal` swaps the
// points of the first two planes as printed in the thesis.
Circle wu_andrade_circle(const Vec3& p, const Vec3& tp, const Vec3& q, const Vec3& tq, bool literal) {
  Circle c;
  Vec3 w = tp.cross(tq);
  if (!(w.norm() > kParallelSine * tp.norm() * tq.norm())) return c;
  Eigen::Matrix3d m;
  m.row(0) = tp.transpose();
  m.row(1) = tq.transpose();
  m.row(2) = w.transpose();
  Vec3 rhs = literal ? Vec3(tp.dot(q), tq.dot(p), w.dot(p)) : Vec3(tp.dot(p), tq.dot(q), w.dot(p));
  c.center = m.fullPivLu().solve(rhs);
  c.radius = (c.center - p).norm();
  c.valid = c.center.allFinite() && c.radius > 0;
  return c;
}

// Thesis ch. 3, eq 3.7 (Barnhill-Kersey).
double barnhill_kersey_radius(const Vec3& p, const Vec3& q, const Vec3& r) {
  Vec3 a = q - p, b = r - p;
  return a.norm() * b.norm() * (a - b).norm() / (2.0 * a.cross(b).norm());
}

Circle three_point_circle(const Vec3& p, const Vec3& q, const Vec3& r) {
  Circle c;
  Vec3 a = q - p, b = r - p, w = a.cross(b);
  if (!(w.norm() > kParallelSine * a.norm() * b.norm())) return c;
  Eigen::Matrix3d m;
  m.row(0) = a.transpose();
  m.row(1) = b.transpose();
  m.row(2) = w.transpose();
  c.center = p + m.fullPivLu().solve(Vec3(a.dot(a) / 2, b.dot(b) / 2, 0.0));
  c.radius = barnhill_kersey_radius(p, q, r);
  c.valid = c.center.allFinite() && std::isfinite(c.radius);
  return c;
}

// Thesis §2.1 (eqs 2.10-2.12, with the sign caveat of docs/geometry.md) and §3.2 (eq 3.27).
CurveGeometry estimate_from_samples(std::span<const CurveSample> samples, std::size_t index, EstimateCircle circle,
                                    const GeometryTolerances& tol) {
  CurveGeometry g;
  if (index >= samples.size()) {
    g.status = GeometryStatus::kInsufficientSamples;
    return g;
  }
  const CurveSample& here = samples[index];
  g.point = here.point;
  g.t = here.tangent;
  if (!here.point.allFinite() || !here.tangent.allFinite()) {
    g.status = GeometryStatus::kNonFinite;
    return g;
  }
  SampleFrame now = frame_at(samples, index, circle);
  SampleFrame before = index >= 1 ? frame_at(samples, index - 1, circle) : SampleFrame{};
  const SampleFrame& main = now.exists ? now : before;
  if (!main.exists) {
    g.status = GeometryStatus::kInsufficientSamples;
    return g;
  }
  g.kappa = main.kappa;
  if (main.straight || !(g.kappa >= tol.zero_curvature)) {
    g.status = GeometryStatus::kZeroCurvature;
    return g;
  }
  // With only the previous frame, its normal is moved into the normal plane of t.
  g.b = g.t.cross(unit_perpendicular(main.n, g.t)).normalized();
  g.n = g.b.cross(g.t);
  if (!now.exists || !before.exists) {
    g.status = GeometryStatus::kInsufficientSamples;
    return g;
  }
  double chord = (here.point - samples[index - 1].point).norm();
  // Eqs 2.11 and 3.27 divide by the chord, which is the distance between the two frames when the
  // samples are equally spaced (Table 3.3). A Wu-Andrade frame belongs to the middle of its arc,
  // so with unequal steps (a tracer's adaptive ones) the distance between the frames is the mean
  // of the two chords; the literal variant keeps the thesis' chord to reproduce its table.
  if (circle == EstimateCircle::kWuAndrade)
    chord = 0.5 * (chord + (samples[index + 1].point - here.point).norm());
  // A three-point circle belongs to about the mean arc position of its points, so the frames at
  // index and index-1 are a third of the chords from P_index-2 to P_index+1 apart.
  if (circle == EstimateCircle::kThreePoint)
    chord = ((samples[index + 1].point - here.point).norm() + chord +
             (samples[index - 1].point - samples[index - 2].point).norm()) /
            3.0;
  if (before.straight) {
    g.status = GeometryStatus::kZeroCurvature;  // the osculating plane one step back is undefined
    return g;
  }
  double phi = std::atan2(now.b.cross(before.b).norm(), now.b.dot(before.b));
  double tau_abs = 2.0 * std::sin(phi / 2.0) / chord;                          // eq 2.11
  double side = (here.point - samples[index - 1].point).dot(now.b);            // eq 2.12
  g.tau = side > 0 ? tau_abs : (side < 0 ? -tau_abs : 0.0);
  g.kappa_prime = (now.kappa - before.kappa) / chord;                          // eq 3.27
  g.status = GeometryStatus::kOk;
  return g;
}

}  // namespace ssimarch
