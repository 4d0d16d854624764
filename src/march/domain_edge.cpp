#include <cmath>
#include <string>

#include "march_steps.hpp"
#include "ssimarch/march/predictor.hpp"

namespace ssimarch::internal {

namespace {
// The first bound of a non-periodic unknown the chord a -> a + delta crosses: its index (-1 if
// none), the chord fraction where it does, and the bound's value.
int first_crossed_bound(const Problem& P, const VecX& a, const VecX& delta, double* fraction, double* value) {
  int edge = -1;
  *fraction = 2;
  for (int i = 0; i < P.dim(); ++i) {
    if (P.periods()[static_cast<std::size_t>(i)] > 0 || delta[i] == 0) continue;
    const Interval& iv = P.bounds()[static_cast<std::size_t>(i)];
    for (double bound : {iv.lo, iv.hi}) {
      double f = (bound - a[i]) / delta[i];
      if (f >= 0 && f <= 1 && f < *fraction) {
        *fraction = f;
        edge = i;
        *value = bound;
      }
    }
  }
  return edge;
}
}  // namespace

Event land_on_domain_edge(const Problem& P, const CurvePoint& cur, const VecX& x1, const CorrectorOptions& co,
                          TraceStats* stats, MarchResult* r) {
  Event e;
  e.kind = EventKind::kDomainEdge;
  const VecX delta = x1 - cur.x;
  double fraction = 2, value = 0;
  const int edge = first_crossed_bound(P, cur.x, delta, &fraction, &value);
  if (edge < 0) {
    e.message = "left the domain";
    return e;
  }
  CorrectorResult landed = solve_with_fixed_unknown(P, cur.x + fraction * delta, edge, value, co);
  stats->linearizations += landed.linearizations;
  stats->add_surface_evaluations(landed.evaluations);
  const std::string name = P.unknown_names()[static_cast<std::size_t>(edge)];
  if (landed.status != CorrectorStatus::kConverged || !P.inside(landed.x, 1e-9 * (1 + std::fabs(value)))) {
    e.message = "left the domain at " + name + " = " + std::to_string(value) + " (could not land on the edge)";
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
  e.message = "reached the domain edge " + name + " = " + std::to_string(value);
  return e;
}

}  // namespace ssimarch::internal
