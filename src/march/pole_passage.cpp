#include "ssimarch/march/pole_passage.hpp"

#include <algorithm>
#include <cmath>

#include "march_steps.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

namespace {

using J1 = Jet<1, 1>;

const Surface& surface_of(const Problem& P, int index) { return index == 0 ? P.first() : P.second(); }

// The parameter range along the edge and the derivative of F across it at w, pointing into the
// domain (docs/math/poles.md, eq. (2)): the direction in which the meridian w leaves P.
const Interval& along_range(const Problem& P, const Pole& pole) {
  return P.bounds()[static_cast<std::size_t>(pole.along)];
}
Vec3 inward_direction(const Problem& P, const Pole& pole, double w) {
  const Surface& s = surface_of(P, pole.surface);
  const bool edge_in_u = pole.unknown == 2 * pole.surface;  // u is constant on the edge
  Vec3T<J1> f = edge_in_u ? s.point(J1::variable(0, pole.value), J1(w)) : s.point(J1(w), J1::variable(0, pole.value));
  const Vec3 d(f.x.d(0), f.y.d(0), f.z.d(0));
  return pole.upper ? Vec3(-d) : d;
}

// The limit normal of the pole's surface at P: the normal of the plane the inward directions
// span (eq. (3)); zero when they do not span one (a cone's apex: no tangent plane).
Vec3 limit_normal(const Problem& P, const Pole& pole) {
  const Interval& w = along_range(P, pole);
  Vec3 best = Vec3::Zero();
  const Vec3 d0 = inward_direction(P, pole, w.lo);
  for (int i = 1; i < 8; ++i) {
    const Vec3 c = d0.cross(inward_direction(P, pole, w.lo + w.width() * i / 8));
    if (c.norm() > best.norm()) best = c;
  }
  if (!(best.norm() > 0)) return Vec3::Zero();
  best.normalize();
  // A tangent plane exists only when every inward direction lies in it.
  for (int i = 0; i < 16; ++i) {
    const Vec3 d = inward_direction(P, pole, w.lo + w.width() * (i + 0.5) / 16);
    if (std::fabs(best.dot(d)) > 1e-8 * d.norm()) return Vec3::Zero();
  }
  return best;
}

// The other surface at P: its unknowns (parametric) and its unit normal; distance of P from it.
struct OtherSide {
  Vec2 params = Vec2::Zero();
  Vec3 normal = Vec3::Zero();
  double distance = 0;
};
OtherSide other_side(const Problem& P, const Pole& pole, const UnknownVec& x, const Vec3& p) {
  OtherSide o;
  const Surface& g = surface_of(P, 1 - pole.surface);
  if (P.kind() == PairKind::kParametricImplicit) {
    Vec3T<Jet<3, 1>> X(Jet<3, 1>::variable(0, p.x()), Jet<3, 1>::variable(1, p.y()), Jet<3, 1>::variable(2, p.z()));
    const Jet<3, 1> v = g.value(X);
    const Vec3 grad(v.d(0), v.d(1), v.d(2));
    o.normal = grad.norm() > 0 ? Vec3(grad.normalized()) : Vec3::Zero();
    o.distance = grad.norm() > 0 ? std::fabs(v.value()) / grad.norm() : std::fabs(v.value());
    return o;
  }
  const int first = 2 * (1 - pole.surface);
  o.params = refine_closest_parameters(g, p, Vec2(x[first], x[first + 1]));
  Vec3T<Jet<2, 1>> f = g.point(Jet<2, 1>::variable(0, o.params[0]), Jet<2, 1>::variable(1, o.params[1]));
  const Vec3 q(f.x.value(), f.y.value(), f.z.value());
  const Vec3 n = Vec3(f.x.d(0), f.y.d(0), f.z.d(0)).cross(Vec3(f.x.d(1), f.y.d(1), f.z.d(1)));
  o.normal = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
  o.distance = (q - p).norm();
  return o;
}

// The meridian w whose inward direction is closest to the unit vector `dir` (eq. (4)): the best
// of 64 samples, refined by golden-section search on the bracket around it.
double exit_meridian(const Problem& P, const Pole& pole, const Vec3& dir) {
  const Interval& w = along_range(P, pole);
  auto score = [&](double t) { return inward_direction(P, pole, t).normalized().dot(dir); };
  constexpr int kSamples = 64;
  const double dw = w.width() / kSamples;
  double best = w.lo, best_score = -2;
  for (int i = 0; i <= kSamples; ++i) {
    const double t = w.lo + dw * i, s = score(t);
    if (s > best_score) best = t, best_score = s;
  }
  const bool periodic = P.periods()[static_cast<std::size_t>(pole.along)] > 0;
  double a = best - dw, b = best + dw;
  if (!periodic) a = std::max(a, w.lo), b = std::min(b, w.hi);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (score(c) > score(d)) b = d;
    else a = c;
  }
  return 0.5 * (a + b);
}

