#include "ssimarch/trace/tangential_contact.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "ssimarch/march/pole_passage.hpp"
#include "ssimarch/march/tracer.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"
#include "ssimarch/singular/third_order_point.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/trace/trace_tolerances.hpp"
#include "ssimarch/singular/classify.hpp"

namespace ssimarch {

namespace {

// Kernel ratio below which the Hessian of h counts as rank one (a contact curve: h = lambda/2 d^2
// exactly along it, so the ratio is rounding, ~1e-12; at an isolated A_k point near it the ratio
// is the distance to the point times the cubic coefficients, far above this for the step lengths used).
constexpr double kRankOneRatio = 1e-6;

// The eigen-decomposition of the Hessian at the base point: the large eigenvalue's direction
// (across the curve) and the kernel direction (along it).
struct HessianSplit {
  double big = 0, small = 0;
  Vec2 across = Vec2::UnitX(), along = Vec2::UnitY();
};
HessianSplit split(const Eigen::Matrix2d& H) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(H);
  const int b = std::fabs(es.eigenvalues()[1]) >= std::fabs(es.eigenvalues()[0]) ? 1 : 0;
  HessianSplit s;
  s.big = es.eigenvalues()[b];
  s.small = es.eigenvalues()[1 - b];
  s.across = es.eigenvectors().col(b);
  s.along = es.eigenvectors().col(1 - b);
  return s;
}

// The point's data from its local curve (status from the tolerances).
void describe(const Problem& P, const ContactOptions& o, ContactPoint* p) {
  const LocalValue v = evaluate(p->curve.h, Vec2::Zero());
  const HessianSplit s = split(v.hessian);
  p->location.x = p->curve.base;
  p->location.point = p->curve.origin;
  p->location.gap = std::fabs(v.value);
  p->location.sine = v.gradient.norm();
  p->lambda = v.hessian.trace();
  p->kernel_ratio = std::fabs(s.big) > 0 ? std::fabs(s.small) / std::fabs(s.big) : 1.0;
  p->kernel = s.along;
  p->tangent = p->curve.direction_3d(s.along);
  const bool meets = p->location.gap <= o.gap_tolerance * P.scale();
  p->location.status =
      meets && p->location.sine <= o.sine_tolerance ? LocateStatus::kConverged : LocateStatus::kNotSingular;
}

}  // namespace

ContactPoint correct_onto_contact(const Problem& P, const VecX& guess, const ContactOptions& o) {
  ContactPoint p;
  p.location.x = guess;
  VecX x = guess;
  const double floor = 1e-15 * P.scale();
  // A step within the gap tolerance that is no shorter than the one before is rounding: the
  // local curve of a parametric-parametric pair is exact to ~1e-12 only, and Newton there wandered
  // at that level for all max_corrections local curves of every corrected point (a third of the
  // trace of two tori tangent along a circle, 13 local curves per contact point).
  const double rounding = o.gap_tolerance * P.scale();
  double last = std::numeric_limits<double>::infinity();
  for (int k = 0; k < o.max_corrections; ++k) {
    p.curve = local_curve(P, P.wrap(x));
    ++p.location.expansions;
    if (p.curve.status != LocalCurveStatus::kOk) return p;
    const LocalValue v = evaluate(p.curve.h, Vec2::Zero());
    const HessianSplit s = split(v.hessian);
    if (!(std::fabs(s.big) > 0)) return p;
    // Newton on grad h = 0 restricted to the Hessian's range: the minimum-norm step, which moves
    // across the curve and never along it (docs/math/tangential_contact.md §2).
    const Vec2 z = -(s.across.dot(v.gradient) / s.big) * s.across;
    p.location.last_step = z.norm();
    if (!z.allFinite() || z.norm() > 0.1 * P.scale()) return p;
    x = p.curve.unknowns_at(z);
    if (z.norm() <= floor || (z.norm() <= rounding && z.norm() >= last)) break;
    last = z.norm();
  }
  p.curve = local_curve(P, P.wrap(x));
  if (p.curve.status != LocalCurveStatus::kOk) return p;
  describe(P, o, &p);
  return p;
}

