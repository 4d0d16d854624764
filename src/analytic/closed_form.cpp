// docs/math/closed_form_quadrics.md: which pairs have a closed form, and how the answer is put in
// the shape of a traced one.
#include "ssimarch/analytic/closed_form.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>

#include "ssimarch/analytic/coaxial_section.hpp"
#include "ssimarch/analytic/conic_pieces.hpp"
#include "ssimarch/analytic/plane_section.hpp"
#include "ssimarch/analytic/quadric_form.hpp"
#include "ssimarch/analytic/quadric_pencil.hpp"
#include "ssimarch/analytic/ruled_crossing.hpp"
#include "ssimarch/analytic/ruled_section.hpp"
#include "ssimarch/march/model_size.hpp"
#include "ssimarch/problem/closed_form_tolerances.hpp"
#include "ssimarch/singular/locate.hpp"
#include "ssimarch/trace/singular_registry.hpp"

namespace ssimarch {

namespace {

// The whole (unclipped) section, and which closed form gave it; `gap`: the tangency gap tolerance
// (model units, contact_gap_tolerance).
std::optional<std::vector<Conic>> section(const Surface& a, const Surface& b, double scale, double gap, std::string* pair) {
  for (int order = 0; order < 2; ++order) {
    const Surface& p = order == 0 ? a : b;
    const Surface& q = order == 0 ? b : a;
    const Plane* plane = p.get_if<Plane>();
    const auto Q = plane ? quadric_matrix(q) : std::nullopt;
    if (plane && Q) {
      *pair = "plane-quadric";
      return plane_section(plane->frame(), *Q, scale, gap);
    }
  }
  const auto ra = revolution_form(a), rb = revolution_form(b);
  if (!ra || !rb) return std::nullopt;
  *pair = "coaxial";
  return coaxial_section(*ra, *rb, scale, gap);
}

// The trims of a primitive as slabs: a plane's or paraboloid's parameter rectangle, a cylinder's
// or cone's axial range (their implicit forms are unbounded; the trims bound the parametric ones).
void add_trims(const Surface& s, std::vector<Slab>* slabs) {
  auto rectangle = [&](const Frame& f, const ParamDomain& d) {
    slabs->push_back({f.e0, {d.u.lo + f.e0.dot(f.origin), d.u.hi + f.e0.dot(f.origin)}});
    slabs->push_back({f.e1, {d.v.lo + f.e1.dot(f.origin), d.v.hi + f.e1.dot(f.origin)}});
  };
  auto axial = [&](const Frame& f, const Interval& r) {
    slabs->push_back({f.e2, {r.lo + f.e2.dot(f.origin), r.hi + f.e2.dot(f.origin)}});
  };
  if (const auto* p = s.get_if<Plane>()) rectangle(p->frame(), p->domain());
  if (const auto* p = s.get_if<Paraboloid>()) rectangle(p->frame(), p->domain());
  if (const auto* c = s.get_if<Cylinder>()) axial(c->frame(), c->range());
  if (const auto* c = s.get_if<Cone>()) axial(c->frame(), c->range());
}

SingularPointReport contact_point(const Vec3& p) {
  SingularPointReport r;
  r.p = p;
  r.x = p;
  r.type = SingularType::kIsolated;
  return r;
}

bool inside_region(const Vec3& p, const std::vector<Slab>& region) {
  return std::all_of(region.begin(), region.end(), [&](const Slab& s) { return s.contains(p); });
}

// Distance from p to the polyline of c.
double distance_to(const TracedCurve& c, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
    const Vec3 a = c.points[i].p, d = c.points[i + 1].p - a;
    const double l2 = d.squaredNorm();
    const double s = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + s * d - p).norm());
  }
  return best;
}

