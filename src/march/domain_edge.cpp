#include <cmath>
#include <string>

#include "march_steps.hpp"
#include "ssimarch/march/predictor.hpp"
#include "ssimarch/march/trim_landing.hpp"

namespace ssimarch::internal {

namespace {

// The first boundary the step from `cur` to x1 crosses: a bound of a non-periodic unknown
// (fraction of the chord in x) or a trim's face (fraction of the 3D chord); both fractions
// estimate the same fraction of the curve's step, so the smaller one is crossed first.
struct Crossing {
  int unknown = -1;  // the bound's unknown, or -1
  int trim = -1;     // the trim's index in Problem::trims(), or -1
  double fraction = 2, value = 0;
};

Crossing first_crossing(const Problem& P, const std::vector<Slab>& trims, const CurvePoint& cur, const UnknownVec& x1) {
  Crossing c;
  const UnknownVec delta = x1 - cur.x;
  for (int i = 0; i < P.dim(); ++i) {
    if (P.periods()[static_cast<std::size_t>(i)] > 0 || delta[i] == 0) continue;
    const Interval& iv = P.bounds()[static_cast<std::size_t>(i)];
    for (double bound : {iv.lo, iv.hi}) {
      const double f = (bound - cur.x[i]) / delta[i];
      if (f >= 0 && f <= 1 && f < c.fraction) c = Crossing{i, -1, f, bound};
    }
  }
  const Vec3 p1 = P.point(x1);
  for (std::size_t k = 0; k < trims.size(); ++k) {
    const Slab& s = trims[k];
    const double a = s.normal.dot(cur.p), b = s.normal.dot(p1);
    if (a == b) continue;
    for (double bound : {s.range.lo, s.range.hi}) {
      const double f = (bound - a) / (b - a);
      if (f >= 0 && f <= 1 && f < c.fraction) c = Crossing{-1, static_cast<int>(k), f, bound};
    }
  }
  return c;
}

}  // namespace

// Newton on the square system [H(x); normal . point(x) - offset], Jacobian [J_H; normal^T DP(x)]:
// the curve point on a trim's face (docs/math/poles.md §2), as solve_with_fixed_unknown lands on
// a parameter bound.
CorrectorResult solve_on_plane(const Problem& P, const UnknownVec& guess, const Vec3& normal, double offset,
                               const CorrectorOptions& co) {
  CorrectorResult r;
  r.x = guess;
  const int n = P.dim();
  auto converged = [&](const Linearization& L) {
    return L.distance <= co.tolerance && std::fabs(normal.dot(L.point) - offset) <= co.tolerance;
  };
  // One Newton step past the tolerance: a curve meeting the plane at a shallow angle has its end
  // point fixed along the curve only to (residual / sin angle); the extra step of a quadratically
  // converging iteration brings it to rounding level, so both surface orders land on one point.
  bool polish = false;
  for (int it = 1; it <= co.max_iterations + 2; ++it) {
    const Linearization L = P.linearize(r.x);
    ++r.linearizations;
    ++r.evaluations[0];
    ++r.evaluations[1];
    r.distance = L.distance;
    if (!L.h.allFinite() || !L.jacobian.allFinite()) break;
    if (it > 1 && converged(L)) {
      if (polish) {
        r.status = CorrectorStatus::kConverged;
        return r;
      }
      polish = true;
    } else if (it > co.max_iterations) {
      break;
    }
    UnknownMat A(n, n);
    A.topRows(n - 1) = L.jacobian;
    A.row(n - 1) = (L.point_jacobian.transpose() * normal).transpose();
    UnknownVec rhs(n);
    rhs.head(n - 1) = L.h;
    rhs[n - 1] = normal.dot(L.point) - offset;
    const Eigen::FullPivLU<UnknownMat> lu(A);
    if (!lu.isInvertible()) {
      r.status = CorrectorStatus::kSingular;
      return r;
    }
    r.x -= lu.solve(rhs);
    r.iterations = it;
  }
  r.status = CorrectorStatus::kDiverged;
  return r;
}

int bound_left_at(const Problem& P, const UnknownVec& x, const UnknownVec& dx) {
  for (int i = 0; i < P.dim() && i < dx.size(); ++i) {
    if (P.periods()[static_cast<std::size_t>(i)] > 0) continue;
    const Interval& b = P.bounds()[static_cast<std::size_t>(i)];
    if ((std::fabs(x[i] - b.lo) <= 1e-12 * (1 + std::fabs(b.lo)) && dx[i] < 0) ||
        (std::fabs(x[i] - b.hi) <= 1e-12 * (1 + std::fabs(b.hi)) && dx[i] > 0))
      return i;
  }
  return -1;
}

const Pole* crossed_pole(const Problem& P, const std::vector<Pole>& poles, const CurvePoint& cur, const UnknownVec& x1) {
  const Crossing c = first_crossing(P, problem_trims(P), cur, x1);
  if (c.unknown < 0) return nullptr;
  for (const Pole& pole : poles)
    if (pole.unknown == c.unknown && pole.value == c.value) return &pole;
  return nullptr;
}

Event land_on_domain_edge(const Problem& P, const CurvePoint& cur, const UnknownVec& x1, const CorrectorOptions& co,
                          TraceStats* stats, MarchResult* r) {
  Event e;
  e.kind = EventKind::kDomainEdge;
  const std::vector<Slab> trims = problem_trims(P);
  const Crossing c = first_crossing(P, trims, cur, x1);
  if (c.unknown < 0 && c.trim < 0) {
    e.message = "left the domain";
    return e;
  }
  const UnknownVec guess = cur.x + c.fraction * (x1 - cur.x);
  const Slab* trim = c.trim >= 0 ? &trims[static_cast<std::size_t>(c.trim)] : nullptr;
  CorrectorResult landed = trim ? solve_on_plane(P, guess, trim->normal, c.value, co)
                                : solve_with_fixed_unknown(P, guess, c.unknown, c.value, co);
  stats->linearizations += landed.linearizations;
  stats->add_surface_evaluations(landed.evaluations);
  const std::string name = trim ? "the trim plane n . p (n = " + describe_point(trim->normal) + ")"
                                : P.unknown_names()[static_cast<std::size_t>(c.unknown)];
  if (landed.status != CorrectorStatus::kConverged || !P.inside(landed.x, 1e-9 * (1 + std::fabs(c.value)))) {
    e.message = "left the domain at " + name + " = " + std::to_string(c.value) + " (could not land on the edge)";
    return e;
  }
  const Vec3 pe = P.point(landed.x);
  if ((pe - cur.p).norm() > 1e-12 * P.scale()) {
    DynamicCurveJet ej = curve_jet_dynamic(P, landed.x, 1, &cur.t);
    ++stats->jet_evaluations;
    stats->add_surface_evaluations(jet_evaluation_cost(P, 1));
    Vec3 te = ej.status == CurveJetStatus::kOk ? ej.tangent() : Vec3((pe - cur.p).normalized());
    r->length += arc_length_estimate(cur.p, cur.t, pe, te);
    r->points.push_back({landed.x, pe, te});
    stats->record_iterations(landed.iterations);
    ++stats->points;
  }
  e.message = "reached the domain edge " + name + " = " + std::to_string(c.value);
  return e;
}

}  // namespace ssimarch::internal

namespace ssimarch {

std::optional<UnknownVec> onto_trims(const Problem& P, const UnknownVec& x, const CorrectorOptions& co) {
  const Vec3 p = P.point(x);
  for (const Slab& s : problem_trims(P)) {
    if (s.contains(p)) continue;
    const double value = s.normal.dot(p) < s.range.lo ? s.range.lo : s.range.hi;
    const CorrectorResult r = internal::solve_on_plane(P, x, s.normal, value, co);
    if (r.status != CorrectorStatus::kConverged || !P.inside(r.x, 1e-9 * (1 + std::fabs(value)))) return std::nullopt;
    return r.x;
  }
  return x;
}

}  // namespace ssimarch