// Unknowns whose 3D point is near q (|q - P| small, q beyond the pole along `dir`): the pole
// surface in the chart of the exit meridian (eq. (5)), the other surface by its nearest point.
UnknownVec chart_unknowns(const Problem& P, const Pole& pole, const UnknownVec& x, const Vec3& q, const OtherSide& other) {
  UnknownVec y = x;
  const Vec3 off = q - pole.point;
  const double w = exit_meridian(P, pole, off.normalized());
  const double speed = inward_direction(P, pole, w).norm();
  const double step = speed > 0 ? off.norm() / speed : 0.0;
  y[pole.along] = w;
  y[pole.unknown] = pole.value + (pole.upper ? -step : step);
  const int first = 2 * pole.surface;
  const Vec2 uv = refine_closest_parameters(surface_of(P, pole.surface), q, Vec2(y[first], y[first + 1]));
  y[first] = uv[0];
  y[first + 1] = uv[1];
  if (P.kind() == PairKind::kParametricParametric) {
    const int o = 2 * (1 - pole.surface);
    const Vec2 pq = refine_closest_parameters(surface_of(P, 1 - pole.surface), q, other.params);
    y[o] = pq[0];
    y[o + 1] = pq[1];
  }
  return y;
}

// The corrected curve point from the chart unknowns y, if it lies beyond the pole along dir and
// within half of `distance` of the target q.
std::optional<CurvePoint> corrected_beyond(const Problem& P, const Pole& pole, const UnknownVec& y, const Vec3& q,
                                           const Vec3& dir, double distance, const CorrectorOptions& co) {
  // Corrected in the plane through q normal to dir (Allgower & Georg's pseudo-arclength
  // corrector): a free minimum-norm correction near the pole slides along the badly scaled
  // parameter towards P, the plane keeps the point at its distance beyond P.
  const CorrectorResult c = solve_on_plane(P, y, dir, dir.dot(q), co);
  if (c.status != CorrectorStatus::kConverged || !P.inside(c.x)) return std::nullopt;
  const Vec3 p = P.point(c.x);
  if ((p - q).norm() > 0.5 * distance || (p - pole.point).dot(dir) <= 0) return std::nullopt;
  const DynamicCurveJet j = curve_jet_dynamic(P, c.x, 1, &dir);
  if (j.status != CurveJetStatus::kOk) return std::nullopt;
  return CurvePoint{c.x, p, j.tangent()};
}

// The tangent of the curve at P: N_F x N_G oriented along `along` (eq. (1)); where the two
// normals are (nearly) parallel or N_F is undefined, `along` with its normal part removed.
Vec3 tangent_at_pole(const Vec3& nf, const Vec3& ng, const Vec3& along) {
  Vec3 t = nf.cross(ng);
  if (t.norm() < 1e-6) t = along - along.dot(nf) * nf;
  if (!(t.norm() > 0)) return along;
  t.normalize();
  return t.dot(along) < 0 ? Vec3(-t) : t;
}

}  // namespace

PolePassage pass_pole(const Problem& P, const Pole& pole, const CurvePoint& cur, double distance,
                      const CorrectorOptions& co) {
  PolePassage r;
  const OtherSide other = other_side(P, pole, cur.x, pole.point);
  const double pass_tolerance = std::max(10 * co.tolerance, 1e-12 * P.scale());
  r.through = other.distance <= pass_tolerance;
  Vec3 q, dir;
  if (r.through) {
    const Vec3 t = tangent_at_pole(limit_normal(P, pole), other.normal, cur.t);
    UnknownVec x = cur.x;
    x[pole.unknown] = pole.value;
    if (P.kind() == PairKind::kParametricParametric) x.segment(2 * (1 - pole.surface), 2) = other.params;
    r.at_pole = CurvePoint{x, pole.point, t};
    q = pole.point + distance * t;
    dir = t;
  } else {
    const double ahead = (pole.point - cur.p).dot(cur.t);
    q = cur.p + 2 * std::max(ahead, distance) * cur.t;
    dir = cur.t;
  }
  const UnknownVec y = chart_unknowns(P, pole, cur.x, q, other);
  if (auto b = corrected_beyond(P, pole, y, q, dir, distance, co)) {
    r.ok = true;
    r.beyond = *b;
  } else {
    r.message = "found no curve point beyond the pole at " + describe_point(pole.point);
  }
  return r;
}

std::optional<CurvePoint> leave_pole(const Problem& P, const Pole& pole, const UnknownVec& x, double distance,
                                     const CorrectorOptions& co) {
  const OtherSide other = other_side(P, pole, x, pole.point);
  const Vec3 nf = limit_normal(P, pole);
  const Vec3 t = nf.cross(other.normal);
  if (t.norm() < 1e-6) return std::nullopt;
  const Vec3 dir = t.normalized();
  const Vec3 q = pole.point + distance * dir;
  return corrected_beyond(P, pole, chart_unknowns(P, pole, x, q, other), q, dir, distance, co);
}

UnknownVec unknowns_beyond_pole(const Problem& P, const Pole& pole, const UnknownVec& x, const Vec3& q) {
  return chart_unknowns(P, pole, x, q, other_side(P, pole, x, pole.point));
}

}  // namespace ssimarch
