// docs/math/closed_form_quadrics.md: which pairs have a closed form, and how the answer is put in
// the shape of a traced one.
#include "ssimarch/analytic/closed_form.hpp"

#include <chrono>

#include "ssimarch/analytic/coaxial_section.hpp"
#include "ssimarch/analytic/conic_pieces.hpp"
#include "ssimarch/analytic/plane_section.hpp"
#include "ssimarch/analytic/quadric_form.hpp"

namespace ssimarch {

namespace {

// The whole (unclipped) section, and which closed form gave it.
std::optional<std::vector<Conic>> section(const Surface& a, const Surface& b, double scale, std::string* pair) {
  for (int order = 0; order < 2; ++order) {
    const Surface& p = order == 0 ? a : b;
    const Surface& q = order == 0 ? b : a;
    const Plane* plane = p.get_if<Plane>();
    const auto Q = plane ? quadric_matrix(q) : std::nullopt;
    if (plane && Q) {
      *pair = "plane-quadric";
      return plane_section(plane->frame(), *Q, scale);
    }
  }
  const auto ra = revolution_form(a), rb = revolution_form(b);
  if (!ra || !rb) return std::nullopt;
  *pair = "coaxial";
  return coaxial_section(*ra, *rb, scale);
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

SingularPointReport contact_point(const Conic& c) {
  SingularPointReport r;
  r.p = c.center;
  r.x = c.center;
  r.type = "isolated";
  return r;
}

}  // namespace

std::optional<ClosedFormResult> closed_form_intersection(const Problem& problem, const TraceOptions& options) {
  if (problem.kind() != PairKind::kImplicitImplicit || problem.disjoint()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  ClosedFormResult out;
  const double scale = problem.scale();
  const auto whole = section(problem.first(), problem.second(), scale, &out.pair);
  if (!whole) return std::nullopt;
  const auto& bounds = problem.bounds();
  std::vector<Slab> region = box_slabs({bounds[0], bounds[1], bounds[2]});
  add_trims(problem.first(), &region);
  add_trims(problem.second(), &region);
  const double deviation = options.deviation > 0 ? options.deviation : 1e-4 * scale;
  const double max_chord = options.step_length > 0 ? options.step_length : scale / 10;
  for (const Conic& conic : *whole) {
    for (const Conic& piece : clip_to_slabs(conic, region)) {
      if (piece.type == ConicType::kPoint) {
        out.result.isolated_points.push_back(contact_point(piece));
        continue;
      }
      out.result.curves.push_back(sample_conic(piece, deviation, max_chord));
      out.result.curves.back().tangential_contact = piece.contact == Contact::kTangential;  // a double root
      out.conics.push_back(piece);
      out.result.stats.points += static_cast<long>(out.result.curves.back().points.size());
    }
  }
  out.result.start_search.method = "closed-form";
  out.result.start_search.certified = true;
  out.result.start_search.note = "exact " + out.pair + " section (docs/math/closed_form_quadrics.md); no search";
  out.result.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace ssimarch
