#include "ssimarch/trace/tangency_hunt.hpp"

#include <algorithm>

#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/analysis.hpp"
#include "ssimarch/singular/detection.hpp"
#include "ssimarch/trace/on_traced_curve.hpp"
#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/start/patch_exclusion.hpp"

namespace ssimarch {

namespace {

// The curves of tangential contact among `curves`.
bool near_contact_curve(const Vec3& p, const std::vector<TracedCurve>& curves, double radius) {
  for (const TracedCurve& c : curves) {
    if (!c.tangential_contact) continue;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
      if (chord_distance(p, c.points[i].p, c.points[i + 1].p) <= radius) return true;
  }
  return false;
}

// Types with real half-branches leaving the point (isolated points and points of a contact
// curve have none to trace).
bool has_real_branches(SingularType t) {
  return t != SingularType::kRegular && t != SingularType::kIsolated && t != SingularType::kTangentialContact &&
         t != SingularType::kTangentLineCrossing;
}

// The share of the start-point box budget the hunt's own turning-system search may use when no
// certified search ran (a fifth: its unexplored boxes are still hunted, on the grid).
constexpr long kHuntSearchBudgetShare = 5;

// Halvings of a grid start's cell by the hunt's singular-point exclusion before the start is
// tried: six per direction (sub-patches 1/64 of the cell). Only sub-patches that can hold a
// singular point are halved again, so the work follows the curve (~2 x 64 evaluations of f_G o F
// along a transversal curve through the cell, a few microseconds each) against one local curve
// and a location (milliseconds) for every start tried; the whole 64 x 64 only where the cell is
// all contact (no exclusion anywhere).
constexpr int kHuntCellHalvings = 12;

// Whether x lies within one cell of a grid of `grid` samples per unknown from one of the boxes.
bool near_box(const Problem& P, const std::vector<std::vector<Interval>>& boxes, const VecX& x, int grid) {
  for (const auto& b : boxes) {
    bool inside = true;
    for (std::size_t i = 0; i < b.size() && inside; ++i) {
      const double cell = P.bounds()[i].width() / (grid - 1);
      inside = x[static_cast<Eigen::Index>(i)] >= b[i].lo - cell && x[static_cast<Eigen::Index>(i)] <= b[i].hi + cell;
    }
    if (inside) return true;
  }
  return false;
}

bool near_node(const Vec3& p, const SingularRegistry& registry, double radius) {
  for (const SingularNode& n : registry.nodes())
    if ((n.location.point - p).norm() <= radius) return true;
  return false;
}

// Traces the contact curve through the corrected point c and records it.
void add_contact_curve(const Tracer& tracer, const ContactPoint& c, std::vector<TracedCurve>* curves,
                       SingularRegistry* registry) {
  ContactOptions o;
  o.step = tracer.spacing();
  o.max_points = tracer.options().max_points;
  ContactTrace t = trace_tangential_contact(tracer.problem(), c.location.x, o);
  if (t.curve.points.size() < 2) return;
  const int index = static_cast<int>(curves->size());
  curves->push_back(std::move(t.curve));
  for (const SingularLocation& s : t.crossings) registry->mark(registry->add(s), -1, index);
}

// Inserts the node's point into each passage of curve ci within radius of it (a curve through a
// node passes it once per branch: Viviani's curve twice), marking the half-branches along it.
bool insert_into(SingularRegistry* registry, int n, int ci, TracedCurve* c, double radius) {
  const SingularNode& node = registry->node(n);
  const Vec3 s = node.location.point;
  bool found = false;
  for (std::size_t i = 0; i + 1 < c->points.size(); ++i) {
    const Vec3 a = c->points[i].p, seg = c->points[i + 1].p - a;
    const double L2 = seg.squaredNorm();
    if (!(L2 > 0)) continue;
    const double tau = (s - a).dot(seg) / L2;
    if (tau < 0 || tau > 1 || (s - (a + tau * seg)).norm() > radius) continue;
    const Vec3 d = seg.normalized();
    Vec3 t = d;
    for (std::size_t k = 0; k < node.branches.size(); ++k) {
      const double cosine = node.branches[k].tangent_3d.dot(d);
      if (std::fabs(cosine) < 0.9) continue;
      registry->mark(n, static_cast<int>(k), ci);
      if (cosine > 0) t = node.branches[k].tangent_3d;
    }
    registry->mark(n, -1, ci);
    found = true;
    if ((c->points[i].p - s).norm() > 0 && (c->points[i + 1].p - s).norm() > 0) {
      c->points.insert(c->points.begin() + static_cast<std::ptrdiff_t>(i) + 1, CurvePoint{node.location.x, s, t});
      ++i;  // past the inserted point: the next segment starts at the node
    } else {
      ++i;  // the segment after the node's own point is the same passage
    }
  }
  return found;
}

void take_found(const Problem& P, const SingularLocation& s, double merge, double radius, SingularRegistry* registry,
                const std::vector<TracedCurve>& curves, std::vector<SingularPointReport>* isolated) {
  if (near_node(s.point, *registry, merge) || near_contact_curve(s.point, curves, radius)) return;
  SingularAnalysisOptions options;
  options.half_branches = false;  // the registry finds them for a point with real branches
  const SingularAnalysis a = analyse_singular_point(P, s, options);
  if (!a.analysed()) return;
  bool known = false;
  for (const SingularPointReport& r : *isolated) known = known || (r.p - s.point).norm() <= merge;
  if (a.kind.type == SingularType::kIsolated && !known) isolated->push_back(make_report(a, false));
  if (has_real_branches(a.kind.type)) registry->add(s);
}

}  // namespace

void attach_crossings(SingularRegistry* registry, std::vector<TracedCurve>* curves, double radius) {
  for (std::size_t n = 0; n < registry->nodes().size(); ++n) {
    // Crossings with contact curves, and singular points the hunt found that no curve met yet.
    const SingularNode& node = registry->nodes()[n];
    if (node.kind.type != SingularType::kTangentLineCrossing && !node.curves.empty()) continue;
    for (std::size_t ci = 0; ci < curves->size(); ++ci) {
      TracedCurve& c = (*curves)[ci];
      const auto& on = registry->nodes()[n].curves;
      // A contact curve's march records the crossings it passes without making them points of
      // its own (march_contact steps over them): they become points here too, or the network
      // would not cut the contact curve there and its crossing branch would be another component.
      const bool met = std::find(on.begin(), on.end(), static_cast<int>(ci)) != on.end();
      if (met && !c.tangential_contact) continue;
      insert_into(registry, static_cast<int>(n), static_cast<int>(ci), &c, radius);
    }
  }
}

bool trace_contact_from(const Tracer& tracer, const VecX& x, std::vector<TracedCurve>* curves,
                        SingularRegistry* registry) {
  const Problem& P = tracer.problem();
  if (!(Problem::rank_ratio(P.linearize(x)) < kSuspectSingularRankRatio)) return false;
  const ContactPoint c = correct_onto_contact(P, x);
  if (!is_contact_point(c) || near_contact_curve(c.location.point, *curves, 0.2 * tracer.spacing())) return false;
  add_contact_curve(tracer, c, curves, registry);
  return true;
}

void hunt_tangencies(const Tracer& tracer, const StartPointSearch& search, SingularRegistry* registry,
                     std::vector<TracedCurve>* curves, std::vector<SingularPointReport>* isolated) {
  const Problem& P = tracer.problem();
  const double radius = 0.2 * tracer.spacing();
  const double merge = 1e-7 * P.scale();
  // The poles of the parametrisations on the other surface first, whatever the search found: a
  // singular point there (a cone's apex touching a sphere's pole) is no ordinary root of the
  // search's systems in the parameters.
  for (const SingularLocation& s : singular_points_at_poles(P))
    take_found(P, s, merge, radius, registry, *curves, isolated);
  HuntOptions hunt;
  std::vector<std::vector<Interval>> candidates;
  if (search.method == StartSearchMethod::kCertified) {
    if (search.certified) return;  // no singular point in the domain
    for (const UncertainRegion& u : search.uncertain_regions) hunt.regions.push_back(u.box);
    // More region samples than the whole domain's grid: the grid (parametric-implicit pairs).
    const std::size_t samples = hunt.regions.size() * static_cast<std::size_t>(hunt.region_grid * hunt.region_grid);
    if (P.kind() == PairKind::kParametricImplicit && samples > static_cast<std::size_t>(hunt.grid * hunt.grid))
      hunt.regions.clear();
  } else if (P.kind() != PairKind::kParametricImplicit) {
    return;
  } else if (evaluates_on_intervals(P.first()) && evaluates_on_intervals(P.second())) {
    // Given or sampled start points: the boxes one turning system leaves undecided (unexplored
    // ones included) hold every singular point, so only the grid starts within a cell of them are
    // hunted (each start costs a local curve: the whole grid took seconds on thesis pair 1).
    candidates = singular_point_regions(P, std::max(1L, tracer.options().start_box_budget / kHuntSearchBudgetShare));
    if (candidates.empty()) return;
    hunt.consider = [&](const VecX& x) { return near_box(P, candidates, x, hunt.grid); };
  }
  // A start whose cell (the points nearer to it than to any other start: half a grid step about
  // it) provably holds no singular point is skipped (start/patch_exclusion.hpp): every
  // singular point keeps the start nearest to it, from which it was found before.
  if (singular_exclusion_applies(P))
    hunt.holds_none = [&P](const VecX& x0, const VecX& step) {
      const double hu = 0.5 * step[0], hv = 0.5 * step[1];
      return patch_holds_no_singular_point(P, IntervalNumber(x0[0] - hu, x0[0] + hu),
                                           IntervalNumber(x0[1] - hv, x0[1] + hv), kHuntCellHalvings);
    };
  // A grid cell from a singular point sin(theta) is about a cell's fraction of the scale; 0.2
  // leaves room while skipping the transversal rest of the curve.
  hunt.max_sine = 0.2;
  hunt.skip = [&](const Vec3& p) { return near_contact_curve(p, *curves, radius) || near_node(p, *registry, merge); };
  hunt.on_found = [&](const SingularLocation& s) {
    const ContactPoint c = correct_onto_contact(P, s.x);
    if (is_contact_point(c) && !near_contact_curve(c.location.point, *curves, radius))
      add_contact_curve(tracer, c, curves, registry);
  };
  for (const SingularLocation& s : hunt_singular_points(P, hunt))
    take_found(P, s, merge, radius, registry, *curves, isolated);
}

}  // namespace ssimarch