// The singular points where branches of the section meet (the double roots of the discriminant),
// with the curves through each. A root of multiplicity 2 is a node whose record the closed form
// gives exactly (ruled_crossing.hpp); any other (a tacnode or higher contact: Delta'' = 0) is
// classified as the tracer does it (trace/singular_registry.hpp: local curve, type,
// half-branches). False when one is not a singular point to within kClosedFormCrossing: the caller
// then traces.
bool crossing_reports(const Problem& problem, const RuledCurves& curves, const RuledSection& section,
                      const std::vector<Slab>& region, ClosedFormResult* out) {
  const double merge = 1e-6 * problem.scale();
  SingularRegistry registry(problem, merge);
  std::vector<SingularPointReport>& reports = out->result.singular_points;
  for (double theta : section.crossings) {
    const Vec3 p = curves.double_root_point(theta);
    if (!inside_region(p, region)) continue;
    // The double root is the singular point itself (exact up to rounding): no search; checked to
    // be one (the surfaces meet there with parallel normals) before it is reported.
    SingularLocation at;
    at.x = VecX(p);
    at.point = p;
    const Linearization L = problem.linearize(at.x);
    at.gap = L.distance;
    at.sine = L.normal_first.cross(L.normal_second).norm();
    if (!(at.gap <= kClosedFormCrossing * problem.scale() && at.sine <= kClosedFormCrossing)) return false;
    at.status = LocateStatus::kConverged;
    if (std::any_of(reports.begin(), reports.end(), [&](const SingularPointReport& r) { return (r.p - p).norm() <= merge; }))
      continue;
    std::optional<SingularPointReport> report = ruled_node(problem, curves, theta, section.scale);
    if (!report) {
      const SingularNode& node = registry.node(registry.add(at));
      report = make_report(node);
    }
    const auto& c = out->result.curves;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (distance_to(c[i], report->p) <= merge) report->curves.push_back(static_cast<int>(i));
    reports.push_back(std::move(*report));
  }
  return true;
}

// Largest first-order distance of the curves' points from the quadric Q (|X^T Q X| / |grad|).
double quadric_residual(const std::vector<TracedCurve>& curves, const Eigen::Matrix4d& Q) {
  double worst = 0;
  for (const TracedCurve& c : curves)
    for (const CurvePoint& p : c.points) {
      const Eigen::Vector4d X(p.p.x(), p.p.y(), p.p.z(), 1);
      const Eigen::Vector4d QX = Q * X;
      worst = std::max(worst, std::fabs(X.dot(QX)) / (2 * QX.head<3>().norm()));
    }
  return worst;
}

enum class Along { kAnswered, kNotApplicable, kGiveUp };

// The section of Q along `rulings` in `out`: kNotApplicable where the method does not apply to
// them (ruled_section.hpp), kGiveUp where it applies but a loop cannot be clipped or a crossing
// is not a singular point (the caller traces). `check`: a quadric the points must also lie on
// (to kPencilResidual), or null.
Along section_along(const Problem& problem, const Rulings& rulings, const Eigen::Matrix4d& Q, const Eigen::Matrix4d* check,
                    const std::vector<Slab>& region, double deviation, double max_chord, ClosedFormResult* out) {
  const RuledCurves curves(rulings, Q);
  const auto section = curves.section();
  if (!section) return Along::kNotApplicable;
  auto pieces = ruled_curves_in(curves, *section, region, deviation, max_chord);
  if (!pieces) return Along::kGiveUp;
  if (check && !(quadric_residual(*pieces, *check) <= kPencilResidual * std::max(1.0, problem.scale())))
    return Along::kNotApplicable;
  ClosedFormResult r;
  r.result.curves = std::move(*pieces);
  for (double theta : section->isolated) {
    const Vec3 p = curves.double_root_point(theta);
    if (inside_region(p, region)) r.result.isolated_points.push_back(contact_point(p));
  }
  if (!crossing_reports(problem, curves, *section, region, &r)) return Along::kGiveUp;
  out->result.curves = std::move(r.result.curves);
  out->result.isolated_points = std::move(r.result.isolated_points);
  out->result.singular_points = std::move(r.result.singular_points);
  return Along::kAnswered;
}

