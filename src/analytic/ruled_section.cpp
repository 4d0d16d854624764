// docs/math/closed_form_quadrics.md, "Along the rulings": the roots of the discriminant and the
// loops they bound.
#include "ssimarch/analytic/ruled_section.hpp"

#include <numbers>
#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/analytic/trig_polynomial.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"

namespace ssimarch {

namespace {

constexpr int kGrid = 96;  // samples per turn for the scales of Delta and a (degree 2: smooth on this grid)
// |theta - tau| (radians) within which a point is at the crossing tau: the crossing's own sample
// (ruled_pieces.cpp, add_crossings) maps to tau up to rounding.
constexpr double kCrossingParameter = 1e-12;
constexpr double kJetDiscriminant = 1e-8;  // |Delta| relative to its terms above which its jet is trusted

Eigen::Vector4d point4(const Vec3& p, double w) { return {p.x(), p.y(), p.z(), w}; }

constexpr int kBisections = 200;  // enough to reach adjacent doubles from any bracket in [0, 4 pi]

// A root of a function on [lo, hi] where it changes sign (bisection to adjacent doubles).
template <class F>
double bisect(const F& f, double lo, double hi) {
  double flo = f(lo);
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    const double fm = f(mid);
    if ((fm < 0) == (flo < 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

// Delta and its first two derivatives at theta.
struct DiscriminantJet {
  double value, first, second;
};

double wrap_angle(double theta) { return theta - (2 * std::numbers::pi) * std::floor(theta / (2 * std::numbers::pi)); }

// A check of the root finding: Delta is >= 0 (to `zero`) along every loop, so every point is
// real. False (the caller traces instead) if a critical point of Delta was missed.
template <class F>
bool covers_no_gap(const RuledSection& s, const F& disc, double zero) {
  for (const RuledLoop& loop : s.loops)
    for (int k = 0; k < 4 * kGrid; ++k) {
      const double phi = loop.period() * (k + 0.5) / (4 * kGrid);
      const double theta = loop.arc ? 0.5 * (loop.lo + loop.hi) - 0.5 * (loop.hi - loop.lo) * std::cos(phi) : loop.lo + phi;
      if (disc(theta) < -zero) return false;
    }
  return true;
}

}  // namespace

std::optional<Rulings> rulings_of(const Surface& surface) {
  Rulings r;
  if (const auto* c = surface.get_if<Cylinder>()) {
    // X = o + r cos e0 + r sin e1 + t e2 (surface/cylinder.hpp).
    const Frame& f = c->frame();
    r.a = {point4(f.origin, 1), point4(c->radius() * f.e0, 0), point4(c->radius() * f.e1, 0)};
    r.d = {point4(f.e2, 0), Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()};
    return r;
  }
  if (const auto* k = surface.get_if<Cone>()) {
    // X = o + t (tan(alpha) (cos e0 + sin e1) + e2) (surface/cone.hpp): every ruling through the apex.
    const Frame& f = k->frame();
    const double tn = std::tan(k->half_angle());
    r.a = {point4(f.origin, 1), Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()};
    r.d = {point4(f.e2, 0), point4(tn * f.e0, 0), point4(tn * f.e1, 0)};
    r.cone = true;
    return r;
  }
  return std::nullopt;
}

double RuledLoop::period() const { return arc ? (2 * std::numbers::pi) : (2 * std::numbers::pi) * turns; }

Vec3 RuledCurves::double_root_point(double theta) const {
  const auto [a, b, c] = quadratic(theta);
  const double t = std::fabs(a) >= std::fabs(b) ? -b / (2 * a) : -2 * c / b;
  const Vec3T<double> p = on_ruling(theta, t);
  return {p.x, p.y, p.z};
}

double RuledCurves::root_sign(const RuledLoop& loop, double phi) const {
  double sign = loop.arc ? (std::sin(phi) >= 0 ? 1.0 : -1.0) : loop.sign;
  const double th = loop.arc ? 0.5 * (loop.lo + loop.hi) - 0.5 * (loop.hi - loop.lo) * std::cos(phi) : loop.lo + phi;
  for (double tau : loop.switches)
    sign *= loop.arc ? (th >= tau ? 1.0 : -1.0) : (std::sin(0.5 * (th - tau)) >= 0 ? 1.0 : -1.0);
  return sign;
}

namespace {

// d point / d phi at a crossing tau where `loop` changes sheet (Delta(tau) = 0 < Delta''(tau)):
// the signed root S = sign sqrt(Delta) is smooth there with dS/dtheta = s sqrt(Delta''/2), s its
// sign just past tau, so t = (-b + S) / 2a has an exact jet. A difference of sqrt(Delta) across
// tau does not: at a step h, Delta ~ Delta'' h^2 / 2 may round to 0 on both sides, which puts both
// points between the two sheets and gives the bisector of the two branches (edges of the Levin
// pencil's ellipses 1.1e-3 too long, issue 13). None when phi is not at such a crossing.
std::optional<Vec3> crossing_derivative(const RuledCurves& rc, const RuledLoop& loop, double phi) {
  const Taylor<1> theta = loop.arc ? 0.5 * (loop.lo + loop.hi) - 0.5 * (loop.hi - loop.lo) * cos(Taylor<1>::variable(0, phi))
                                   : loop.lo + Taylor<1>::variable(0, phi);
  for (double tau : loop.switches) {
    if (!(std::fabs(std::remainder(theta[0] - tau, (2 * std::numbers::pi))) <= kCrossingParameter)) continue;
    const auto [a2, b2, c2] = rc.quadratic(Taylor<2>::variable(0, tau));
    const double second = 2 * (b2 * b2 - 4.0 * a2 * c2)[2];  // Delta''(tau)
    if (!(second > 0) || theta[1] == 0) return std::nullopt;
    // The sign just past tau (theta > tau): a step along phi in the direction theta increases.
    const double s = rc.root_sign(loop, phi + (theta[1] > 0 ? 1 : -1) * 1e3 * kCrossingParameter / std::fabs(theta[1]));
    const Taylor<1> S = s * std::sqrt(0.5 * second) * (theta - tau);
    const auto [a, b, c] = rc.quadratic(theta);
    const Taylor<1> t = b[0] * s > 0 ? Taylor<1>(2.0 * c / (-b - S)) : Taylor<1>((-b + S) / (2.0 * a));
    const Vec3T<Taylor<1>> p = rc.on_ruling(theta, t);
    const Vec3 d(p.x[1], p.y[1], p.z[1]);
    if (d.allFinite()) return d;
  }
  return std::nullopt;
}

}  // namespace

Vec3 RuledCurves::derivative(const RuledLoop& loop, double phi) const { return point_and_derivative(loop, phi).second; }

std::pair<Vec3, Vec3> RuledCurves::point_and_derivative(const RuledLoop& loop, double phi) const {
  if (const auto d = crossing_derivative(*this, loop, phi)) {
    const Vec3T<double> p = point(loop, phi);
    return {Vec3(p.x, p.y, p.z), *d};
  }
  // Jets in phi are exact where Delta is well away from 0; at and next to its roots (the turning
  // points, the crossings) sqrt(Delta)'s jet is 0/0 and rounding decides it, so there a central
  // difference of the (analytic) loop: its error is O(h^2) ~ 1e-10 relative.
  const double theta = loop.arc ? 0.5 * (loop.lo + loop.hi) - 0.5 * (loop.hi - loop.lo) * std::cos(phi) : loop.lo + phi;
  const auto [a, b, c] = quadratic(theta);
  if (std::fabs(b * b - 4 * a * c) > kJetDiscriminant * (b * b + 4 * std::fabs(a * c))) {
    const Vec3T<Taylor<1>> p = point(loop, Taylor<1>::variable(0, phi));
    const Vec3 d(p.x[1], p.y[1], p.z[1]);
    if (d.allFinite()) return {Vec3(p.x[0], p.y[0], p.z[0]), d};
  }
  const double h = 1e-5;
  const Vec3T<double> here = point(loop, phi), ahead = point(loop, phi + h), behind = point(loop, phi - h);
  return {Vec3(here.x, here.y, here.z), Vec3(ahead.x - behind.x, ahead.y - behind.y, ahead.z - behind.z) / (2 * h)};
}

namespace {

// The loops of a section whose crossings are known: between consecutive simple roots of Delta
// where Delta > 0, or, without simple roots, the whole circle once or twice (a closed curve that
// changes sheet an odd number of times runs round twice). A crossing changes sheet where the root
// has multiplicity 2 (Delta'' > 0); at a root of multiplicity 4 the square root keeps its sign.
void add_loops(RuledSection* out, std::vector<double> simple, const TrigPolynomial& delta, const TrigPolynomial& delta2,
               double zero) {
  std::vector<double> switching;
  for (double t : out->crossings)
    if (delta2(t) > zero) switching.push_back(t);
  std::sort(simple.begin(), simple.end());
  if (simple.empty()) {
    const int k = static_cast<int>(switching.size());
    RuledLoop loop;
    loop.arc = false;
    loop.lo = 0;
    loop.switches = switching;
    loop.turns = k % 2 == 0 ? 1 : 2;
    out->loops.push_back(loop);
    if (k % 2 == 0) {
      loop.sign = -1;
      out->loops.push_back(loop);
    }
    return;
  }
  for (std::size_t i = 0; i < simple.size(); ++i) {
    const double lo = simple[i], hi = i + 1 < simple.size() ? simple[i + 1] : simple[0] + (2 * std::numbers::pi);
    if (!(delta(0.5 * (lo + hi)) > 0)) continue;
    RuledLoop loop;
    loop.lo = lo;
    loop.hi = hi;
    for (double t : switching) {
      const double u = t < lo ? t + (2 * std::numbers::pi) : t;
      if (u > lo && u < hi) loop.switches.push_back(u);
    }
    out->loops.push_back(loop);
  }
}

}  // namespace

std::optional<RuledSection> RuledCurves::section() const {
  // a, b, c and Delta = b^2 - 4 a c as trigonometric polynomials in theta (a, c: quadratic forms
  // of the rulings' A and D, degree 2; b: a bilinear one): exact coefficients, so the roots and
  // critical points of Delta are those of a polynomial of degree <= 4 in e^{i theta}.
  const TrigPolynomial qa = bilinear_form(r_.d, q_, r_.d), qb = 2.0 * bilinear_form(r_.d, q_, r_.a),
                       qc = bilinear_form(r_.a, q_, r_.a);
  const TrigPolynomial delta = qb * qb - 4.0 * (qa * qc), delta1 = delta.derivative(), delta2 = delta1.derivative();
  auto disc = [&](double th) { return delta(th); };
  auto direct = [&](double th) {
    const auto [a, b, c] = quadratic(th);
    return b * b - 4 * a * c;
  };
  auto disc_jet = [&](double th) { return DiscriminantJet{delta(th), delta1(th), delta2(th)}; };
  // Scales: of Delta's terms, and of a (for "a ruling meets Q once": a = 0 somewhere).
  double scale = 0, a_min = std::numeric_limits<double>::infinity(), a_max = 0, c_max = 0;
  for (int k = 0; k < kGrid; ++k) {
    const double th = (2 * std::numbers::pi) * k / kGrid;
    const double a = qa(th), b = qb(th), c = qc(th);
    scale = std::max(scale, b * b + 4 * std::fabs(a * c));
    a_min = std::min(a_min, std::fabs(a));
    a_max = std::max(a_max, std::fabs(a));
    c_max = std::max(c_max, std::fabs(c));
  }
  if (!(scale > 0) || !std::isfinite(scale)) return std::nullopt;  // Q vanishes on the surface
  // a keeps one sign (of degree 2 on a cone, it may cross 0 between the grid's samples), and its
  // smallest |a| includes its critical points, where a touching zero hides between samples.
  if (!trig_sign_changes(qa).empty()) return std::nullopt;
  for (double th : trig_sign_changes(qa.derivative())) a_min = std::min(a_min, std::fabs(qa(th)));
  if (!(a_min > kClosedFormDegeneracy * a_max) || a_max == 0) return std::nullopt;
  // c is constant on a cone (A^T Q A at the apex): zero when the apex lies on Q, where every
  // ruling has the root t = 0 and the curve passes through the apex.
  if (r_.cone && 4 * a_max * c_max <= kClosedFormDegeneracy * scale) return std::nullopt;
  const double zero = kClosedFormDegeneracy * scale;

  // Critical points of Delta: the sign changes of Delta' (trig_polynomial.hpp).
  std::vector<double> crit = trig_sign_changes(delta1);
  crit.erase(std::unique(crit.begin(), crit.end(), [](double x, double y) { return y - x < 1e-13; }), crit.end());
  if (crit.size() > 1 && crit.back() - crit.front() > (2 * std::numbers::pi) - 1e-13)
    crit.pop_back();  // one point, both ends

  RuledSection out;
  out.scale = scale;
  out.zero = zero;
  std::vector<double> simple;
  double max_value = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < crit.size(); ++i) {
    const DiscriminantJet j = disc_jet(crit[i]);
    max_value = std::max(max_value, j.value);
    if (std::fabs(j.value) <= zero) {
      if (j.second > zero) out.crossings.push_back(crit[i]);      // a minimum touching 0: branches meet
      else if (j.second < -zero) out.isolated.push_back(crit[i]);  // a maximum touching 0: an isolated point
      else out.crossings.push_back(crit[i]);                       // a root of multiplicity >= 4 (tacnode)
    }
    // A simple root between this critical point and the next (Delta is monotone there).
    const double a = crit[i], b = i + 1 < crit.size() ? crit[i + 1] : crit[0] + (2 * std::numbers::pi);
    const double da = j.value, db = disc(b);
    // The ends of a loop are where the points' own Delta (b^2 - 4ac of quadratic(), which
    // point() evaluates) vanishes: bisected on it, not on the coefficient form, whose rounding
    // differs by ~eps times Delta's terms — a shift the square root turns into a gap of
    // sqrt(shift) between a loop's two halves at its ends (OCCT bug28222_3: 1e-7).
    if ((da > zero && db < -zero) || (da < -zero && db > zero)) simple.push_back(wrap_angle(bisect(direct, a, b)));
  }
  if (crit.empty()) max_value = disc(0.0);
  if (!(max_value > zero)) {
    // Delta <= 0 everywhere: no curve, at most isolated points; Delta == 0 throughout: the
    // surfaces touch along a curve (not a closed form here).
    if (crit.empty() || std::all_of(crit.begin(), crit.end(), [&](double t) { return std::fabs(disc(t)) <= zero; }))
      return std::nullopt;
    out.crossings.clear();
    return out;
  }
  add_loops(&out, std::move(simple), delta, delta2, zero);
  return covers_no_gap(out, disc, zero) ? std::optional<RuledSection>(out) : std::nullopt;
}

}  // namespace ssimarch
