#include <algorithm>
#include <cmath>
#include <optional>
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

// A face of the domain: the bound `value` of a non-periodic unknown, or a trim's face n . p = value.
struct Face {
  int unknown = -1;
  int trim = -1;
  double value = 0;
};

// Rounding allowance of a point on a face at `value` (the landing polishes to rounding level; the
// same relative allowance as bound_left_at).
double face_slack(double value) { return 1e-12 * (1 + std::fabs(value)); }

// The face x lies beyond by more than rounding, the farthest relative to its allowance; none
// when x lies in every bound and trim. Every face is examined, so the answer does not depend on
// the order of the trims, which swapping the surfaces reverses.
std::optional<Face> violated_face(const Problem& P, const std::vector<Slab>& trims, const UnknownVec& x) {
  std::optional<Face> worst;
  double ratio = 1;
  auto consider = [&](double beyond, double value, int unknown, int trim) {
    const double q = beyond / face_slack(value);
    if (q > ratio) ratio = q, worst = Face{unknown, trim, value};
  };
  for (int i = 0; i < P.dim(); ++i) {
    if (P.periods()[static_cast<std::size_t>(i)] > 0) continue;
    const Interval& b = P.bounds()[static_cast<std::size_t>(i)];
    consider(b.lo - x[i], b.lo, i, -1);
    consider(x[i] - b.hi, b.hi, i, -1);
  }
  if (trims.empty()) return worst;
  const Vec3 p = P.point(x);
  for (std::size_t k = 0; k < trims.size(); ++k) {
    const double s = trims[k].normal.dot(p);
    consider(trims[k].range.lo - s, trims[k].range.lo, -1, static_cast<int>(k));
    consider(s - trims[k].range.hi, trims[k].range.hi, -1, static_cast<int>(k));
  }
  return worst;
}

CorrectorResult land_on_face(const Problem& P, const std::vector<Slab>& trims, const UnknownVec& guess, const Face& f,
                             const CorrectorOptions& co) {
  return f.trim >= 0 ? solve_on_plane(P, guess, trims[static_cast<std::size_t>(f.trim)].normal, f.value, co)
                     : solve_with_fixed_unknown(P, guess, f.unknown, f.value, co);
}

// A curve point landed on one face of the domain, moved onto the face it still lies beyond, until
// it lies inside every face (to rounding). Where two faces nearly coincide (two trims of nearly
// coaxial cones 1e-10 apart, OCCT bug33244) the chord's estimate of which one is crossed first
// depends on the step, and so on the direction of travel and the order of the surfaces; the curve
// leaves the domain where it meets the inner one, whichever was estimated first (issue 11 item 4).
// Each move lands on a face the point was beyond, inside the faces it was inside, so at most one
// move per face is made; a move that does not converge keeps the point it started from.
// *face (if given) becomes the face of the last move.
UnknownVec settle_inside(const Problem& P, const std::vector<Slab>& trims, UnknownVec x, const CorrectorOptions& co,
                         TraceStats* stats, Face* face = nullptr) {
  const int faces = 2 * (P.dim() + static_cast<int>(trims.size()));
  for (int move = 0; move < faces; ++move) {
    const std::optional<Face> f = violated_face(P, trims, x);
    if (!f) break;
    const CorrectorResult r = land_on_face(P, trims, x, *f, co);
    if (stats) {
      stats->linearizations += r.linearizations;
      stats->add_surface_evaluations(r.evaluations);
    }
    if (r.status != CorrectorStatus::kConverged) break;
    x = r.x;
    if (face) *face = *f;
  }
  return x;
}

}  // namespace

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
  Face face{c.unknown, c.trim, c.value};
  CorrectorResult landed = land_on_face(P, trims, guess, face, co);
  stats->linearizations += landed.linearizations;
  stats->add_surface_evaluations(landed.evaluations);
  if (landed.status == CorrectorStatus::kConverged) landed.x = settle_inside(P, trims, landed.x, co, stats, &face);
  const Slab* trim = face.trim >= 0 ? &trims[static_cast<std::size_t>(face.trim)] : nullptr;
  const std::string name = trim ? "the trim plane n . p (n = " + describe_point(trim->normal) + ")"
                                : P.unknown_names()[static_cast<std::size_t>(face.unknown)];
  if (landed.status != CorrectorStatus::kConverged || !P.inside(landed.x, 1e-9 * (1 + std::fabs(face.value)))) {
    e.message = "left the domain at " + name + " = " + std::to_string(face.value) + " (could not land on the edge)";
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
  e.message = "reached the domain edge " + name + " = " + std::to_string(face.value);
  return e;
}

}  // namespace ssimarch::internal

namespace ssimarch {

std::optional<UnknownVec> onto_trims(const Problem& P, const UnknownVec& x, const CorrectorOptions& co) {
  const Vec3 p = P.point(x);
  const std::vector<Slab> trims = problem_trims(P);
  if (std::all_of(trims.begin(), trims.end(), [&](const Slab& s) { return s.contains(p); })) return x;
  // The face of the trim x lies farthest beyond, then any face the landed point still lies beyond
  // (internal::settle_inside): the same point whatever the order of the trims.
  std::size_t k = 0;
  double farthest = -1, value = 0;
  for (std::size_t i = 0; i < trims.size(); ++i) {
    const double s = trims[i].normal.dot(p);
    const double lo = trims[i].range.lo - s, hi = s - trims[i].range.hi;
    if (std::max(lo, hi) > farthest) farthest = std::max(lo, hi), k = i, value = lo > hi ? trims[i].range.lo : trims[i].range.hi;
  }
  const CorrectorResult r = solve_on_plane(P, x, trims[k].normal, value, co);
  if (r.status != CorrectorStatus::kConverged) return std::nullopt;
  const UnknownVec y = internal::settle_inside(P, trims, r.x, co, nullptr);
  if (!P.inside(y, 1e-9 * (1 + std::fabs(value)))) return std::nullopt;
  return y;
}

}  // namespace ssimarch