// The section along the rulings of a cylinder or cone of the pair (ruled_section.hpp) in `out`,
// or else along those of a real cone or cylinder of the pair's pencil (quadric_pencil.hpp); false
// where neither applies or a crossing point of its branches could not be located.
bool ruled_answer(const Problem& problem, const std::vector<Slab>& region, double deviation, double max_chord,
                  ClosedFormResult* out) {
  // Which surface's rulings: a cylinder's before a cone's (they never pass through an apex), and
  // between two of a kind the one first by (size, origin, axis), so that the answer does not
  // depend on the order of the pair.
  auto key = [](const Surface& s) {
    const Cylinder* c = s.get_if<Cylinder>();
    const Cone* k = s.get_if<Cone>();
    const Frame& f = c ? c->frame() : k->frame();
    return std::array<double, 8>{c ? 0.0 : 1.0, c ? c->radius() : k->half_angle(), f.origin.x(), f.origin.y(),
                                 f.origin.z(), f.e2.x(), f.e2.y(), f.e2.z()};
  };
  std::vector<std::pair<const Surface*, const Surface*>> order;  // (ruled, other)
  for (const auto& [ruled, other] : {std::pair{&problem.first(), &problem.second()}, std::pair{&problem.second(), &problem.first()}})
    if (ruled->get_if<Cylinder>() || ruled->get_if<Cone>()) order.push_back({ruled, other});
  if (order.size() == 2 && key(*order[1].first) < key(*order[0].first)) std::swap(order[0], order[1]);
  for (const auto& [ruled, other] : order) {
    const auto rulings = rulings_of(*ruled);
    const auto Q = quadric_matrix(*other);
    if (!rulings || !Q) continue;
    const Along a = section_along(problem, *rulings, *Q, nullptr, region, deviation, max_chord, out);
    if (a == Along::kGiveUp) return false;
    if (a == Along::kAnswered) {
      out->pair = "ruled-quadric";
      return true;
    }
  }
  // The pencil (Levin): a cone or cylinder through the curve, whose rulings meet the first
  // quadric in it; the points are checked on the second.
  const auto A = quadric_matrix(problem.first()), B = quadric_matrix(problem.second());
  if (!A || !B) return false;
  const auto& box = problem.bounds();
  const Vec3 centre(0.5 * (box[0].lo + box[0].hi), 0.5 * (box[1].lo + box[1].hi), 0.5 * (box[2].lo + box[2].hi));
  for (const PencilMember& m : ruled_members(*A, *B, centre, problem.scale())) {
    const Along a = section_along(problem, m.rulings, *A, &*B, region, deviation, max_chord, out);
    if (a == Along::kGiveUp) return false;
    if (a == Along::kAnswered) {
      out->pair = m.cylinder ? "pencil-cylinder" : "pencil-cone";
      return true;
    }
  }
  return false;
}

}  // namespace

std::optional<ClosedFormResult> closed_form_intersection(const Problem& problem, const TraceOptions& options) {
  if (problem.kind() != PairKind::kImplicitImplicit || problem.disjoint()) return std::nullopt;
  return closed_form_intersection(problem, resolve_trace_options(options, problem.scale()));
}

std::optional<ClosedFormResult> closed_form_intersection(const Problem& problem, const ResolvedTraceOptions& options) {
  if (problem.kind() != PairKind::kImplicitImplicit || problem.disjoint()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  ClosedFormResult out;
  const double scale = problem.scale();
  const auto& bounds = problem.bounds();
  std::vector<Slab> region = box_slabs({bounds[0], bounds[1], bounds[2]});
  add_trims(problem.first(), &region);
  add_trims(problem.second(), &region);
  const double deviation = options.options.deviation, max_chord = options.chord;
  const double gap = contact_gap_tolerance(options.options.tolerance, scale);
  if (const auto whole = section(problem.first(), problem.second(), scale, gap, &out.pair)) {
    for (const Conic& conic : *whole) {
      for (const Conic& piece : clip_to_slabs(conic, region)) {
        if (piece.type == ConicType::kPoint) {
          out.result.isolated_points.push_back(contact_point(piece.center));
          continue;
        }
        out.result.curves.push_back(sample_conic(piece, deviation, max_chord));
        out.result.curves.back().tangential_contact = piece.contact == Contact::kTangential;  // a double root
        out.conics.push_back(piece);
      }
    }
  } else if (!ruled_answer(problem, region, deviation, max_chord, &out)) {
    return std::nullopt;
  }
  for (const TracedCurve& c : out.result.curves) out.result.stats.points += static_cast<long>(c.points.size());
  out.result.start_search.method = StartSearchMethod::kClosedForm;
  out.result.start_search.certified = true;
  out.result.start_search.note = "exact " + out.pair + " section (docs/math/closed_form_quadrics.md); no search";
  out.result.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace ssimarch