bool on_contact_curve(const ContactPoint& p) {
  return p.location.status == LocateStatus::kConverged && p.kernel_ratio <= kRankOneRatio;
}

bool is_contact_point(const ContactPoint& p) {
  return on_contact_curve(p) &&
         classify(p.curve.h, {.length = p.curve.germ_length}).type == SingularType::kTangentialContact;
}

namespace {

// The corrected point at arc distance ds from `from` along the direction `dir` (in from's (s, t)).
ContactPoint advance(const Problem& P, const ContactPoint& from, const Vec2& dir, double ds, const ContactOptions& o) {
  return correct_onto_contact(P, from.curve.unknowns_at(ds * dir), o);
}

// The crossing between a and b (lambda changes sign; b at arc distance ds from a along dir): the
// zero of lambda along the curve by regula falsi (Illinois variant) on the arc parameter. None
// when the sign change is no zero of lambda: |lambda| never falls to kCrossingLambdaRatio of its
// values at a and b (a pole of lambda, where the contact curve passes a singular point of a
// surface: the apex of a cone touched along a generator, whose two nappes lie on either side of
// the plane; docs/math/tangential_contact.md §3).
std::optional<SingularLocation> locate_crossing(const Problem& P, const ContactPoint& a, const ContactPoint& b,
                                                const Vec2& dir, double ds, const ContactOptions& o) {
  double ta = 0, tb = ds, fa = a.lambda, fb = b.lambda;
  SingularLocation best = std::fabs(fa) <= std::fabs(fb) ? a.location : b.location;
  double best_f = std::min(std::fabs(fa), std::fabs(fb));
  int side = 0;
  for (int it = 0; it < 60 && tb - ta > 1e-14 * P.scale(); ++it) {
    const double t = (ta * fb - tb * fa) / (fb - fa);
    const ContactPoint c = advance(P, a, dir, t, o);
    if (c.location.status != LocateStatus::kConverged) break;
    if (std::fabs(c.lambda) < best_f) best_f = std::fabs(c.lambda), best = c.location;
    if ((c.lambda > 0) == (fa > 0)) {
      ta = t, fa = c.lambda;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      tb = t, fb = c.lambda;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
    if (c.lambda == 0) break;
  }
  if (!(best_f <= kCrossingLambdaRatio * std::max(std::fabs(a.lambda), std::fabs(b.lambda)))) return std::nullopt;
  // lambda's zero places the crossing only as well as lambda is known, and the corrected points are
  // worst there (§3): the crossing is refined where h vanishes to third order.
  return third_order_point(P, best, ds).location;
}

struct Half {
  std::vector<CurvePoint> points;
  double length = 0;
  Termination end = Termination::kStepUnderflow;
  std::string message;
  bool closed = false;
};

// True when the chord a -> b passes the start s (a closed contact curve came back).
bool passes(const Vec3& s, const Vec3& a, const Vec3& b, double ds) {
  const Vec3 c = b - a;
  const double L2 = c.squaredNorm(), along = (s - a).dot(c);
  if (!(L2 > 0) || along < 0 || along > L2) return false;
  return (s - a - (along / L2) * c).norm() <= 0.05 * ds;
}

// A slack for Problem::inside as a fraction of the narrowest bounded unknown's range: an absolute
// slack of 1e-7 let a contact line on a cone scaled by 1e-6 run 3 % past its range (issue 26).
double slack(const Problem& P, double fraction) {
  double width = std::numeric_limits<double>::infinity();
  for (int i = 0; i < P.dim(); ++i)
    if (!(P.periods()[static_cast<std::size_t>(i)] > 0))
      width = std::min(width, P.bounds()[static_cast<std::size_t>(i)].width());
  return fraction * (std::isfinite(width) && width > 0 ? width : P.scale());
}

// The first bound of the domain the unknowns' chord from -> to crosses: the fraction of the chord
// where it does, and the unknown (-1: none; periodic unknowns have no bound).
std::pair<double, int> first_exit(const Problem& P, const VecX& from, const VecX& to) {
  const VecX d = P.difference(from, to);
  std::pair<double, int> out{1.0, -1};
  for (int i = 0; i < P.dim(); ++i) {
    const Interval& B = P.bounds()[static_cast<std::size_t>(i)];
    if (P.periods()[static_cast<std::size_t>(i)] > 0 || d[i] == 0) continue;
    const double x = from[i], bound = d[i] > 0 ? B.hi : B.lo;
    if ((x + d[i] - bound) * (d[i] > 0 ? 1 : -1) > 0 && (bound - x) / d[i] <= out.first) out = {(bound - x) / d[i], i};
  }
  return out;
}

// The contact point where the march leaves the domain, between cur (inside) and next (outside):
// first the fraction of the step where the unknowns' chord leaves; when the corrected point there
// is not on the contact curve inside the domain (the corrector moves it off the chord: cylinder on a
// plane traced parametric-parametric stopped 0.021 short of its edge, and a second start in that gap
// traced the line again), the fraction is bisected on the corrected points until the bracket is
// at rounding level of the step, so the end lies on the bound. None when nothing lands.
std::optional<ContactPoint> land_on_bound(const Problem& P, const ContactPoint& cur, const ContactPoint& next,
                                          const Vec2& dir, double ds, const ContactOptions& o) {
  const double f = first_exit(P, cur.location.x, next.location.x).first;
  ContactPoint edge = advance(P, cur, dir, f * ds, o);
  if (on_contact_curve(edge) && P.inside(edge.location.x, slack(P, 1e-7))) return edge;
  std::optional<ContactPoint> landed;
  double lo = 0, hi = 1;
  while (hi - lo > 4 * std::numeric_limits<double>::epsilon()) {
    const double mid = 0.5 * (lo + hi);
    ContactPoint p = advance(P, cur, dir, mid * ds, o);
    if (on_contact_curve(p) && P.inside(p.location.x, 0)) {
      lo = mid;
      landed = std::move(p);
    } else {
      hi = mid;
    }
  }
  return landed;
}

// A step of the contact march that left the domain over a pole (a degenerate edge mapped to one
// point, march/pole_passage.hpp) when the contact curve goes through that point: the curve is one
// curve through the pole, as a transversal curve is (docs/math/poles.md). The continuation is the
// contact point about ds beyond the pole, found from the mirror of cur across it in the pole's
// chart; empty when there is none (the curve ends at the edge).
struct PoleCrossing {
  CurvePoint at_pole;
  ContactPoint beyond;
};
std::optional<PoleCrossing> cross_pole(const Problem& P, const std::vector<Pole>& poles, const ContactPoint& cur,
                                       const VecX& next_x, const Vec3& travel, double ds, const ContactOptions& o) {
  const auto [fraction, unknown] = first_exit(P, cur.location.x, next_x);
  if (unknown < 0) return std::nullopt;
  const Interval& B = P.bounds()[static_cast<std::size_t>(unknown)];
  for (const Pole& pole : poles) {
    const double bound = pole.upper ? B.hi : B.lo;
    if (pole.unknown != unknown || pole.value != bound) continue;
    const Vec3 to_pole = pole.point - cur.location.point;
    if (to_pole.norm() > 1.5 * ds || to_pole.dot(travel) < 0) return std::nullopt;
    const Vec3 q = pole.point + std::max(to_pole.norm(), 0.25 * ds) * travel;
    ContactPoint beyond = correct_onto_contact(P, unknowns_beyond_pole(P, pole, cur.location.x, q), o);
    const Vec3 past = beyond.location.point - pole.point;
    if (!on_contact_curve(beyond) || !P.inside(beyond.location.x, slack(P, 1e-9)) || past.dot(travel) <= 0 ||
        (beyond.location.point - q).norm() > 0.5 * (q - pole.point).norm())
      return std::nullopt;
    VecX x = cur.location.x;
    x[pole.unknown] = pole.value;
    const Vec3 t = (past.normalized() + to_pole.normalized()).normalized();  // the chords' bisector
    return PoleCrossing{CurvePoint{x, pole.point, t.allFinite() ? t : travel}, std::move(beyond)};
  }
  return std::nullopt;
}

// Marches from `start` along `sign` * its kernel direction until closure, the domain edge, the
// point budget or a failed correction; crossings are appended.
Half march_contact(const Problem& P, const ContactPoint& start, double sign, double step, const ContactOptions& o,
                   std::vector<SingularLocation>* crossings) {
  Half out;
  const std::vector<Pole> poles = problem_poles(P);
  ContactPoint cur = start;
  Vec3 travel = sign * start.tangent;
  out.points.push_back({cur.location.x, cur.location.point, travel});
  double ds = step;
  while (static_cast<long>(out.points.size()) < o.max_points) {
    const Vec2 dir = cur.kernel * (cur.tangent.dot(travel) >= 0 ? 1.0 : -1.0);
    ContactPoint next = advance(P, cur, dir, ds, o);
    const double chord = (next.location.point - cur.location.point).norm();
    if (!on_contact_curve(next) || chord < 0.5 * ds || chord > 1.5 * ds ||
        (next.location.point - cur.location.point).dot(travel) <= 0) {
      ds *= 0.5;
      if (ds >= 1e-6 * step) continue;
      out.end = Termination::kStepUnderflow;
      out.message = "the curve of tangential contact ends at " + describe_point(cur.location.point);
      return out;
    }
    if (!P.inside(next.location.x, slack(P, 1e-9))) {
      // A curve started on the domain's edge (a pole) comes back to it there: closed.
      const Vec3 to_start = start.location.point - cur.location.point;
      if (out.points.size() >= 3 && to_start.norm() <= 1.5 * ds && to_start.dot(travel) > 0) {
        out.length += arc_length_estimate(cur.location.point, travel, start.location.point, sign * start.tangent);
        out.points.push_back({start.location.x, start.location.point, sign * start.tangent});
        out.closed = true;
        out.end = Termination::kClosedLoop;
        return out;
      }
      if (auto pass = cross_pole(P, poles, cur, next.location.x, travel, ds, o)) {
        const Vec3 t_beyond = (pass->beyond.location.point - pass->at_pole.p).normalized();
        out.length += arc_length_estimate(cur.location.point, travel, pass->at_pole.p, pass->at_pole.t) +
                      arc_length_estimate(pass->at_pole.p, pass->at_pole.t, pass->beyond.location.point, t_beyond);
        out.points.push_back(pass->at_pole);
        out.points.push_back({pass->beyond.location.x, pass->beyond.location.point, t_beyond});
        travel = t_beyond;
        cur = std::move(pass->beyond);
        continue;
      }
      const std::optional<ContactPoint> edge = land_on_bound(P, cur, next, dir, ds, o);
      out.end = Termination::kLeftDomain;
      out.message = "the curve of tangential contact leaves the domain at " + describe_point(cur.location.point);
      if (edge) {
        // The arc, not the chord, to the edge point (with the curve's tangent there): a chord of
        // length c on a curve of curvature k falls short by k^2 c^3 / 24 (1.7e-6 at each end of
        // bug25950's contact circle, whose march lands on the sphere's pole from both sides).
        const Vec3 t_edge = edge->tangent * (edge->tangent.dot(travel) >= 0 ? 1.0 : -1.0);
        out.length += arc_length_estimate(cur.location.point, travel, edge->location.point, t_edge);
        out.points.push_back({edge->location.x, edge->location.point, t_edge});
        out.message = "the curve of tangential contact leaves the domain at " + describe_point(edge->location.point);
      }
      return out;
    }
    if ((next.lambda > 0) != (cur.lambda > 0))
      if (auto c = locate_crossing(P, cur, next, dir, ds, o)) crossings->push_back(std::move(*c));
    const Vec3 t_next = next.tangent * (next.tangent.dot(next.location.point - cur.location.point) >= 0 ? 1.0 : -1.0);
    if (out.points.size() >= 3 && passes(start.location.point, cur.location.point, next.location.point, ds)) {
      out.length += arc_length_estimate(cur.location.point, travel, start.location.point, sign * start.tangent);
      out.points.push_back({start.location.x, start.location.point, sign * start.tangent});
      out.closed = true;
      out.end = Termination::kClosedLoop;
      return out;
    }
    out.length += arc_length_estimate(cur.location.point, travel, next.location.point, t_next);
    out.points.push_back({next.location.x, next.location.point, t_next});
    travel = t_next;
    cur = std::move(next);
    ds = std::min(step, 2 * ds);
  }
  out.end = Termination::kMaxPoints;
  out.message = "reached max_points on the curve of tangential contact";
  return out;
}

}  // namespace

std::optional<SingularLocation> crossing_near(const Problem& P, const VecX& x, double radius, const ContactOptions& o) {
  const ContactPoint start = correct_onto_contact(P, x, o);
  if (!on_contact_curve(start)) return std::nullopt;
  constexpr int kSteps = 8;  // sub-steps per direction: a crossing is a sign change of lambda between two
  const double ds = radius / kSteps;
  std::optional<SingularLocation> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (double sign : {1.0, -1.0}) {
    ContactPoint cur = start;
    Vec3 travel = sign * start.tangent;
    for (int i = 0; i < kSteps; ++i) {
      const Vec2 dir = cur.kernel * (cur.tangent.dot(travel) >= 0 ? 1.0 : -1.0);
      ContactPoint next = advance(P, cur, dir, ds, o);
      if (!on_contact_curve(next)) break;
      if ((next.lambda > 0) != (cur.lambda > 0)) {
        const std::optional<SingularLocation> c = locate_crossing(P, cur, next, dir, ds, o);
        if (!c) break;
        const double d = (c->point - start.location.point).norm();
        if (d < best_distance) best_distance = d, best = c;
        break;
      }
      travel = next.tangent * (next.tangent.dot(next.location.point - cur.location.point) >= 0 ? 1.0 : -1.0);
      cur = std::move(next);
    }
  }
  return best;
}

std::optional<SingularAnalysis> crossing_behind_node(const Problem& P, const SingularAnalysis& node, double merge,
                                                     const SingularAnalysisOptions& options) {
  if (!node.analysed() || node.kind.type != SingularType::kNode) return std::nullopt;
  const ThirdOrderPoint t = third_order_point(P, node.location, third_order_reach(node, merge));
  if (!(t.hessian_norm <= kThirdOrderHessianFall * t.initial_hessian_norm)) return std::nullopt;
  SingularAnalysis a = analyse_singular_point(P, t.location, options);
  if (!a.analysed() || a.kind.multiplicity < 3) return std::nullopt;
  return a;
}

ContactTrace trace_tangential_contact(const Problem& P, const VecX& x0, const ContactOptions& o) {
  ContactTrace out;
  const ContactPoint start = correct_onto_contact(P, x0, o);
  if (!is_contact_point(start) || !P.inside(start.location.x, slack(P, 1e-9))) return out;
  const double step = o.step > 0 ? o.step : P.scale() / 100;
  Half forward = march_contact(P, start, 1.0, step, o, &out.crossings);
  TracedCurve& c = out.curve;
  c.tangential_contact = true;
  if (forward.closed) {
    c.points = std::move(forward.points);
    c.closed = true;
    c.length = forward.length;
    return out;
  }
  Half backward = march_contact(P, start, -1.0, step, o, &out.crossings);
  for (auto it = backward.points.rbegin(); it != backward.points.rend(); ++it)
    c.points.push_back({it->x, it->p, -it->t});
  c.points.insert(c.points.end(), forward.points.begin() + 1, forward.points.end());
  c.length = forward.length + backward.length;
  // Both halves stopped at one point of the domain's edge (a pole the curve passes, or a seam):
  // the ends meet, the curve is closed.
  const double meet = 1e-9 * P.scale();
  c.closed = forward.end == Termination::kLeftDomain && backward.end == Termination::kLeftDomain &&
             c.points.size() > 3 && (c.points.front().p - c.points.back().p).norm() <= meet;
  if (c.closed) {
    c.points.back() = c.points.front();
    return out;
  }
  c.start_end = backward.end;
  c.start_message = backward.message;
  c.end_end = forward.end;
  c.end_message = forward.message;
  return out;
}

}  // namespace ssimarch
